# chapter-15-lab's shadow study (chapter-15-lab/shadow_study.cpp, docs/chapter-15-lab.md): every
# filter with every way of drawing the cascades, validation clean; the variance map's visibility the
# same to the bit whichever way its layers are drawn, and the same as chapter-16's; what the study
# cannot be combined with, refused; and the reference (tests/accuracy/shadow_reference.cpp): a
# shadow map's visibility on the box over the plane and on the cut-out agrees with the rays', and a
# visibility from another sun does not.
set(LAB_RUN $<TARGET_FILE:chapter-15-lab> --device llvmpipe --validation --headless)
set(STUDY_SIZE --width 320 --height 180)

chapter_test(lab.shadows-chapter-16-visibility
    COMMAND $<TARGET_FILE:chapter-16> --device llvmpipe --validation --headless ${STUDY_SIZE} --view visibility
            --frames 3 --screenshot ${TEST_OUT}/lab-shadows-chapter-16.png QUIET_STDERR)
set_tests_properties(lab.shadows-chapter-16-visibility PROPERTIES FIXTURES_SETUP lab-shadows-ch16)
foreach(filter vsm pcf2 pcf3 pcf5 vsm16 depth)
    foreach(layers geometry multiview passes)
        set(name lab.shadows-${filter}-${layers})
        chapter_test(${name}
            COMMAND ${LAB_RUN} ${STUDY_SIZE} --shadows ${filter} --shadow-layers ${layers} --view visibility
                    --frames 3 --screenshot ${TEST_OUT}/${name}.png
            EXPECT_STDOUT "19 draws" QUIET_STDERR)
        set_tests_properties(${name} PROPERTIES FIXTURES_SETUP ${name})
    endforeach()
    # The layers drawn in one pass with multiview, or a pass each: the very same map.
    foreach(layers multiview passes)
        add_test(NAME lab.shadows-${filter}-${layers}-same COMMAND image_compare
            ${TEST_OUT}/lab.shadows-${filter}-${layers}.png --golden ${TEST_OUT}/lab.shadows-${filter}-geometry.png
            --max-diff 0 --max-fraction 0)
        set_tests_properties(lab.shadows-${filter}-${layers}-same PROPERTIES
            FIXTURES_REQUIRED "lab.shadows-${filter}-${layers};lab.shadows-${filter}-geometry")
    endforeach()
endforeach()
# The variance map is chapter-16's, to the bit; PCF is another image (its own test below).
add_test(NAME lab.shadows-vsm-is-chapter-16 COMMAND image_compare ${TEST_OUT}/lab.shadows-vsm-geometry.png
    --golden ${TEST_OUT}/lab-shadows-chapter-16.png --max-diff 0 --max-fraction 0)
set_tests_properties(lab.shadows-vsm-is-chapter-16 PROPERTIES
    FIXTURES_REQUIRED "lab.shadows-vsm-geometry;lab-shadows-ch16")
chapter_test(lab.shadows-pcf-is-not-vsm COMMAND $<TARGET_FILE:image_compare> ${TEST_OUT}/lab.shadows-pcf5-geometry.png
    --golden ${TEST_OUT}/lab.shadows-vsm-geometry.png --max-diff 0 --max-fraction 0
    EXPECT_EXIT 1 EXPECT_STDOUT "FAIL golden .*max abs diff [1-9]")
set_tests_properties(lab.shadows-pcf-is-not-vsm PROPERTIES
    FIXTURES_REQUIRED "lab.shadows-pcf5-geometry;lab.shadows-vsm-geometry")

# The half-float moments and the depth alone are other maps: other images.
foreach(filter vsm16 depth)
    chapter_test(lab.shadows-${filter}-is-not-vsm COMMAND $<TARGET_FILE:image_compare>
        ${TEST_OUT}/lab.shadows-${filter}-geometry.png --golden ${TEST_OUT}/lab.shadows-vsm-geometry.png --max-diff 0
        --max-fraction 0 EXPECT_EXIT 1 EXPECT_STDOUT "FAIL golden .*max abs diff [1-9]")
    set_tests_properties(lab.shadows-${filter}-is-not-vsm PROPERTIES
        FIXTURES_REQUIRED "lab.shadows-${filter}-geometry;lab.shadows-vsm-geometry")
