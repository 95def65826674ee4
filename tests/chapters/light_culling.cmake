# chapter-15-lab: light ranges and tiled light culling. The culled image must equal
# the book's loop over every light (with the same ranges) up to fp32 rounding of the sum --
# pfm_compare's bound -- in every hard case, under validation (synchronization validation on):
# many lights, both light-pass forms and G-buffer layouts; a light whose range covers the whole
# screen; a light inside the near plane; a light behind a wall (culled by depth: no tile lists
# it); 65,536 lights in one tile; lists too long for their buffer; tiles of sky; a resize to a size that is no multiple of the
# tile; the camera turning while frames are in flight; --light-cutoff. Plus the options' errors.
set(LIGHT_SCENES ${CMAKE_BINARY_DIR}/bin/scenes)
set(CULL_SIZE --width 320 --height 180)

# culling_case(NAME LIGHTS ARGS... [TILED_STDOUT regex]): renders ARGS with --light-culling none
# and tiled, dumps both light outputs and compares them (LIGHTS: the scene's light count, for the
# rounding bound; at least 20% of the values must be lit).
function(culling_case name lights)
    cmake_parse_arguments(C "" "TILED_STDOUT" "ARGS" ${ARGN})
    if(NOT C_TILED_STDOUT)
        set(C_TILED_STDOUT "light culling: [0-9]+ light-tile pairs")
    endif()
    foreach(mode none tiled)
        set(expect "0 NaN, 0 infinite, 0 negative")
        if(mode STREQUAL tiled)
            set(expect "${C_TILED_STDOUT}.*0 NaN, 0 infinite, 0 negative")
        endif()
        chapter_test(chapter-15-lab.cull-${name}-${mode}
            COMMAND ${LAB_RUN} --headless ${C_ARGS} --light-culling ${mode} --check-output
                    --dump ${TEST_OUT}/cull-${name}-${mode}
            EXPECT_STDOUT "${expect}" QUIET_STDERR)
        set_tests_properties(chapter-15-lab.cull-${name}-${mode} PROPERTIES FIXTURES_SETUP cull-${name}-${mode})
    endforeach()
    add_test(NAME chapter-15-lab.cull-${name}-equals-loop
        COMMAND pfm_compare ${TEST_OUT}/cull-${name}-tiled/light.pfm ${TEST_OUT}/cull-${name}-none/light.pfm
                --lights ${lights} --min-lit 0.2)
    set_tests_properties(chapter-15-lab.cull-${name}-equals-loop PROPERTIES
        FIXTURES_REQUIRED "cull-${name}-none;cull-${name}-tiled")
endfunction()

# Many lights (the generated scene), each light-pass form with each G-buffer layout once.
culling_case(lights-1024-fragment-book 1024 ARGS ${CULL_SIZE} --scene ${LIGHT_SCENES}/lights-1024/scene.json)
culling_case(lights-1024-compute-compact 1024
    ARGS ${CULL_SIZE} --scene ${LIGHT_SCENES}/lights-1024/scene.json --light-pass compute --gbuffer compact)
culling_case(lights-4096-compute-reference 4096
    ARGS ${CULL_SIZE} --scene ${LIGHT_SCENES}/lights-4096/scene.json --light-pass compute --gbuffer reference)

