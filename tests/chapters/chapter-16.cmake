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

# Cascades drawn only when what they see changed. A still camera: each cascade drawn once in 100
# frames, and the 100th frame the first to the bit (no shimmer).
chapter_test(chapter-16.still-camera-first WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180 --screenshot ${TEST_OUT}/chapter-16-still-1.png
    EXPECT_STDOUT "cascades drawn 1, 1, 1 times in 1 frames" QUIET_STDERR)
chapter_test(chapter-16.still-camera WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames 100
            --screenshot ${TEST_OUT}/chapter-16-still-100.png
    EXPECT_STDOUT "cascades drawn 1, 1, 1 times in 100 frames" QUIET_STDERR)
set_tests_properties(chapter-16.still-camera-first PROPERTIES FIXTURES_SETUP ch16-still-1)
set_tests_properties(chapter-16.still-camera PROPERTIES FIXTURES_SETUP ch16-still-100)
add_test(NAME chapter-16.still-camera-no-shimmer COMMAND image_compare ${TEST_OUT}/chapter-16-still-100.png
    --size 320 180 --golden ${TEST_OUT}/chapter-16-still-1.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-16.still-camera-no-shimmer PROPERTIES FIXTURES_REQUIRED "ch16-still-1;ch16-still-100")

# A camera creeping forward 0.1 mm a frame, less than a texel of any cascade: the second frame
# draws no cascade again (the snapped matrices are the same to the bit), and the sun's visibility
# changes only where the scene's own edges moved: 19 of 230,400 pixels here; without the
# snapping, every cascade is drawn again and 141 change as the shadow edges crawl.
foreach(frames 1 2)
    chapter_test(chapter-16.creep-${frames} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 640 --height 360 --frames ${frames} --camera-motion creep
                --view visibility --screenshot ${TEST_OUT}/chapter-16-creep-${frames}.png
        EXPECT_STDOUT "cascades drawn 1, 1, 1 times in ${frames} frames" QUIET_STDERR)
    set_tests_properties(chapter-16.creep-${frames} PROPERTIES FIXTURES_SETUP ch16-creep-${frames})
endforeach()
add_test(NAME chapter-16.creep-edges-still COMMAND image_compare ${TEST_OUT}/chapter-16-creep-2.png
    --size 640 360 --golden ${TEST_OUT}/chapter-16-creep-1.png --max-diff 0 --max-fraction 0.0003)
set_tests_properties(chapter-16.creep-edges-still PROPERTIES FIXTURES_REQUIRED "ch16-creep-1;ch16-creep-2")

# A walking camera: cascades drawn again as they move, and the image the one drawing every cascade
# every frame gives, to the bit.
# The walk draws the first two cascades every frame and keeps the last in some (30, 30, 19): the
# frames that draw some layers and load the others, validation clean.
foreach(case "changed;cascades drawn 30, 30, 1[0-9] times in 30 frames"
             "always;cascades drawn 30, 30, 30 times in 30 frames")
    list(GET case 0 redraw)
    list(GET case 1 expected)
    chapter_test(chapter-16.walk-${redraw} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames 30 --camera-motion walk
                --shadow-redraw ${redraw} --screenshot ${TEST_OUT}/chapter-16-walk-${redraw}.png
        EXPECT_STDOUT "${expected}" QUIET_STDERR)
    set_tests_properties(chapter-16.walk-${redraw} PROPERTIES FIXTURES_SETUP ch16-walk-${redraw})
endforeach()
add_test(NAME chapter-16.walk-same-image COMMAND image_compare ${TEST_OUT}/chapter-16-walk-changed.png
    --size 320 180 --golden ${TEST_OUT}/chapter-16-walk-always.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-16.walk-same-image PROPERTIES FIXTURES_REQUIRED "ch16-walk-changed;ch16-walk-always")