endforeach()

# The report names the study; lavapipe cannot filter depth linearly, so PCF gathers its taps.
chapter_test(lab.shadows-benchmark
    COMMAND ${LAB_RUN} ${STUDY_SIZE} --shadows pcf3 --cascades 2 --shadow-map-size 1024 --benchmark --warmup 0
            --frames 2
    EXPECT_STDOUT "shadow_study +pcf3, geometry shader, 2 cascades of 1024\npcf_taps +gathered.*GPU shadow +[0-9]"
    QUIET_STDERR)

foreach(case "compute|--light-pass compute|--shadows shades with the fragment light pass, not --light-pass compute"
             "tiled|--light-culling tiled|--shadows loops over every light: no --light-culling tiled"
             "forward|--shading forward|--shadows reads the G-buffer: no --shading forward"
             "compact|--gbuffer compact|--shadows reads the G-buffer's positions: --gbuffer book or reference")
    string(REPLACE "|" ";" parts "${case}")
    list(GET parts 0 name)
    list(GET parts 1 option)
    list(GET parts 2 message)
    separate_arguments(option)
    chapter_test(lab.shadows-refused-${name} COMMAND ${LAB_RUN} --shadows vsm ${option}
        EXPECT_EXIT 2 EXPECT_STDERR "${message}" ONE_LINE_STDERR)
endforeach()
foreach(option "--shadow-layers multiview" "--cascades 2" "--shadow-map-size 512" "--view visibility")
    separate_arguments(args UNIX_COMMAND "${option}")
    list(GET args 0 flag)
    string(REGEX REPLACE "^--" "" name "${flag}")
    set(needs "${flag}")
    if(flag STREQUAL "--view")
        set(needs "--view visibility")
    endif()
    chapter_test(lab.shadows-${name}-needs-shadows COMMAND ${LAB_RUN} ${args}
        EXPECT_EXIT 2 EXPECT_STDERR "${needs} needs --shadows" ONE_LINE_STDERR)
endforeach()