# Hard cases on the test scenes' models (SCENE_MODELS, chapters/chapter-15.cmake): a sun, so that no pixel
# is black, plus the light(s) of the case.
set(SUN "{\"type\": \"directional\", \"direction\": [0.3, -1, -0.4], \"intensity\": 0.5}")
# A light whose range (1000) covers every pixel: every lit tile lists it.
file(WRITE ${TEST_SCENES}/cull-whole-screen.json "{${SCENE_MODELS}, \"lights\": [${SUN},
  {\"type\": \"point\", \"position\": [0, 3, 2], \"color\": [1, 0.5, 0.2], \"intensity\": 20, \"range\": 1000},
  {\"type\": \"point\", \"position\": [3, 1, 0], \"color\": [0.2, 0.5, 1], \"intensity\": 2, \"range\": 2}]}\n")
culling_case(whole-screen 3 ARGS ${CULL_SIZE} --scene ${TEST_SCENES}/cull-whole-screen.json)
# A light 5 cm in front of the camera, closer than the near plane (10 cm): its sphere is clipped
# by the near plane, its rectangle is the whole screen.
file(WRITE ${TEST_SCENES}/cull-near-plane.json "{${SCENE_MODELS}, \"lights\": [${SUN},
  {\"type\": \"point\", \"position\": [0, 3.19, 12.45], \"color\": [1, 1, 0.8], \"intensity\": 30, \"range\": 14}]}\n")
culling_case(near-plane 2 ARGS ${CULL_SIZE} --scene ${TEST_SCENES}/cull-near-plane.json)
# A light 1.5 units behind the north wall (z = -15) with range 0.9: its rectangle covers wall
# tiles, but no surface of theirs is within its reach, so no tile lists it. (A tile's box is
# axis-aligned in view space, so it reaches a little off the tilted wall: at 1 unit behind it,
# two tiles' boxes still touched the sphere.)
file(WRITE ${TEST_SCENES}/cull-behind-wall.json "{${SCENE_MODELS}, \"lights\": [${SUN},
  {\"type\": \"point\", \"position\": [0, 3, -16.5], \"color\": [1, 0, 0], \"intensity\": 50, \"range\": 0.9}]}\n")
culling_case(behind-wall 2 ARGS ${CULL_SIZE} --scene ${TEST_SCENES}/cull-behind-wall.json
    TILED_STDOUT "light culling: 0 light-tile pairs")
# Tiles of sky: the camera looks up over the wall; lights along the wall tops reach into tiles
# with no surface, which list nothing.
set(TOP_LIGHTS "")
foreach(x -12 -8 -4 0 4 8 12)
    string(APPEND TOP_LIGHTS ", {\"type\": \"point\", \"position\": [${x}, 6.3, -14.5], \"color\": [0.4, 0.8, 1], \"intensity\": 3, \"range\": 2.5}")
endforeach()
string(REPLACE "\"pitch\": -10" "\"pitch\": 12" SKY_SCENE "${SCENE_MODELS}")
file(WRITE ${TEST_SCENES}/cull-sky.json "{${SKY_SCENE}, \"lights\": [${SUN}${TOP_LIGHTS}]}\n")
culling_case(sky 8 ARGS ${CULL_SIZE} --scene ${TEST_SCENES}/cull-sky.json)

# 65,536 lights within 2 cm of one point: all of them in one tile (the longest list holds them
# all), in a tile grid of 12 x 7 tiles.
add_test(NAME chapter-15-lab.cull-cluster-scene
    COMMAND generate_light_scene ${LIGHT_SCENES}/default 65536 ${TEST_SCENES}/cull-cluster.json --cluster)
set_tests_properties(chapter-15-lab.cull-cluster-scene PROPERTIES FIXTURES_SETUP cull-cluster-scene)
culling_case(cluster-65536 65536 ARGS --width 96 --height 54 --scene ${TEST_SCENES}/cull-cluster.json
    TILED_STDOUT "at most 65536 lights in a tile")
foreach(mode none tiled)
    set_property(TEST chapter-15-lab.cull-cluster-65536-${mode} APPEND PROPERTY FIXTURES_REQUIRED cull-cluster-scene)
endforeach()

# Lists that do not fit: 2,000 lights whose range (100) covers every tile need 2,000 entries per
# tile, far more than the 64 per tile (plus 4 per light) the lists are sized for. The tiles that
# do not fit are shaded with every light, and the image is still the loop's.
add_test(NAME chapter-15-lab.cull-overflow-scene
    COMMAND generate_light_scene ${LIGHT_SCENES}/default 2000 ${TEST_SCENES}/cull-overflow.json --range 100)
set_tests_properties(chapter-15-lab.cull-overflow-scene PROPERTIES FIXTURES_SETUP cull-overflow-scene)
culling_case(overflow 2000 ARGS --width 160 --height 90 --scene ${TEST_SCENES}/cull-overflow.json
    TILED_STDOUT "at most 2000 lights in a tile, [1-9][0-9]* tiles over capacity")
foreach(mode none tiled)
    set_property(TEST chapter-15-lab.cull-overflow-${mode} APPEND PROPERTY FIXTURES_REQUIRED cull-overflow-scene)
endforeach()

# A resize (to 333x197: tiles overhang both edges) while frames are in flight: the tile grid and
# lists follow the window.
culling_case(resize 1024 ARGS ${CULL_SIZE} --scene ${LIGHT_SCENES}/lights-1024/scene.json --frames 4 --resize 333x197)
# The camera turning 9 degrees a frame, three frames in flight: each frame's lists are its own.
culling_case(camera-turning 256
    ARGS ${CULL_SIZE} --scene ${LIGHT_SCENES}/lights-256/scene.json --frames 8 --frames-in-flight 3 --orbit 9)
# --light-cutoff on the default scene: its point light gets a range (sqrt(6 / 0.01) = 24.5).
culling_case(cutoff 2 ARGS ${CULL_SIZE} --light-cutoff 0.01 TILED_STDOUT "1 point lights get a range.*light culling")

chapter_test(chapter-15-lab.light-cutoff-bad COMMAND ${LAB} --headless --light-cutoff -1
    EXPECT_EXIT 2 EXPECT_STDERR "--light-cutoff must be a positive number \\(an irradiance\\), got '-1'" ONE_LINE_STDERR)
chapter_test(chapter-15-lab.light-cutoff-not-a-number COMMAND ${LAB} --headless --light-cutoff 1e-3x
    EXPECT_EXIT 2 EXPECT_STDERR "--light-cutoff must be a positive number" ONE_LINE_STDERR)
chapter_test(chapter-15-lab.light-cutoff-zero COMMAND ${LAB} --headless --light-cutoff 0
    EXPECT_EXIT 2 EXPECT_STDERR "--light-cutoff must be a positive number" ONE_LINE_STDERR)
chapter_test(chapter-15-lab.orbit-bad COMMAND ${LAB} --headless --orbit 400
    EXPECT_EXIT 2 EXPECT_STDERR "--orbit must be a number of degrees within -360..360, got '400'" ONE_LINE_STDERR)
chapter_test(chapter-15-lab.bad-light-culling COMMAND ${LAB} --headless --light-culling clustered
    EXPECT_EXIT 2 EXPECT_STDERR "--light-culling must be one of none\\|tiled" ONE_LINE_STDERR)

# The many-light scene as a picture: tiled culling against its golden image.
chapter_test(chapter-15-lab.lights-1024-tiled
    COMMAND ${LAB_RUN} --headless ${LAB_SIZE} --scene ${LIGHT_SCENES}/lights-1024/scene.json --light-culling tiled
            --screenshot ${TEST_OUT}/chapter-15-lights-1024.png QUIET_STDERR)
set_tests_properties(chapter-15-lab.lights-1024-tiled PROPERTIES FIXTURES_SETUP ch15-lights-1024)
add_test(NAME chapter-15-lab.lights-1024-tiled-image COMMAND image_compare ${TEST_OUT}/chapter-15-lights-1024.png
    --size 640 360 --golden ${GOLDEN}/chapter-15-lights-1024.png --max-diff 5 --max-fraction 0.001)
set_tests_properties(chapter-15-lab.lights-1024-tiled-image PROPERTIES FIXTURES_REQUIRED ch15-lights-1024)
