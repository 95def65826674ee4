# Shaders compiled at run time and reloaded while a chapter runs (docs/live-shaders.md):
# chapters/runtime_shaders.sh checks the start (a newer source compiled and used, a compile error's
# file:line and exit code 2, a copied bin/ without sources), chapters/live_reload.sh edits a copy of the
# shaders under a running chapter (--shader-dir), headless and in a window, with --validation.
if(NOT VKBOOK_HAVE_RUNTIME_SHADERS)
    message(WARNING "no runtime shader compilation in this build: the live-reload tests are not registered")
    return()
endif()
set(SHADER_SOURCES ${PROJECT_SOURCE_DIR}/shaders)
set(SMALL --width 320 --height 180)

# At start-up.
chapter_test(shaders.chapter-06.newer-source-compiled
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/chapters/runtime_shaders.sh newer ${SHADER_SOURCES} $<TARGET_FILE:image_compare>
            $<TARGET_FILE:chapter-06> ${SMALL}
    EXPECT_STDOUT "runtime_shaders: newer: ok")
set_property(TEST shaders.chapter-06.newer-source-compiled APPEND PROPERTY ENVIRONMENT
             FILE=chapter-06/triangle.frag "PIXELS=--pixel-linear 160 110 1 0 1")
foreach(case "chapter-06;chapter-06/triangle.frag" "chapter-15;chapter-15/scene.frag"
             "chapter-15-lab;chapter-15/scene_surface.glsl")
    list(GET case 0 program)
    list(GET case 1 file)
    chapter_test(shaders.${program}.compile-error
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/chapters/runtime_shaders.sh error ${SHADER_SOURCES} $<TARGET_FILE:image_compare>
                $<TARGET_FILE:${program}> ${SMALL}
        EXPECT_STDOUT "error: .*${file}:[0-9]+: error: .*runtime_shaders: error: ok")
    set_property(TEST shaders.${program}.compile-error APPEND PROPERTY ENVIRONMENT FILE=${file})
endforeach()
foreach(case "chapter-06;chapter-06/triangle.frag" "chapter-10;chapter-10/lighting.frag"
             "chapter-14;chapter-14/light.frag" "chapter-15;chapter-15/light.frag"
             "chapter-15-lab;chapter-15-lab/light.frag")
    list(GET case 0 program)
    list(GET case 1 file)
    chapter_test(shaders.${program}.interface-change-refused
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/chapters/runtime_shaders.sh interface ${SHADER_SOURCES}
                $<TARGET_FILE:image_compare> $<TARGET_FILE:${program}> ${SMALL}
        EXPECT_STDOUT "interface changed: .*runtime_shaders: interface: ok")
    set_property(TEST shaders.${program}.interface-change-refused APPEND PROPERTY ENVIRONMENT FILE=${file})
endforeach()
# At start-up, a specialization constant moved to another constant_id: the pipeline's map entry
# would be ignored (Vulkan), so the chapter stops naming the shader and the ID it still sets.
foreach(case "chapter-10;chapter-10/geometry.frag;s/constant_id = 1)/constant_id = 6)/;chapter-10/geometry.frag: the pipeline sets specialization constant 1,"
             "chapter-14;chapter-14/scene.frag;s/constant_id = 0)/constant_id = 5)/;chapter-14/scene.frag: the pipeline sets specialization constant 0,"
             "chapter-15;chapter-15/scene_surface.glsl;s/constant_id = 2)/constant_id = 7)/;chapter-15/scene.frag: the pipeline sets specialization constant 2,"
             "chapter-15;chapter-15/light_loop.glsl;s/constant_id = 4)/constant_id = 9)/;chapter-15/light.frag: the pipeline sets specialization constant 4,"
             "chapter-15-lab;chapter-15/light_loop.glsl;s/constant_id = 3)/constant_id = 8)/;chapter-15-lab/light.frag: the pipeline sets specialization constant 3,")
    list(GET case 0 program)
    list(GET case 1 file)
    list(GET case 2 edit)
    list(GET case 3 expect)
    get_filename_component(stem ${file} NAME_WE)
    chapter_test(shaders.${program}.constant-id-moved-${stem}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/chapters/runtime_shaders.sh constant-id ${SHADER_SOURCES}
                $<TARGET_FILE:image_compare> $<TARGET_FILE:${program}> ${SMALL}
        EXPECT_STDOUT "${expect} which the shader does not declare.*runtime_shaders: constant-id: ok")
    set_property(TEST shaders.${program}.constant-id-moved-${stem} APPEND PROPERTY ENVIRONMENT
                 FILE=${file} SED=${edit} EXPECT=${expect})
