# The validation matrix (docs/reliability.md): every scene chapter's every --view in a window
# under Xvfb, as the headless view tests do offscreen, with --validation (core + synchronization)
# and the image compared with the headless golden image; and every chapter once headless and once
# in a window with the best-practices checks on as well.
set(ACCEPTED_BEST_PRACTICES
    # VK_EXT_debug_utils is enabled only under --validation, to receive the messages.
    UNASSIGNED-BestPractices-vkCreateInstance-specialuse-extension-debugging
    # One VkDeviceMemory per buffer or image, as the book does: at most 47 allocations per run.
    UNASSIGNED-BestPractices-vkAllocateMemory-small-allocation
    UNASSIGNED-BestPractices-vkBindMemory-small-dedicated-allocation
    # glslang marks a compute shader's local size with the WorkgroupSize built-in when it targets
    # SPIR-V 1.3 (Vulkan 1.1, as every shader here does); it is deprecated from SPIR-V 1.6 on.
    UNASSIGNED-BestPractices-SpirvDeprecated_WorkgroupSize)

if(XVFB_RUN)
    set(SCREEN -s "-screen 0 1600x1200x24")
    foreach(spec "10:final albedo depth" "14:final albedo depth" "15:final position albedo normal pbr depth"
                 "16:final cascades shadow-map")
        string(REPLACE ":" ";" spec "${spec}")
        list(GET spec 0 number)
        list(GET spec 1 views)
        string(REPLACE " " ";" views "${views}")
        foreach(view IN LISTS views)
            set(name matrix.chapter-${number}-window-${view})
            chapter_test(${name}
                COMMAND ${XVFB_RUN} -a ${SCREEN} $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation
                        --width 640 --height 360 --view ${view} --frames 3 --screenshot ${TEST_OUT}/${name}.png
                QUIET_STDERR)
            set_tests_properties(${name} PROPERTIES FIXTURES_SETUP ${name})
            add_test(NAME ${name}-image COMMAND image_compare ${TEST_OUT}/${name}.png --size 640 360
                     --golden ${GOLDEN}/chapter-${number}-${view}.png --max-diff 5 --max-fraction 0.001)
            set_tests_properties(${name}-image PROPERTIES FIXTURES_REQUIRED ${name})
        endforeach()
    endforeach()
endif()

foreach(number 06 10 14 15 16 17 18 19 20)
    set(run $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --width 320 --height 180 --frames 3)
    string(REPLACE ";" "\\;" accepted "${ACCEPTED_BEST_PRACTICES}")
    string(REPLACE ";" "\\;" headless "${run};--headless")
    add_test(NAME matrix.chapter-${number}-best-practices
             COMMAND ${CMAKE_COMMAND} -DCOMMAND=${headless} -DACCEPTED=${accepted}
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/chapters/best_practices.cmake)
    set_tests_properties(matrix.chapter-${number}-best-practices PROPERTIES ENVIRONMENT "${TEST_ENV}")
    if(XVFB_RUN)
        string(REPLACE ";" "\\;" windowed "${XVFB_RUN};-a;${run};--resize;400x240")
        add_test(NAME matrix.chapter-${number}-window-best-practices
                 COMMAND ${CMAKE_COMMAND} -DCOMMAND=${windowed} -DACCEPTED=${accepted}
                         -P ${CMAKE_CURRENT_SOURCE_DIR}/chapters/best_practices.cmake)
        set_tests_properties(matrix.chapter-${number}-window-best-practices PROPERTIES ENVIRONMENT "${TEST_ENV}")
    endif()
endforeach()