if(TARGET shadow_reference)
    set(SHADOWS_GLTF ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows)
    set(REFERENCE $<TARGET_FILE:shadow_reference>)
    # The box over the plane (its shadow's outline known: chapters/chapter-16.cmake) and the cut-out, each
    # dumped at 640x360 with the variance map and with PCF 3x3.
    foreach(scene box_on_plane cutout_over_plane sun_down default)
        foreach(filter vsm pcf3 depth)
            if(scene MATCHES "sun_down|default" AND filter MATCHES "pcf3|depth")
                continue()
            endif()
            set(file ${SHADOWS_GLTF}/${scene}.json)
            if(scene STREQUAL "default")
                set(file ${CMAKE_BINARY_DIR}/bin/scenes/default/scene.json)
            endif()
            set(name lab.shadows-dump-${scene}-${filter})
            chapter_test(${name} WORKDIR /
                COMMAND ${LAB_RUN} --width 640 --height 360 --gbuffer reference --scene ${file}
                        --shadows ${filter} --view visibility --dump ${TEST_OUT}/study/${scene}-${filter}
                EXPECT_STDOUT "draws" QUIET_STDERR)
            set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP ${name})
        endforeach()
    endforeach()
    # Against the rays: at most 0.2% of the pixels facing the sun wrong, and none away from an
    # outline (no acne, no leak). Measured: 0.02-0.04%, all at the outlines. Rays that ignored the
    # cut-out's alpha would shadow the strip under its transparent half: 1.5% wrong.
    # The rays find the frame's surfaces (over 130,000 pixels facing the sun of 230,400).
    foreach(scene box_on_plane cutout_over_plane)
        chapter_test(lab.shadows-reference-${scene}
            COMMAND ${REFERENCE} ${SHADOWS_GLTF}/${scene}.json ${TEST_OUT}/study/${scene}-vsm
                    --compare vsm=${TEST_OUT}/study/${scene}-vsm/light.pfm
                    --compare pcf3=${TEST_OUT}/study/${scene}-pcf3/light.pfm
                    --compare depth=${TEST_OUT}/study/${scene}-depth/light.pfm --max-wrong 0.002
            EXPECT_STDOUT "reference: 640x360, [0-9]+ triangles, 1[3-9][0-9][0-9][0-9][0-9] pixels facing the sun.*\nvsm +[0-9.]+ +[0-9.]+ +0[.]000 +0[.]000 .*\npcf3 +[0-9.]+ +[0-9.]+ +0[.]000 +0[.]000 .*\ndepth +[0-9.]+ +[0-9.]+ +0[.]000 +0[.]000 ")
        set_tests_properties(lab.shadows-reference-${scene} PROPERTIES
            FIXTURES_REQUIRED "lab.shadows-dump-${scene}-vsm;lab.shadows-dump-${scene}-pcf3;lab.shadows-dump-${scene}-depth")
    endforeach()
    # The same plane under the sun straight down, compared with the rays of the slanted sun: the
    # shadow is elsewhere, and the comparison must say so (exit 1: 1.8% wrong, over the 0.2%).
    chapter_test(lab.shadows-reference-sees-a-wrong-sun
        COMMAND ${REFERENCE} ${SHADOWS_GLTF}/box_on_plane.json ${TEST_OUT}/study/box_on_plane-vsm
                --compare wrong-sun=${TEST_OUT}/study/sun_down-vsm/light.pfm --max-wrong 0.002
        EXPECT_EXIT 1 EXPECT_STDOUT "FAIL wrong-sun: 1[.][0-9]+% of the pixels wrong, allowed 0[.]200%")
    set_tests_properties(lab.shadows-reference-sees-a-wrong-sun PROPERTIES
        FIXTURES_REQUIRED "lab.shadows-dump-box_on_plane-vsm;lab.shadows-dump-sun_down-vsm")
    # Another scene's G-buffer (the courtyard's, against the box scene): the camera's rays miss it,
    # and the comparison is refused rather than passed with nothing counted.
    chapter_test(lab.shadows-reference-another-frame
        COMMAND ${REFERENCE} ${SHADOWS_GLTF}/box_on_plane.json ${TEST_OUT}/study/default-vsm
                --compare vsm=${TEST_OUT}/study/default-vsm/light.pfm
        EXPECT_EXIT 2 EXPECT_STDERR "the camera's rays miss [0-9]+ of the G-buffer's surface pixels" ONE_LINE_STDERR)
    set_tests_properties(lab.shadows-reference-another-frame PROPERTIES
        FIXTURES_REQUIRED "gltf-cases;lab.shadows-dump-default-vsm")
    # A PFM whose 22-byte header asks for 16384 x 16384 pixels it does not hold: refused before
    # anything is allocated for them.
    file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/hostile-pfm/position.pfm "PF\n16384 16384\n-1\n")
    file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/hostile-pfm/coverage.pfm "PF\n16384 16384\n-1\n")
    chapter_test(lab.shadows-reference-truncated-pfm COMMAND ${REFERENCE} ${SHADOWS_GLTF}/box_on_plane.json
                 ${CMAKE_CURRENT_BINARY_DIR}/hostile-pfm
        EXPECT_EXIT 2 EXPECT_STDERR "shadow_reference: .*hostile-pfm/position.pfm: truncated" ONE_LINE_STDERR)
    set_tests_properties(lab.shadows-reference-truncated-pfm PROPERTIES FIXTURES_REQUIRED gltf-cases TIMEOUT 20)
    # A directory without the G-buffer: one line, exit 2.
    chapter_test(lab.shadows-reference-bad-dir COMMAND ${REFERENCE} ${SHADOWS_GLTF}/box_on_plane.json
                 ${TEST_OUT}/study/no-such-dir
        EXPECT_EXIT 2 EXPECT_STDERR "shadow_reference: .*no-such-dir/position.pfm: not a little-endian PFM file"
        ONE_LINE_STDERR)
    set_tests_properties(lab.shadows-reference-bad-dir PROPERTIES FIXTURES_REQUIRED gltf-cases)
endif()