endforeach()

# At start-up, an included file newer than the build's SPIR-V: exactly the shaders that include it
# are compiled (chapter-06's own compiler and common's).
foreach(case "chapter-06;include/srgb.glsl;chapter-06/triangle.frag"
             "chapter-15;chapter-15/light_inputs.glsl;chapter-15/light.frag")
    list(GET case 0 program)
    list(GET case 1 include)
    list(GET case 2 compiled)
    chapter_test(shaders.${program}.newer-include-compiled
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/chapters/runtime_shaders.sh newer-include ${SHADER_SOURCES}
                $<TARGET_FILE:image_compare> $<TARGET_FILE:${program}> ${SMALL}
        EXPECT_STDOUT "shaders: compiled ${compiled} ")
    set_property(TEST shaders.${program}.newer-include-compiled APPEND PROPERTY ENVIRONMENT
                 INCLUDE=${include} COMPILED=${compiled})
endforeach()
# --check-output fails on a bad light output: every pixel negative, then NaN.
foreach(case "chapter-15;chapter-15/light.frag" "chapter-15-lab;chapter-15-lab/light.frag")
    list(GET case 0 program)
    list(GET case 1 file)
    foreach(value "negative;-1.0;0 NaN, 0 infinite, [1-9][0-9]* negative" "nan;uintBitsToFloat(0x7fc00000u);[1-9][0-9]* NaN, 0 infinite")
        list(GET value 0 kind)
        list(GET value 1 glsl)
        list(GET value 2 expected)
        chapter_test(shaders.${program}.check-output-${kind}
            COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/chapters/runtime_shaders.sh bad-output ${SHADER_SOURCES}
                    $<TARGET_FILE:image_compare> $<TARGET_FILE:${program}> ${SMALL}
            EXPECT_STDOUT "light output 320x180: ${expected}")
        set_property(TEST shaders.${program}.check-output-${kind} APPEND PROPERTY ENVIRONMENT FILE=${file} VALUE=${glsl})
    endforeach()
endforeach()
chapter_test(shaders.chapter-06.copied-without-sources
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/chapters/runtime_shaders.sh no-sources ${SHADER_SOURCES}
            $<TARGET_FILE:image_compare> $<TARGET_FILE:chapter-06> ${SMALL}
    EXPECT_STDOUT "runtime_shaders: no-sources: ok")
foreach(number 06 10 14 15)
    chapter_test(shaders.chapter-${number}.help-says-runtime COMMAND $<TARGET_FILE:chapter-${number}> --help
        EXPECT_STDOUT "shaders: compiled at run time from .*shaders when newer than the build's SPIR-V, reloaded when edited")
endforeach()
chapter_test(shaders.shader-dir-missing COMMAND $<TARGET_FILE:chapter-15> --headless --shader-dir /nonexistent
    EXPECT_EXIT 2 ONE_LINE_STDERR EXPECT_STDERR "--shader-dir '/nonexistent' is not a directory")

# live_test(NAME SCENARIO FILE[=NAME] COMMAND chapter options...)
function(live_test name scenario shader)
    cmake_parse_arguments(L "WINDOW" "" "COMMAND" ${ARGN})
    set(command ${CMAKE_CURRENT_SOURCE_DIR}/chapters/live_reload.sh ${scenario} ${SHADER_SOURCES} ${shader}
                $<TARGET_FILE:image_compare> ${L_COMMAND} --validation ${SMALL})
    if(L_WINDOW)
        if(NOT XVFB_RUN)
            return()
        endif()
        set(command ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${command})
    else()
        list(APPEND command --headless)
    endif()
    chapter_test(${name} COMMAND ${command} EXPECT_STDOUT "live_reload: ${scenario}: ok")
    set_tests_properties(${name} PROPERTIES TIMEOUT 300)
