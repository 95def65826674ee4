# chapter-15 tests: every view against its golden image; the light output finite and
# non-negative; scenes with no lights, a directional light only and 64 point lights; the window
# with key presses that move the lights and a resize.
set(CH15 $<TARGET_FILE:chapter-15>)
set(CH15_RUN ${CH15} --device llvmpipe --validation)
set(CH15_SIZE --width 640 --height 360)

foreach(view final position albedo normal pbr depth)
    chapter_test(chapter-15.view-${view} WORKDIR /
        COMMAND ${CH15_RUN} --headless ${CH15_SIZE} --view ${view} --screenshot ${TEST_OUT}/chapter-15-${view}.png
        EXPECT_STDOUT "70656 triangles" QUIET_STDERR)
    set_tests_properties(chapter-15.view-${view} PROPERTIES FIXTURES_SETUP ch15-${view})
    add_test(NAME chapter-15.view-${view}-image COMMAND image_compare ${TEST_OUT}/chapter-15-${view}.png
        --size 640 360 --golden ${GOLDEN}/chapter-15-${view}.png --max-diff 5 --max-fraction 0.001)
    set_tests_properties(chapter-15.view-${view}-image PROPERTIES FIXTURES_REQUIRED ch15-${view})
endforeach()

# The light pass's float output: no NaN, no infinity, nothing negative, at 1280x720, with FXAA
# and 3 frames in flight for good measure.
# The book's G-buffer: four R16G16B16A16_SFLOAT attachments and D32_SFLOAT depth, 36 bytes a pixel.
chapter_test(chapter-15.gbuffer-bytes-per-pixel COMMAND ${CH15_RUN} --headless --benchmark --warmup 0 --frames 1
    EXPECT_STDOUT "gbuffer_bytes_per_pixel +36\n" QUIET_STDERR)
chapter_test(chapter-15.output-finite COMMAND ${CH15_RUN} --headless --check-output --fxaa --frames 4 --frames-in-flight 3
    EXPECT_STDOUT "light output 1280x720: 0 NaN, 0 infinite, 0 negative" QUIET_STDERR)

