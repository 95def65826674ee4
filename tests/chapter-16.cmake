# chapter-16 tests: the final image, the cascades view and the shadow map against golden images,
# with validation (synchronization validation on); a box over a plane under a known sun, whose
# shadow must be where the geometry puts it and nowhere else; the standalone build.
set(CH16 $<TARGET_FILE:chapter-16>)
set(CH16_RUN ${CH16} --device llvmpipe --validation)

foreach(view final cascades shadow-map)
    chapter_test(chapter-16.view-${view} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 640 --height 360 --view ${view}
                --screenshot ${TEST_OUT}/chapter-16-${view}.png
        EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
    set_tests_properties(chapter-16.view-${view} PROPERTIES FIXTURES_SETUP ch16-${view})
    add_test(NAME chapter-16.view-${view}-image COMMAND image_compare ${TEST_OUT}/chapter-16-${view}.png
        --size 640 360 --golden ${GOLDEN}/chapter-16-${view}.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(chapter-16.view-${view}-image PROPERTIES FIXTURES_REQUIRED ch16-${view})
endforeach()

# A box from (-0.5, 1, -0.5) to (0.5, 2, 0.5) over a plane at y = 0, seen from 10 above (15.6
# pixels a metre at 320x180: world x down the image from row 90, world z leftwards from column 160),
# a sun along (1, -1, 0.5), no ambient light (tools/gltf_cases.cpp, shadows/): the shadow is the
# box's square swept from x 0.5..1.5, z 0..1 to x 1.5..2.5, z 0.5..1.5, symmetric in neither axis.
# Points at least a quarter metre inside it are black -- (1, 0.5), (1.5, 0.75), (2, 1) -- and points
# as far outside it lit by the sun alone -- (1, -0.5), the first's mirror in z; (2, 0); (2.9, 1);
# (-1, 0); (1.5, 2) -- at albedo 0.8 / pi x 2 x cos(light, up) 0.67, 0.33 linear, 156 in sRGB.
chapter_test(chapter-16.box-shadow WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/box_on_plane.json
            --screenshot ${TEST_OUT}/chapter-16-box-shadow.png
    EXPECT_STDOUT "chapter-16: 2 draws" QUIET_STDERR)
set_tests_properties(chapter-16.box-shadow PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP ch16-box)
add_test(NAME chapter-16.box-shadow-in-shadow COMMAND image_compare ${TEST_OUT}/chapter-16-box-shadow.png
    --size 320 180 --pixel 152 106 0 0 0 --pixel 148 113 0 0 0 --pixel 144 121 0 0 0 --pixel-tolerance 2)
add_test(NAME chapter-16.box-shadow-lit-elsewhere COMMAND image_compare ${TEST_OUT}/chapter-16-box-shadow.png
    --size 320 180 --pixel 168 106 156 156 156 --pixel 160 121 156 156 156 --pixel 144 135 156 156 156
    --pixel 160 74 156 156 156 --pixel 129 113 156 156 156 --pixel-tolerance 3)
set_tests_properties(chapter-16.box-shadow-in-shadow chapter-16.box-shadow-lit-elsewhere PROPERTIES
    FIXTURES_REQUIRED ch16-box)

standalone_build_test(16 --width 320 --height 180)

# Hard light directions on the box over the plane -- straight down, 5e-4 radians off, one degree
# above the horizon -- and the default scene: the light output finite and non-negative, validation
# clean; the camera straight down and straight up.
foreach(sun sun_down sun_down_5e-4 sun_grazing)
    chapter_test(chapter-16.${sun} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --check-output
                --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/${sun}.json
        EXPECT_STDOUT "light output 320x180: 0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
    set_tests_properties(chapter-16.${sun} PROPERTIES FIXTURES_REQUIRED gltf-cases)
endforeach()
chapter_test(chapter-16.check-output WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 640 --height 360 --check-output --frames 3
    EXPECT_STDOUT "light output 640x360: 0 NaN, 0 infinite, 0 negative" QUIET_STDERR)

# Acne: under the grazing sun every texel's depth lies partly behind the plane it stands for, and
# without the normal offset the plane shadows itself in stripes (19 of these 76 rows were darker).
# Every row of a column down the plane must have the plane's one lit value (23: the sun at one
# degree, sin 1 deg = 0.017 of its light, after the microfacet terms).
chapter_test(chapter-16.sun-grazing-image WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/sun_grazing.json
            --screenshot ${TEST_OUT}/chapter-16-sun-grazing.png
    EXPECT_STDOUT "chapter-16: 2 draws" QUIET_STDERR)
set_tests_properties(chapter-16.sun-grazing-image PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP ch16-grazing)
set(column)
foreach(y RANGE 20 170 2)
    list(APPEND column --pixel 160 ${y} 23 23 23)
endforeach()
add_test(NAME chapter-16.sun-grazing-no-acne COMMAND image_compare ${TEST_OUT}/chapter-16-sun-grazing.png
    --size 320 180 ${column} --pixel-tolerance 2)
set_tests_properties(chapter-16.sun-grazing-no-acne PROPERTIES FIXTURES_REQUIRED ch16-grazing)

# Every count of cascades the option takes, with one geometry shader: finite, non-negative, clean.
foreach(count 1 2 4)
    chapter_test(chapter-16.cascades-${count} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --cascades ${count} --check-output --frames 2
        EXPECT_STDOUT "light output 320x180: 0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
endforeach()

# A point light half a metre over the middle of the sun's shadow: its light there is not darkened
# by the sun's shadow (the book's Lo * shadow would leave the pixel black): 236 right under it.
chapter_test(chapter-16.point-light-in-sun-shadow WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/box_on_plane_point.json
            --screenshot ${TEST_OUT}/chapter-16-point-in-shadow.png
    EXPECT_STDOUT "chapter-16: 2 draws.*2 lights" QUIET_STDERR)
set_tests_properties(chapter-16.point-light-in-sun-shadow PROPERTIES FIXTURES_REQUIRED gltf-cases
                     FIXTURES_SETUP ch16-point)
add_test(NAME chapter-16.point-light-in-sun-shadow-image COMMAND image_compare
    ${TEST_OUT}/chapter-16-point-in-shadow.png --size 320 180 --pixel 148 113 236 236 236 --pixel-tolerance 3)
set_tests_properties(chapter-16.point-light-in-sun-shadow-image PROPERTIES FIXTURES_REQUIRED ch16-point)