endfunction()

live_test(live-reload.chapter-06.edit edit chapter-06/triangle.frag COMMAND $<TARGET_FILE:chapter-06>)
live_test(live-reload.chapter-10.edit edit chapter-10/lighting.frag COMMAND $<TARGET_FILE:chapter-10>)
live_test(live-reload.chapter-14.edit edit chapter-14/light.frag COMMAND $<TARGET_FILE:chapter-14>)
live_test(live-reload.chapter-15.edit edit chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15>)
live_test(live-reload.chapter-15-lab.edit edit chapter-15-lab/light.frag
    COMMAND $<TARGET_FILE:chapter-15-lab>)
live_test(live-reload.chapter-15-lab.post-edit edit common/post.frag COMMAND $<TARGET_FILE:chapter-15-lab>
    --light-culling tiled --light-pass compute --gui)
live_test(live-reload.chapter-06.broken broken chapter-06/triangle.frag COMMAND $<TARGET_FILE:chapter-06>)
live_test(live-reload.chapter-15.broken broken chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15>)
live_test(live-reload.chapter-15.fix fix chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15>)
live_test(live-reload.chapter-15.interface interface chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15>)
# Every rule of the interface check (tests/chapters/live_reload_rules.py): refused, the image unchanged.
foreach(rule block-grown member-moved image-type array-size push-grown output-moved capability readonly-lost
             aliased-binding)
    live_test(live-reload.chapter-15.rule-${rule} rule chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15>)
    set_property(TEST live-reload.chapter-15.rule-${rule} APPEND PROPERTY ENVIRONMENT RULE=${rule})
endforeach()
foreach(rule accept-unused-member accept-fewer-resources accept-renamed accept-new-constant accept-capabilities)
    live_test(live-reload.chapter-15.${rule} accept chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15>)
    set_property(TEST live-reload.chapter-15.${rule} APPEND PROPERTY ENVIRONMENT RULE=${rule})
endforeach()
foreach(rule input-components new-output new-varying)
    live_test(live-reload.chapter-15.rule-${rule} rule chapter-15/scene.frag COMMAND $<TARGET_FILE:chapter-15>)
    set_property(TEST live-reload.chapter-15.rule-${rule} APPEND PROPERTY ENVIRONMENT RULE=${rule})
endforeach()
live_test(live-reload.chapter-15.rule-constant-type rule chapter-15/scene.frag COMMAND $<TARGET_FILE:chapter-15>)
set_property(TEST live-reload.chapter-15.rule-constant-type APPEND PROPERTY ENVIRONMENT RULE=constant-type)
live_test(live-reload.chapter-15-lab.rule-local-size rule chapter-15-lab/light.comp
    COMMAND $<TARGET_FILE:chapter-15-lab> --light-pass compute)
set_property(TEST live-reload.chapter-15-lab.rule-local-size APPEND PROPERTY ENVIRONMENT RULE=local-size)
live_test(live-reload.chapter-15.gui-broken broken chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15> --gui)
# A pipeline that cannot be made on reload (the fault-injection layer, tests/reliability/fault.cmake): the old
# ones keep drawing, the same edit saved again is picked up.
foreach(case "chapter-06;chapter-06/triangle.frag;chapter-06/triangle.vert"
             "chapter-10;chapter-10/lighting.frag;chapter-10/geometry.frag"
             "chapter-14;chapter-14/light.frag;chapter-14/scene.frag"
             "chapter-15;chapter-15/light.frag;chapter-15/scene.frag"
             "chapter-15-lab;chapter-15-lab/light.frag;common/post.frag")
    list(GET case 0 program)
    list(GET case 1 file)
    list(GET case 2 other)
    live_test(live-reload.${program}.pipeline-fails fault ${file} COMMAND $<TARGET_FILE:${program}> --device llvmpipe)
    set_property(TEST live-reload.${program}.pipeline-fails APPEND PROPERTY ENVIRONMENT
                 XDG_DATA_HOME=${FAULT_LAYER_DIR} VKBOOK_FAULT_LAYER=1 RETOUCH=${other})