# Test scenes on the default scene's models: written here, with absolute model paths.
set(SCENE_DIR ${CMAKE_BINARY_DIR}/bin/scenes/default)
set(TEST_SCENES ${CMAKE_CURRENT_BINARY_DIR}/scenes)
set(SCENE_MODELS "\"models\": [{\"file\": \"${SCENE_DIR}/courtyard.obj\"},
  {\"file\": \"${SCENE_DIR}/sphere.obj\", \"position\": [-2, 0.75, 1], \"scale\": 0.7, \"materials\": {\"sphere\": {\"diffuse\": [0.8, 0.1, 0.08, 1], \"roughness\": 0.3}}},
  {\"file\": \"${SCENE_DIR}/sphere.obj\", \"position\": [0, 0.75, 1], \"scale\": 0.7, \"materials\": {\"sphere\": {\"diffuse\": [1, 0.77, 0.34, 1], \"roughness\": 0, \"metallic\": 1}}},
  {\"file\": \"${SCENE_DIR}/sphere.obj\", \"position\": [2, 0.75, 1], \"scale\": 0.7, \"materials\": {\"sphere\": {\"roughness\": 1}}},
  {\"file\": \"${SCENE_DIR}/grille.obj\", \"position\": [0, 0.1, -6]}],
  \"camera\": {\"position\": [0, 3.2, 12.5], \"pitch\": -10, \"near\": 0.1, \"far\": 60},
  \"ambient\": {\"color\": [1, 1, 1], \"intensity\": 0.2}")
file(WRITE ${TEST_SCENES}/no-lights.json "{${SCENE_MODELS}, \"lights\": []}\n")
file(WRITE ${TEST_SCENES}/directional-only.json
     "{${SCENE_MODELS}, \"lights\": [{\"type\": \"directional\", \"direction\": [0.3, -1, -0.4], \"intensity\": 2}]}\n")
set(POINT_LIGHTS "")
foreach(i RANGE 63)  # an 8 x 8 grid over the floor, colours cycling
    math(EXPR gx "${i} % 8")
    math(EXPR gz "${i} / 8")
    math(EXPR x "${gx} * 3 - 10")
    math(EXPR z "${gz} * 3 - 10")
    math(EXPR channel "${i} % 3")
    set(colors "[1, 0, 0]" "[0, 1, 0]" "[0, 0, 1]")
    list(GET colors ${channel} color)
    string(APPEND POINT_LIGHTS "{\"type\": \"point\", \"position\": [${x}, 1.5, ${z}], \"color\": ${color}, \"intensity\": 3},")
endforeach()
string(REGEX REPLACE ",$" "" POINT_LIGHTS "${POINT_LIGHTS}")
file(WRITE ${TEST_SCENES}/many-point-lights.json "{${SCENE_MODELS}, \"lights\": [${POINT_LIGHTS}]}\n")

foreach(scene no-lights directional-only many-point-lights)
    chapter_test(chapter-15.scene-${scene}
        COMMAND ${CH15_RUN} --headless ${CH15_SIZE} --scene ${TEST_SCENES}/${scene}.json --check-output
                --screenshot ${TEST_OUT}/chapter-15-${scene}.png
        EXPECT_STDOUT "0 NaN, 0 infinite, 0 negative" QUIET_STDERR)
    set_tests_properties(chapter-15.scene-${scene} PROPERTIES FIXTURES_SETUP ch15-${scene})
endforeach()
chapter_test(chapter-15.scene-many-point-lights-count COMMAND ${CH15_RUN} --headless --width 64 --height 36
    --scene ${TEST_SCENES}/many-point-lights.json EXPECT_STDOUT ", 64 lights" QUIET_STDERR)
# With no lights, what is left is ambient light: final = 0.2 x albedo (in linear colour).
chapter_test(chapter-15.scene-no-lights-albedo
    COMMAND ${CH15_RUN} --headless ${CH15_SIZE} --scene ${TEST_SCENES}/no-lights.json --view albedo
            --screenshot ${TEST_OUT}/chapter-15-no-lights-albedo.png QUIET_STDERR)
set_tests_properties(chapter-15.scene-no-lights-albedo PROPERTIES FIXTURES_SETUP ch15-no-lights-albedo)
add_test(NAME chapter-15.no-lights-is-ambient-times-albedo
    COMMAND image_compare ${TEST_OUT}/chapter-15-no-lights.png
            --expect-scaled ${TEST_OUT}/chapter-15-no-lights-albedo.png 0.2 --max-diff 2 --max-fraction 0.001)
set_tests_properties(chapter-15.no-lights-is-ambient-times-albedo PROPERTIES
    FIXTURES_REQUIRED "ch15-no-lights;ch15-no-lights-albedo")
# And lights do add light: the directional-only image is not the ambient-only one.
add_test(NAME chapter-15.directional-light-adds-light
    COMMAND image_compare ${TEST_OUT}/chapter-15-directional-only.png
            --expect-scaled ${TEST_OUT}/chapter-15-no-lights-albedo.png 0.2 --max-diff 2 --max-fraction 0.001)
set_tests_properties(chapter-15.directional-light-adds-light PROPERTIES
    FIXTURES_REQUIRED "ch15-directional-only;ch15-no-lights-albedo" WILL_FAIL TRUE)

if(XVFB_RUN)
    find_program(XDOTOOL xdotool)
    if(XDOTOOL)
        chapter_test(chapter-15.window-keys
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CMAKE_CURRENT_SOURCE_DIR}/desktops/window_keys.sh
                    ${CH15_RUN} ${CH15_SIZE}
            EXPECT_STDOUT "lights moved: sun at 2[0-6][0-9]\\.[0-9] degrees, point light at \\(0\\.00, [3-9]\\.[0-9]+, [0-9]\\.[0-9]+\\)"
            QUIET_STDERR)
    else()
        message(WARNING "xdotool not found: chapter-15.window-keys is not registered (apt-get install xdotool)")
    endif()
endif()

chapter_test(chapter-15.bad-view COMMAND ${CH15} --headless --view specular
    EXPECT_EXIT 2 EXPECT_STDERR "--view must be one of final\\|position\\|albedo\\|normal\\|pbr\\|depth" ONE_LINE_STDERR)

standalone_build_test(15 --width 320 --height 180)