# Scrolled cascades (chapter-16/shadow_cache.cpp, the default --shadow-redraw): a cascade that
# moved by whole texels keeps what it still covers and draws only the exposed bands. After 30
# frames of walking (2 cm a frame), turning (0.5 degrees), creeping (0.1 mm) and jumping (5 m
# forward or back every 8th frame, more than the first cascades' width: drawn whole), the frame
# is the one drawing every cascade every frame gives, to the bit; the scrolled runs draw few
# cascades whole (the first frame, a jump, a step of the fitted far plane or of a depth window).
# The jump's walk steps the fitted far plane up and down. 30 frames: what each checks happens in
# them (every cascade scrolled in most of them; three jumps; the far plane stepped both ways), and
# each frame costs the always-redrawn reference three cascades of 70,656 triangles through the
# geometry shader (about 0.1 s on lavapipe: the frame count, not the image size, is its time).
set(SCROLL_FRAMES 30)
foreach(case "walk;whole 1, 1, 1" "turn;whole [1-9], [1-9], [1-9]" "creep;whole 1, 1, 1"
             "jump;whole 4, 4, 4\\).*the fitted far plane stepped up [1-9] and down [1-9] times")
    list(GET case 0 motion)
    list(GET case 1 expected)
    foreach(redraw scrolled always)
        if(redraw STREQUAL "always")
            set(expected "whole ${SCROLL_FRAMES}, ${SCROLL_FRAMES}, ${SCROLL_FRAMES}")
        endif()
        chapter_test(chapter-16.scroll-${motion}-${redraw} WORKDIR /
            COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames ${SCROLL_FRAMES} --camera-motion ${motion}
                    --shadow-redraw ${redraw} --screenshot ${TEST_OUT}/chapter-16-scroll-${motion}-${redraw}.png
            EXPECT_STDOUT "cascades drawn [0-9, ]+ times in ${SCROLL_FRAMES} frames \\(${expected}" QUIET_STDERR)
        set_tests_properties(chapter-16.scroll-${motion}-${redraw} PROPERTIES FIXTURES_SETUP ch16-scroll-${motion}-${redraw})
    endforeach()
    add_test(NAME chapter-16.scroll-${motion}-same-image COMMAND image_compare
        ${TEST_OUT}/chapter-16-scroll-${motion}-scrolled.png --size 320 180
        --golden ${TEST_OUT}/chapter-16-scroll-${motion}-always.png --max-diff 0 --max-fraction 0)
    set_tests_properties(chapter-16.scroll-${motion}-same-image PROPERTIES
        FIXTURES_REQUIRED "ch16-scroll-${motion}-scrolled;ch16-scroll-${motion}-always")
endforeach()

# Along the light: the sun and the camera straight down (shadows/sun_down.json), the camera
# walking down -- the cascades' depth windows step (drawn whole) where their boxes do not move.
# 50 frames: the depth windows step two to four times.
foreach(case "scrolled;whole [2-9], [2-9], [2-9]" "always;whole 50, 50, 50")
    list(GET case 0 redraw)
    list(GET case 1 expected)
    chapter_test(chapter-16.along-light-${redraw} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames 50 --camera-motion walk
                --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/sun_down.json --shadow-redraw ${redraw}
                --screenshot ${TEST_OUT}/chapter-16-along-light-${redraw}.png
        EXPECT_STDOUT "chapter-16: 2 draws.*in 50 frames \\(${expected}\\)" QUIET_STDERR)
    set_tests_properties(chapter-16.along-light-${redraw} PROPERTIES FIXTURES_REQUIRED gltf-cases
        FIXTURES_SETUP ch16-along-light-${redraw})
endforeach()
add_test(NAME chapter-16.along-light-same-image COMMAND image_compare
    ${TEST_OUT}/chapter-16-along-light-scrolled.png --size 320 180
    --golden ${TEST_OUT}/chapter-16-along-light-always.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-16.along-light-same-image PROPERTIES
    FIXTURES_REQUIRED "ch16-along-light-scrolled;ch16-along-light-always")