endforeach()
# A reload makes only the pipelines whose shaders changed: chapter-15's light shader, one; the post
# shader, two (with and without FXAA); none of the scene pass's; the scene shader, one per material
# class of the default scene, four (each with its constants, checked against the new code).
foreach(case "light;chapter-15/light.frag;1" "post;common/post.frag;2" "scene;chapter-15/scene.frag;4")
    list(GET case 0 kind)
    list(GET case 1 file)
    list(GET case 2 count)
    live_test(live-reload.chapter-15.pipelines-${kind} edit ${file} COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe)
    set_property(TEST live-reload.chapter-15.pipelines-${kind} APPEND PROPERTY ENVIRONMENT
                 XDG_DATA_HOME=${FAULT_LAYER_DIR} VKBOOK_FAULT_LAYER=1 EXPECT_PIPELINES=${count})
endforeach()
set_property(TEST live-reload.chapter-15.pipelines-scene APPEND PROPERTY ENVIRONMENT
             "GOOD=    outAlbedo = vec4(1.0, 0.0, 1.0, 1.0)\;  // live_reload.sh")
# The second of the post pass's two pipelines fails: the first, already made, is destroyed.
live_test(live-reload.chapter-15.pipeline-fails-second fault common/post.frag
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe)
set_property(TEST live-reload.chapter-15.pipeline-fails-second APPEND PROPERTY ENVIRONMENT
             XDG_DATA_HOME=${FAULT_LAYER_DIR} VKBOOK_FAULT_LAYER=1 FAULT_OFFSET=2)
# Every way an editor saves, and an edit saved during a (slow) compile: nothing lost, the run goes on.
foreach(style in-place truncate rename-new rename-old delete)
    live_test(live-reload.chapter-15.save-${style} save-${style} chapter-15/light.frag
        COMMAND $<TARGET_FILE:chapter-15>)
endforeach()
live_test(live-reload.chapter-06.save-rename-old save-rename-old chapter-06/triangle.frag
    COMMAND $<TARGET_FILE:chapter-06>)
live_test(live-reload.chapter-15.during-compile during-compile chapter-15/light.frag
    COMMAND $<TARGET_FILE:chapter-15>)
set_property(TEST live-reload.chapter-15.during-compile APPEND PROPERTY ENVIRONMENT
             VKBOOK_TEST_COMPILE_DELAY_MS=1500)
live_test(live-reload.chapter-06.leak leak chapter-06/triangle.frag COMMAND $<TARGET_FILE:chapter-06>)
live_test(live-reload.chapter-15.leak leak chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15>)
# The same 50 reloads with the object-names layer: every pipeline a reload makes is named.
live_test(live-reload.chapter-15.names leak chapter-15/light.frag COMMAND $<TARGET_FILE:chapter-15>)
set_property(TEST live-reload.chapter-15.names APPEND PROPERTY ENVIRONMENT XDG_DATA_HOME=${NAMES_LAYER_DIR}
             VKBOOK_NAMES_LAYER=1 VKBOOK_NAMES_REPORT=${CMAKE_CURRENT_BINARY_DIR}/out/names-live-reload.txt
             CHECK_MEMORY=0)
live_test(live-reload.chapter-06.window-fix fix chapter-06/triangle.frag WINDOW COMMAND $<TARGET_FILE:chapter-06>)
live_test(live-reload.chapter-15.window-edit edit chapter-15/light.frag WINDOW COMMAND $<TARGET_FILE:chapter-15>)
live_test(live-reload.chapter-15.window-broken broken chapter-15/light.frag WINDOW COMMAND $<TARGET_FILE:chapter-15>)
# chapter-16: its light shader edited; its shadow shader edited while the camera stands still --
# the shadow pass's two pipelines made again, and every cascade drawn again with them (a still
# camera draws none otherwise): the moments written as 0, the sun's light gone from the image.
live_test(live-reload.chapter-16.edit edit chapter-16/light.frag COMMAND $<TARGET_FILE:chapter-16>)
live_test(live-reload.chapter-16.shadow-edit edit chapter-16/shadow.frag COMMAND $<TARGET_FILE:chapter-16>
    --device llvmpipe)