# Moving casters: the point light and its marker walk toward the camera (5 cm a frame) from the
# last cascade into the middle one, while the camera walks. Every form draws the frame that
# drawing everything every frame does, to the bit: scrolled (the marker drawn apart, into the
# moving casters' map, in the cascades it reaches), scrolled-together (its old and new place
# redrawn in the cached map, a cascade whole only at a step of its depth window or the far
# plane), changed (every cascade whole). The marker's shadow moved: the sun's visibility alone
# (--view visibility) is not the one with the light still. walk-stop: the marker stops after 30 frames and settles back into the
# cached map 8 frames later, the image still the always-drawn one.
foreach(redraw scrolled scrolled-together changed always still)
    set(options --light-motion walk --shadow-redraw ${redraw})
    set(expected "chapter-16: 19 draws")
    if(redraw STREQUAL "still")
        set(options)
    elseif(redraw STREQUAL "scrolled")
        set(expected "moving casters drawn apart in 0, [1-9][0-9]*, [1-9][0-9]* frames")
    elseif(redraw STREQUAL "scrolled-together")
        set(expected "in 120 frames \\(whole [1-9], [1-9], [1-9]\\)")
    endif()
    chapter_test(chapter-16.moving-caster-${redraw} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames 120 --camera-motion walk ${options}
                --screenshot ${TEST_OUT}/chapter-16-moving-caster-${redraw}.png
        EXPECT_STDOUT "${expected}" QUIET_STDERR)
    set_tests_properties(chapter-16.moving-caster-${redraw} PROPERTIES
        FIXTURES_SETUP ch16-moving-caster-${redraw})
    if(NOT redraw MATCHES "^(always|still)$")
        add_test(NAME chapter-16.moving-caster-${redraw}-same-image COMMAND image_compare
            ${TEST_OUT}/chapter-16-moving-caster-${redraw}.png --size 320 180
            --golden ${TEST_OUT}/chapter-16-moving-caster-always.png --max-diff 0 --max-fraction 0)
        set_tests_properties(chapter-16.moving-caster-${redraw}-same-image PROPERTIES
            FIXTURES_REQUIRED "ch16-moving-caster-${redraw};ch16-moving-caster-always")
    endif()
endforeach()
foreach(light walk still)
    chapter_test(chapter-16.moving-caster-visibility-${light} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames 120 --camera-motion walk
                --light-motion ${light} --view visibility
                --screenshot ${TEST_OUT}/chapter-16-moving-caster-visibility-${light}.png
        EXPECT_STDOUT "chapter-16: 19 draws" QUIET_STDERR)
    set_tests_properties(chapter-16.moving-caster-visibility-${light} PROPERTIES
        FIXTURES_SETUP ch16-moving-caster-visibility-${light})
endforeach()
add_test(NAME chapter-16.moving-caster-shadow-moved COMMAND image_compare
    ${TEST_OUT}/chapter-16-moving-caster-visibility-walk.png --size 320 180
    --golden ${TEST_OUT}/chapter-16-moving-caster-visibility-still.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-16.moving-caster-shadow-moved PROPERTIES WILL_FAIL TRUE
    FIXTURES_REQUIRED "ch16-moving-caster-visibility-walk;ch16-moving-caster-visibility-still")
foreach(redraw scrolled always)
    chapter_test(chapter-16.moving-caster-settles-${redraw} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames 60 --camera-motion walk
                --light-motion walk-stop --shadow-redraw ${redraw}
                --screenshot ${TEST_OUT}/chapter-16-moving-caster-settles-${redraw}.png
        EXPECT_STDOUT "chapter-16: 19 draws" QUIET_STDERR)
    set_tests_properties(chapter-16.moving-caster-settles-${redraw} PROPERTIES
        FIXTURES_SETUP ch16-moving-caster-settles-${redraw})
endforeach()
add_test(NAME chapter-16.moving-caster-settles-same-image COMMAND image_compare
    ${TEST_OUT}/chapter-16-moving-caster-settles-scrolled.png --size 320 180
    --golden ${TEST_OUT}/chapter-16-moving-caster-settles-always.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-16.moving-caster-settles-same-image PROPERTIES
    FIXTURES_REQUIRED "ch16-moving-caster-settles-scrolled;ch16-moving-caster-settles-always")

# A resize mid-walk (--resize at frame 30 of 60, to the same aspect ratio: the cascades' boxes
# unchanged by it): every cascade drawn whole again after it, and the frame the always-redrawn one.
foreach(case "scrolled;whole 2, 2, 2" "always;whole 60, 60, 60")
    list(GET case 0 redraw)
    list(GET case 1 expected)
    chapter_test(chapter-16.resize-walk-${redraw} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames 60 --resize 640x360
                --camera-motion walk --shadow-redraw ${redraw}
                --screenshot ${TEST_OUT}/chapter-16-resize-walk-${redraw}.png
        EXPECT_STDOUT "in 60 frames \\(${expected}\\)" QUIET_STDERR)
    set_tests_properties(chapter-16.resize-walk-${redraw} PROPERTIES FIXTURES_SETUP ch16-resize-walk-${redraw})