set_property(TEST live-reload.chapter-16.shadow-edit APPEND PROPERTY ENVIRONMENT
             XDG_DATA_HOME=${FAULT_LAYER_DIR} VKBOOK_FAULT_LAYER=1 EXPECT_PIPELINES=2
             "GOOD=    outMoments = vec2(0.0)\;  // live_reload.sh")
# chapter-17: its skinning shader edited while the clock stands still (--animation-time): the
# compute pipeline made again, and the figures skinned again with it (a fixed pose is skinned only
# once otherwise): lifted half a metre. Two pipelines: the skinning pass's, and the light pass's made
# again to read the moving casters' map, as the figures' new shapes are moving casters to the shadow
# cache.
live_test(live-reload.chapter-17.skin-edit edit chapter-17/skin.comp COMMAND $<TARGET_FILE:chapter-17>
    --device llvmpipe --animation-time 0.4)
set_property(TEST live-reload.chapter-17.skin-edit APPEND PROPERTY ENVIRONMENT
             XDG_DATA_HOME=${FAULT_LAYER_DIR} VKBOOK_FAULT_LAYER=1 EXPECT_PIPELINES=2
             "GOOD=    skinned[index].position.y += 0.5\;  // live_reload.sh")
# chapter-18: its pulled scene vertex shader edited (every normal made to point up): the scene
# pipelines, made without vertex input, made again from it; the image is the one the edited shader
# gives from the start.
live_test(live-reload.chapter-18.pulled-vertex-edit edit chapter-18/scene.vert COMMAND $<TARGET_FILE:chapter-18>
    --device llvmpipe --animation-time 0.4)
set_property(TEST live-reload.chapter-18.pulled-vertex-edit APPEND PROPERTY ENVIRONMENT
             "GOOD=    outNormal = vec3(0.0, 1.0, 0.0)\;  // live_reload.sh")
# chapter-19: its indirect scene vertex shader edited: the pipelines made again, the indirect draws
# drawing with them.
live_test(live-reload.chapter-19.indirect-vertex-edit edit chapter-19/scene.vert COMMAND $<TARGET_FILE:chapter-19>
    --device llvmpipe --animation-time 0.4)
set_property(TEST live-reload.chapter-19.indirect-vertex-edit APPEND PROPERTY ENVIRONMENT
             "GOOD=    outNormal = vec3(0.0, 1.0, 0.0)\;  // live_reload.sh")
# chapter-20: the same edit, the pipelines made again at the threads' meeting while the render
# thread waits; and again in the ThreadSanitizer build (tests/chapters/chapter-20.cmake), 0 reports.
live_test(live-reload.chapter-20.indirect-vertex-edit edit chapter-19/scene.vert=chapter-20/scene.vert
    COMMAND $<TARGET_FILE:chapter-20> --device llvmpipe --animation-time 0.4)
set_property(TEST live-reload.chapter-20.indirect-vertex-edit APPEND PROPERTY ENVIRONMENT
             "GOOD=    outNormal = vec3(0.0, 1.0, 0.0)\;  // live_reload.sh")
if(TARGET chapter-20 AND TSAN_CH20)
    live_test(tsan.chapter-20.live-reload edit chapter-19/scene.vert=chapter-20/scene.vert
        COMMAND ${TSAN_CH20} --device llvmpipe --animation-time 0.4)
    set_tests_properties(tsan.chapter-20.live-reload PROPERTIES FIXTURES_REQUIRED tsan-chapter-20)
    set_property(TEST tsan.chapter-20.live-reload APPEND PROPERTY ENVIRONMENT ${tsan_env}
                 "GOOD=    outNormal = vec3(0.0, 1.0, 0.0)\;  // live_reload.sh")
endif()