endforeach()
add_test(NAME chapter-16.resize-walk-same-image COMMAND image_compare
    ${TEST_OUT}/chapter-16-resize-walk-scrolled.png --size 640 360
    --golden ${TEST_OUT}/chapter-16-resize-walk-always.png --max-diff 0 --max-fraction 0)
set_tests_properties(chapter-16.resize-walk-same-image PROPERTIES
    FIXTURES_REQUIRED "ch16-resize-walk-scrolled;ch16-resize-walk-always")

# A reload of the shadow shader mid-walk (tests/chapters/shadow_reload_walk.sh: an edit that
# changes the code, not what it computes): the layers drawn whole with the new pipelines, and the
# last frame the always-redrawn one.
chapter_test(chapter-16.reload-walk WORKDIR /
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/chapters/shadow_reload_walk.sh ${PROJECT_SOURCE_DIR}/shaders ${CH16}
            $<TARGET_FILE:image_compare> ${TEST_OUT}/chapter-16-reload-walk
    EXPECT_STDOUT "shadow_reload_walk: ok")
set_tests_properties(chapter-16.reload-walk PROPERTIES TIMEOUT 900)

# The box over the plane seen with near 0.01 and far 1000 (a scene much smaller than the view;
# extreme logarithmic splits), with the last cascade ending where the scene does and at the far
# plane: the shadow exactly where it was. The box scenes' camera is 10 above the plane, so the
# nearer cascades see nothing (a cascade with nothing in it) and every pixel takes the last.
foreach(far scene view)
    chapter_test(chapter-16.far-1000-${far} WORKDIR /
        COMMAND ${CH16_RUN} --headless --width 320 --height 180 --shadow-far ${far} --check-output
                --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/box_on_plane_far.json
                --screenshot ${TEST_OUT}/chapter-16-far-${far}.png
        EXPECT_STDOUT "light output 320x180: 0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
    set_tests_properties(chapter-16.far-1000-${far} PROPERTIES FIXTURES_REQUIRED gltf-cases
                         FIXTURES_SETUP ch16-far-${far})
    add_test(NAME chapter-16.far-1000-${far}-shadow COMMAND image_compare ${TEST_OUT}/chapter-16-far-${far}.png
        --size 320 180 --pixel 152 106 0 0 0 --pixel 148 113 0 0 0 --pixel 144 121 0 0 0
        --pixel 168 106 156 156 156 --pixel 160 121 156 156 156 --pixel 144 135 156 156 156
        --pixel 160 74 156 156 156 --pixel 129 113 156 156 156 --pixel-tolerance 3)
    set_tests_properties(chapter-16.far-1000-${far}-shadow PROPERTIES FIXTURES_REQUIRED ch16-far-${far})
endforeach()
# The cascades fitted to the scene: the last ends at 10.24 (0.01 x 2^(80/8)), the first step of
# near x 2^(k/8) past the plane's farthest corner (10.2 away), not at 1000.
chapter_test(chapter-16.far-fitted-splits WORKDIR /
    COMMAND ${CH16} --device llvmpipe --headless --width 320 --height 180 --benchmark --warmup 0 --frames 1
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/box_on_plane_far.json
    EXPECT_STDOUT "shadow_cascade_2 +[0-9.]+[.][.]10[.]24 m")
set_tests_properties(chapter-16.far-fitted-splits PROPERTIES FIXTURES_REQUIRED gltf-cases)

# The camera straight up, under the box: finite, non-negative, clean.
chapter_test(chapter-16.camera-up WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180 --check-output
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/camera_up.json
    EXPECT_STDOUT "light output 320x180: 0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
set_tests_properties(chapter-16.camera-up PROPERTIES FIXTURES_REQUIRED gltf-cases)

# Cut-outs: a quad over the plane whose texture is transparent on its half at z < 0, under a sun
# along (1, -1, 0) (tools/gltf_cases.cpp, shadows/cutout_over_plane.json). The opaque half's
# shadow is black at (x 2, z 0.5); the same strip under the transparent half, (2, -0.5), is lit
# like the open plane at (2, -3): 160. Without the shadow pass's alpha test both are black.
chapter_test(chapter-16.cutout-shadow WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/cutout_over_plane.json
            --screenshot ${TEST_OUT}/chapter-16-cutout.png
    EXPECT_STDOUT "chapter-16: 2 draws" QUIET_STDERR)
set_tests_properties(chapter-16.cutout-shadow PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP ch16-cutout)
add_test(NAME chapter-16.cutout-shadow-only-where-opaque COMMAND image_compare ${TEST_OUT}/chapter-16-cutout.png
    --size 320 180 --pixel 152 121 0 0 0 --pixel 168 121 160 160 160 --pixel 207 121 160 160 160
    --pixel-tolerance 3)
set_tests_properties(chapter-16.cutout-shadow-only-where-opaque PROPERTIES FIXTURES_REQUIRED ch16-cutout)

# Which cascade a pixel takes: the plane seen along its length, 1 over it and 10 degrees down,
# far 20 (shadows/cascade_rows.json), --shadow-far view: splits 0.5, 1.97, 6.23, 20 (lambda 0.95).
# In column 100, rows 170 and 150 lie 1.47 and 1.80 away (the first cascade, tinted red), rows 132,
# 100 and 90 at 2.26, 4.17 and 5.66 (the second, green), rows 84 and 80 at 7.20 and 8.80 (the
# third, blue). The sun straight down lights the plane evenly: 187 in the tint's channel, 99 in
# the others.
chapter_test(chapter-16.cascade-choice WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180 --view cascades --shadow-far view
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/cascade_rows.json
            --screenshot ${TEST_OUT}/chapter-16-cascade-rows.png
    EXPECT_STDOUT "chapter-16: 2 draws" QUIET_STDERR)
set_tests_properties(chapter-16.cascade-choice PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP ch16-rows)
add_test(NAME chapter-16.cascade-choice-by-distance COMMAND image_compare ${TEST_OUT}/chapter-16-cascade-rows.png
    --size 320 180 --pixel 100 170 187 99 99 --pixel 100 150 187 99 99 --pixel 100 132 99 187 99
    --pixel 100 100 99 187 99 --pixel 100 90 99 187 99 --pixel 100 84 99 99 187 --pixel 100 80 99 99 187
    --pixel-tolerance 3)
set_tests_properties(chapter-16.cascade-choice-by-distance PROPERTIES FIXTURES_REQUIRED ch16-rows)

# --book-scene on the stand-in clone (tools/gltf_cases.cpp, book/): the book's chapter-16 set-up --
# its camera at (-5, 5, 0) looking along +x, the sun straight down at intensity 8, no point light
# and no marker cube (5 draws where chapter-15 has 6), and the stand-in tree in the book's converted
# format (2 draws more, its crown a checker of cut-out leaves whose shadow is a checker too); from
# the clone or from its chapter-15 Sponza.gltf; a clone without chapter-16's tree: the scene
# without it, said.
chapter_test(chapter-16.book-scene WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 640 --height 360 --book-scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/book
            --screenshot ${TEST_OUT}/chapter-16-book-scene.png
    EXPECT_STDOUT "chapter-16: 7 draws, 650 triangles.*1 lights" QUIET_STDERR)
chapter_test(chapter-16.book-scene-from-gltf WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180 --book-scene
            ${CMAKE_CURRENT_BINARY_DIR}/gltf/book/booksamples/chapter-15/resources/models/sponza/Sponza.gltf
    EXPECT_STDOUT "chapter-16: 7 draws, 650 triangles" QUIET_STDERR)
chapter_test(chapter-16.book-scene-without-tree WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180 --book-scene
            ${CMAKE_CURRENT_BINARY_DIR}/gltf/book-without-tree
    EXPECT_STDOUT "chapter-16: 5 draws, 640 triangles"
    EXPECT_STDERR "^warning: the book's tree is not at .*book-without-tree/booksamples/chapter-16/resources/models/tree/tree.json \\(nor tree.obj\\): the scene without it\n$")
# A clone whose tree is the tree.obj the book converted, without the converted files: the same
# scene, the tree read from the OBJ (two draws more, ten triangles).
chapter_test(chapter-16.book-scene-obj-tree WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 640 --height 360 --book-scene
            ${CMAKE_CURRENT_BINARY_DIR}/gltf/book-obj-tree --screenshot ${TEST_OUT}/chapter-16-book-scene-obj-tree.png
    EXPECT_STDOUT "chapter-16: 7 draws, 650 triangles" QUIET_STDERR)
set_tests_properties(chapter-16.book-scene-obj-tree PROPERTIES FIXTURES_SETUP ch16-book-obj)
add_test(NAME chapter-16.book-scene-obj-tree-image COMMAND image_compare ${TEST_OUT}/chapter-16-book-scene-obj-tree.png
    --size 640 360 --golden ${GOLDEN}/chapter-16-book-scene.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-16.book-scene-obj-tree-image PROPERTIES FIXTURES_REQUIRED ch16-book-obj)
# The Sponza.gltf given as a relative path, from its own directory: the tree found all the same.
chapter_test(chapter-16.book-scene-relative
    WORKDIR ${CMAKE_CURRENT_BINARY_DIR}/gltf/book/booksamples/chapter-15/resources/models/sponza
    COMMAND ${CH16_RUN} --headless --width 320 --height 180 --book-scene Sponza.gltf
    EXPECT_STDOUT "chapter-16: 7 draws, 650 triangles" QUIET_STDERR)
set_tests_properties(chapter-16.book-scene-from-gltf chapter-16.book-scene-without-tree
    chapter-16.book-scene-obj-tree chapter-16.book-scene-relative PROPERTIES FIXTURES_REQUIRED gltf-cases)
set_tests_properties(chapter-16.book-scene PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP ch16-book)
add_test(NAME chapter-16.book-scene-image COMMAND image_compare ${TEST_OUT}/chapter-16-book-scene.png
    --size 640 360 --golden ${GOLDEN}/chapter-16-book-scene.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-16.book-scene-image PROPERTIES FIXTURES_REQUIRED ch16-book)

# A scene without a sun: the first frame clears the layers (the light pass reads them: counted as
# drawn whole once), and nothing is ever drawn into them; finite output, validation clean.
chapter_test(chapter-16.no-sun WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180 --frames 5 --check-output
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/no_sun.json
    EXPECT_STDOUT "cascades drawn 1, 1, 1 times in 5 frames \\(whole 1, 1, 1\\).*0.0, 0.0, 0.0 draws per cascade.*light output 320x180: 0 NaN, 0 infinite, 0 negative"
    QUIET_STDERR)
set_tests_properties(chapter-16.no-sun PROPERTIES FIXTURES_REQUIRED gltf-cases)

# Peter-panning: a box standing on the plane under the sun one degree above the horizon, along +x
# (shadows/box_standing_grazing.json). The plane a quarter metre behind its foot is in its shadow
# -- (0.75, 0), (0.7, 0.25) -- as is a point 2.5 m behind it (3, 0); beside the strip (3, 1) and in
# front of the box (-2, 0) it is lit (23: the sun at one degree). An offset lifting the receivers
# 100 times further (150 texels) lights all of the strip's points: the test fails with it.
chapter_test(chapter-16.standing-box-grazing WORKDIR /
    COMMAND ${CH16_RUN} --headless --width 320 --height 180
            --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/box_standing_grazing.json
            --screenshot ${TEST_OUT}/chapter-16-standing-box.png
    EXPECT_STDOUT "chapter-16: 2 draws" QUIET_STDERR)
set_tests_properties(chapter-16.standing-box-grazing PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP ch16-standing)
add_test(NAME chapter-16.standing-box-no-peter-panning COMMAND image_compare ${TEST_OUT}/chapter-16-standing-box.png
    --size 320 180 --pixel 160 102 0 0 0 --pixel 156 101 0 0 0 --pixel 160 137 0 0 0
    --pixel 144 137 23 23 23 --pixel 160 59 23 23 23 --pixel-tolerance 2)
set_tests_properties(chapter-16.standing-box-no-peter-panning PROPERTIES FIXTURES_REQUIRED ch16-standing)
