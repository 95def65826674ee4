# Fault tests: out of GPU memory and device loss, injected by our Vulkan layer
# (reliability/fault_layer/fault_layer.cpp), since lavapipe never fails that way. Each chapter must stop with
# one line on stderr naming the failed call and what happened, exit code 1, promptly (no wait on a
# fence that will never signal) and without a crash or a validation message.

# The layer: a shared library and its manifest, generated next to it. It is an implicit layer
# (found through XDG_DATA_HOME/vulkan/implicit_layer.d) that is only enabled when
# VKBOOK_FAULT_LAYER=1; implicit layers sit above the application's, so validation never sees a
# faulted call. (VK_ADD_LAYER_PATH + VK_INSTANCE_LAYERS would load it too, but the loader reports
# that as a warning through the debug messenger, and --validation counts every warning.)
set(FAULT_LAYER_DIR ${CMAKE_CURRENT_BINARY_DIR}/fault_layer)
add_library(VkLayer_vkbook_fault_injection MODULE reliability/fault_layer/fault_layer.cpp)
target_link_libraries(VkLayer_vkbook_fault_injection PRIVATE Vulkan::Headers)
vkbook_warnings(VkLayer_vkbook_fault_injection)
set_target_properties(VkLayer_vkbook_fault_injection PROPERTIES
    LIBRARY_OUTPUT_DIRECTORY ${FAULT_LAYER_DIR} CXX_VISIBILITY_PRESET hidden)
file(GENERATE OUTPUT ${FAULT_LAYER_DIR}/vulkan/implicit_layer.d/VkLayer_vkbook_fault_injection.json CONTENT [[{
    "file_format_version": "1.1.2",
    "layer": {
        "name": "VK_LAYER_VKBOOK_fault_injection",
        "type": "GLOBAL",
        "library_path": "$<TARGET_FILE:VkLayer_vkbook_fault_injection>",
        "api_version": "1.3.0",
        "implementation_version": "1",
        "description": "vulkan-book-cpp tests: fails one chosen call (VKBOOK_FAULT=<call>:<n>)",
        "instance_extensions": [{"name": "VK_EXT_surface_maintenance1", "spec_version": "1"}],
        "device_extensions": [{"name": "VK_EXT_swapchain_maintenance1", "spec_version": "1", "entrypoints": []}],
        "enable_environment": {"VKBOOK_FAULT_LAYER": "1"},
        "disable_environment": {"VKBOOK_FAULT_LAYER_DISABLE": "1"}
    }
}
]])
set(FAULT_ENV ${TEST_ENV} XDG_DATA_HOME=${FAULT_LAYER_DIR} VKBOOK_FAULT_LAYER=1)

# fault_test(NAME FAULT call:n COMMAND ... EXPECT_STDERR re [EXPECT_EXIT n] [...chapter_test options])
# chapter_test with the layer loaded and VKBOOK_FAULT=call:n; by default exit code 1 and exactly
# one line on stderr.
function(fault_test name)
    cmake_parse_arguments(F "" "FAULT;EXPECT_EXIT" "" ${ARGN})
    if(NOT DEFINED F_EXPECT_EXIT)
        set(F_EXPECT_EXIT 1)
    endif()
    if(F_EXPECT_EXIT EQUAL 1)
        list(APPEND F_UNPARSED_ARGUMENTS ONE_LINE_STDERR)
    endif()
    chapter_test(${name} EXPECT_EXIT ${F_EXPECT_EXIT} ${F_UNPARSED_ARGUMENTS})
    set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_FAULT=${F_FAULT}" TIMEOUT 120)
endfunction()

# The layer is loaded and counts calls (VKBOOK_FAULT_TRACE=1 is also how to choose n below: run a
# chapter with it and count), injects nothing when n is beyond the calls made (a clean run, exit
# 0, validation quiet), and refuses a malformed VKBOOK_FAULT. Without these, every test below
# could pass for the wrong reason.
fault_test(fault.layer-counts-calls FAULT vkAllocateMemory:1000000 EXPECT_EXIT 0
    COMMAND $<TARGET_FILE:chapter-06> --device llvmpipe --validation --headless --width 64 --height 36
    EXPECT_STDERR "VK_LAYER_VKBOOK_fault_injection: vkAllocateMemory #6\n.*VK_LAYER_VKBOOK_fault_injection: vkQueueSubmit #1\n")
set_property(TEST fault.layer-counts-calls APPEND PROPERTY ENVIRONMENT VKBOOK_FAULT_TRACE=1)
fault_test(fault.layer-n-beyond-the-calls-made FAULT vkAllocateMemory:1000000 EXPECT_EXIT 0
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 320 --height 180
            --frames 4 --resize 200x100
    QUIET_STDERR)
fault_test(fault.layer-bad-spec FAULT vkAllocateMemory EXPECT_EXIT 0
    COMMAND $<TARGET_FILE:chapter-06> --device llvmpipe --validation --headless --width 64 --height 36
    EXPECT_STDERR "^VK_LAYER_VKBOOK_fault_injection: VKBOOK_FAULT='vkAllocateMemory' is not <call>:<n>\n$")

# The messages: the plain-words cause, then the call that failed (as VK_CHECK names it).
set(OOM "out of GPU memory: vkAllocateMemory\\(device.handle, &allocInfo, nullptr, &")
set(OOM_NAMED "out of GPU memory: vkAllocateMemory for \"")  # common's allocations name their resource
set(HOST_OOM "out of memory: ")
set(LOST "the GPU was lost \\(driver crash, GPU reset or device removed\\): ")
set(LOST_END "failed with VK_ERROR_DEVICE_LOST \\([a-z_]+\\.cpp:[0-9]+\\)\n$")
set(FRAME_WAIT "vkWaitForFences\\(c\\.device\\.handle, 1, &sync.inFlight, VK_TRUE, UINT64_MAX\\) ${LOST_END}")

# Without --validation nothing lies between the layer and the loader (or Mesa's device-select
# layer), whose lookups answer from the instance's dispatch table, by then the layer's own
# functions: the layer looks up what it passes down when the instance is made, never calls itself.
fault_test(fault.layer-without-validation FAULT vkAllocateMemory:1000000 EXPECT_EXIT 0
    COMMAND $<TARGET_FILE:chapter-16> --device llvmpipe --headless --width 320 --height 180 --frames 2
    QUIET_STDERR)
fault_test(fault.layer-without-validation-oom FAULT vkAllocateMemory:1
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --headless --width 320 --height 180
    EXPECT_STDERR "^chapter-15: error: ${OOM_NAMED}offscreen target 0\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")

# Headless, with validation (a faulted call never reaches the validation layer, which sits below
# ours, and after a failure a chapter makes no more Vulkan calls: it stays quiet).
# Per chapter: n of the first G-buffer allocation + 1 (mid G-buffer), of an allocation during the
# --resize of a 4-frame run (after the first three frames), of frame 3's draw submission, and of
# frame 3's wait for frame 1's fence (a wait on real work: a lost device must not hang it).
# Found with VKBOOK_FAULT_TRACE=1 (and a debugger's backtrace on vkAllocateMemory); when a
# chapter's allocations change, these move -- the message checks keep the tests honest.
#        chapter gbuffer resize submit            wait
foreach(spec "06;3;8;vkQueueSubmit:9;4"
             "10;40;47;vkQueueSubmit:12;4"
             "14;40;48;vkQueueSubmit2:3;5"
             "15;47;62;vkQueueSubmit2:3;5"
             "16;47;66;vkQueueSubmit2:3;5"
             "17;64;83;vkQueueSubmit2:3;5"
             "18;64;83;vkQueueSubmit2:3;5"
             "19;64;90;vkQueueSubmit2:3;5"
             "20;64;90;vkQueueSubmit2:3;5")
    list(GET spec 0 number)
    list(GET spec 1 gbuffer)
    list(GET spec 2 resize)
    list(GET spec 3 submit)
    list(GET spec 4 wait)
    string(REGEX REPLACE ":.*" "" submitCall "${submit}")
    # Chapter 14 and the frame loop of 15 on call vkQueueSubmit2 through common::vk13 (the core command, or the
    # VK_KHR_synchronization2 one on a Vulkan 1.2 device); the message quotes the call as written.
    string(REPLACE "vkQueueSubmit2" "common::vk13\\.QueueSubmit2" submitText "${submitCall}")
    set(run $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --headless --width 320 --height 180)
    set(name fault.chapter-${number})
    fault_test(${name}.oom-first-allocation FAULT vkAllocateMemory:1 COMMAND ${run}
        EXPECT_STDERR "^chapter-${number}: error: ${OOM_NAMED}offscreen target 0\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")
    if(number STREQUAL "06")  # no G-buffer: the vertex buffer
        fault_test(${name}.oom-vertex-buffer FAULT vkAllocateMemory:${gbuffer} COMMAND ${run}
            EXPECT_STDERR "^chapter-06: error: ${OOM}buffer.memory\\) failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(buffer.cpp:[0-9]+\\)\n$")
    else()
        fault_test(${name}.oom-gbuffer FAULT vkAllocateMemory:${gbuffer} COMMAND ${run}
            EXPECT_STDERR "^chapter-${number}: error: ${OOM_NAMED}G-buffer [a-z]+\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")
    endif()
    fault_test(${name}.oom-during-resize FAULT vkAllocateMemory:${resize} COMMAND ${run} --frames 4 --resize 200x100
        EXPECT_STDERR "^chapter-${number}: error: ${OOM_NAMED}(offscreen target [0-9]+|G-buffer [a-z]+)\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")
    fault_test(${name}.lost-at-first-submit FAULT vkQueueSubmit:1 COMMAND ${run}
        EXPECT_STDERR "^chapter-${number}: error: ${LOST}vkQueueSubmit\\(device.queue, 1, &submit, done\\) ${LOST_END}")
    fault_test(${name}.lost-at-frame-3-submit FAULT ${submit} COMMAND ${run} --frames 5
        EXPECT_STDERR "^chapter-${number}: error: ${LOST}${submitText}\\(c\\.device\\.queue, 1, &[a-zA-Z]+, sync.inFlight\\) ${LOST_END}")
    fault_test(${name}.lost-at-frame-3-wait FAULT vkWaitForFences:${wait} COMMAND ${run} --frames 5
        EXPECT_STDERR "^chapter-${number}: error: ${LOST}${FRAME_WAIT}")
endforeach()
# chapter-16's own allocations: the shadow map's moments (its layered image), after the G-buffer.
fault_test(fault.chapter-16.oom-shadow-map FAULT vkAllocateMemory:56
    COMMAND $<TARGET_FILE:chapter-16> --device llvmpipe --validation --headless --width 320 --height 180
    EXPECT_STDERR "^chapter-16: error: ${OOM_NAMED}shadow moments\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")
fault_test(fault.chapter-06.host-oom-create-buffer FAULT vkCreateBuffer:1
    COMMAND $<TARGET_FILE:chapter-06> --device llvmpipe --validation --headless
    EXPECT_STDERR "^chapter-06: error: ${HOST_OOM}vkCreateBuffer\\(.*\\) failed with VK_ERROR_OUT_OF_HOST_MEMORY \\(buffer.cpp:[0-9]+\\)\n$")
fault_test(fault.chapter-15.host-oom-create-image FAULT vkCreateImage:1
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless
    EXPECT_STDERR "^chapter-15: error: ${HOST_OOM}vkCreateImage\\(.*\\) failed with VK_ERROR_OUT_OF_HOST_MEMORY \\(image.cpp:[0-9]+\\)\n$")
# --benchmark reads timestamps with vkGetQueryPoolResults, which reports a lost device too.
fault_test(fault.chapter-15.benchmark-lost-at-query-results FAULT vkGetQueryPoolResults:2
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 320 --height 180
            --benchmark --warmup 1 --frames 4
    EXPECT_STDERR "^chapter-15: error: ${LOST}vkGetQueryPoolResults ${LOST_END}")
# chapter-17's posed vertices (chapter-17/skinning_pass.cpp): a buffer per animated model and mesh,
# made after the scene's meshes; the walker (the scene's model 18) is the first.
fault_test(fault.chapter-17.oom-posed-vertices FAULT vkAllocateMemory:58
    COMMAND $<TARGET_FILE:chapter-17> --device llvmpipe --validation --headless --width 320 --height 180
    EXPECT_STDERR "^chapter-17: error: ${OOM_NAMED}posed vertices: model 18, mesh 0\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")
# chapter-18's posed vertices: the same buffers, their memory allocated with the DEVICE_ADDRESS flag.
fault_test(fault.chapter-18.oom-posed-vertices FAULT vkAllocateMemory:58
    COMMAND $<TARGET_FILE:chapter-18> --device llvmpipe --validation --headless --width 320 --height 180
    EXPECT_STDERR "^chapter-18: error: ${OOM_NAMED}posed vertices: model 18, mesh 0\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")
# chapter-19's GlobalBuffers, made by the first frame's update (matrices, instances, draw commands),
# after the scene's index buffer: the draw commands.
fault_test(fault.chapter-19.oom-draw-commands FAULT vkAllocateMemory:84
    COMMAND $<TARGET_FILE:chapter-19> --device llvmpipe --validation --headless --width 320 --height 180
    EXPECT_STDERR "^chapter-19: error: ${OOM_NAMED}frame 0 draw commands\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")
# chapter-20: the same on its main thread -- frame 1's update, while the render thread draws frame 0:
# the moving casters' map (made once the render thread has been waited for) and frame 1's instances.
# Its render thread's failures are the loop's submit above (lost-at-frame-3-submit), handed to the
# main thread and ended there with one line.
foreach(spec "85;shadow moments: moving casters" "87;frame 1 instances")
    list(GET spec 0 n)
    list(GET spec 1 what)
    string(REGEX REPLACE "[^a-z0-9]+" "-" case "${what}")
    fault_test(fault.chapter-20.oom-${case} FAULT vkAllocateMemory:${n}
        COMMAND $<TARGET_FILE:chapter-20> --device llvmpipe --validation --headless --width 320 --height 180 --frames 3
        EXPECT_STDERR "^chapter-20: error: ${OOM_NAMED}${what}\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")
endforeach()
# The moving casters' map (chapter-16/shadow_pass.cpp), made mid-run the first time a caster moves
# (--light-motion walk: the point light's marker): one line naming it, exit code 1.
fault_test(fault.chapter-16.oom-moving-casters FAULT vkAllocateMemory:65
    COMMAND $<TARGET_FILE:chapter-16> --device llvmpipe --validation --headless --width 320 --height 180
            --frames 3 --light-motion walk
    EXPECT_STDERR "^chapter-16: error: ${OOM_NAMED}shadow moments: moving casters\" failed with VK_ERROR_OUT_OF_DEVICE_MEMORY \\(memory.cpp:[0-9]+\\)\n$")

# In a window (Xvfb): the device lost at frame 3's vkAcquireNextImageKHR and at its
# vkQueuePresentKHR, and out of memory while the swapchain's images are rebuilt after a resize.
if(XVFB_RUN)
    foreach(number 06 15)
        set(window ${XVFB_RUN} -a $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation
                   --width 320 --height 180 --frames 5)
        set(name fault.chapter-${number}.window)
        fault_test(${name}-lost-at-acquire FAULT vkAcquireNextImageKHR:3 COMMAND ${window}
            EXPECT_STDERR "^chapter-${number}: error: ${LOST}vkAcquireNextImageKHR ${LOST_END}")
        fault_test(${name}-lost-at-present FAULT vkQueuePresentKHR:3 COMMAND ${window}
            EXPECT_STDERR "^chapter-${number}: error: ${LOST}vkQueuePresentKHR ${LOST_END}")
    endforeach()
endif()

# A device with less memory than the scene needs (VKBOOK_HEAP_MIB: the layer reports smaller
# device-local heaps): refused from the meshes' sizes and the images' headers before any texture
# is decoded, in one line naming the need and the heap; with enough memory, drawn.
fault_test(fault.heap-too-small FAULT vkAllocateMemory:1000000 EXPECT_EXIT 2
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 64 --height 36
    EXPECT_STDERR "^chapter-15: error: the scene needs 12 MiB of device memory \\(meshes 1 MiB, textures with their mip levels 11 MiB\\). this device's largest device-local memory heap has 8 MiB, of which a scene may use 3/4 \\(6 MiB\\)\n$")
set_property(TEST fault.heap-too-small APPEND PROPERTY ENVIRONMENT VKBOOK_HEAP_MIB=8)
fault_test(fault.heap-large-enough FAULT vkAllocateMemory:1000000 EXPECT_EXIT 0
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 64 --height 36
    EXPECT_STDOUT "chapter-15: 19 draws" QUIET_STDERR)
set_property(TEST fault.heap-large-enough APPEND PROPERTY ENVIRONMENT VKBOOK_HEAP_MIB=16)
# Checked from the headers before any texture is decoded: a header that claims 4096x4096 over a
# body of 4x4 pixels is refused by the budget (85 MiB with its mip levels), not by the decoder.
fault_test(fault.heap-before-decoding FAULT vkAllocateMemory:1000000 EXPECT_EXIT 2
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 64 --height 36
            --model ${HOSTILE}/tex_header_lies.obj
    EXPECT_STDERR "^chapter-15: error: the scene needs [0-9]+ MiB of device memory \\(meshes 1 MiB, textures with their mip levels [0-9]+ MiB\\). this device's largest device-local memory heap has 64 MiB")
set_property(TEST fault.heap-before-decoding APPEND PROPERTY ENVIRONMENT VKBOOK_HEAP_MIB=64)
set_property(TEST fault.heap-before-decoding APPEND PROPERTY FIXTURES_REQUIRED hostile-inputs)
# A device that allows few memory allocations (VKBOOK_MAX_ALLOCATIONS: the layer reports the limit
# and fails the allocation past it, as a driver does): a scene that needs more than the limit less
# the renderer's 64 is refused before it allocates, in one line; at exactly the scene's 22 plus
# those 64, every chapter runs without one failed allocation (the reserve is enough).
fault_test(fault.allocations-too-few FAULT vkAllocateMemory:1000000 EXPECT_EXIT 2
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless --width 64 --height 36
    EXPECT_STDERR "^chapter-15: error: .*the scene needs [0-9]+ memory allocations \\(one per mesh buffer and texture\\). this device allows 70, of which the renderer keeps 64\n$")
set_property(TEST fault.allocations-too-few APPEND PROPERTY ENVIRONMENT VKBOOK_MAX_ALLOCATIONS=70)
# chapter-17's posed buffers, influences and palettes counted as well, before any is made: its
# default scene needs 8 beside the scene's 26 and the renderer's 64 -- refused at 97, run at 98.
fault_test(fault.allocations-too-few-chapter-17 FAULT vkAllocateMemory:1000000 EXPECT_EXIT 2
    COMMAND $<TARGET_FILE:chapter-17> --device llvmpipe --validation --headless --width 64 --height 36
    EXPECT_STDERR "^chapter-17: error: the scene's animated models need 8 more memory allocations \\(a buffer per instance and skinned mesh\\) beside the scene's 26. this device allows 97, of which the renderer keeps 64\n$")
set_property(TEST fault.allocations-too-few-chapter-17 APPEND PROPERTY ENVIRONMENT VKBOOK_MAX_ALLOCATIONS=97)
fault_test(fault.allocations-at-the-reserve-17 FAULT vkAllocateMemory:1000000 EXPECT_EXIT 0
    COMMAND $<TARGET_FILE:chapter-17> --device llvmpipe --validation --headless --width 64 --height 36 --gui --frames 3
    EXPECT_STDOUT "chapter-17: 21 draws" QUIET_STDERR)
set_property(TEST fault.allocations-at-the-reserve-17 APPEND PROPERTY ENVIRONMENT VKBOOK_MAX_ALLOCATIONS=98)
foreach(chapter 10 14 15 15-lab)
    set(gui --gui)
    if(chapter STREQUAL "10")
        set(gui)  # chapter-10 has no overlay
    endif()
    fault_test(fault.allocations-at-the-reserve-${chapter} FAULT vkAllocateMemory:1000000 EXPECT_EXIT 0
        COMMAND $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless --width 64 --height 36
                ${gui} --frames 3
        EXPECT_STDOUT "chapter-${chapter}: 19 draws" QUIET_STDERR)
    set_property(TEST fault.allocations-at-the-reserve-${chapter} APPEND PROPERTY ENVIRONMENT VKBOOK_MAX_ALLOCATIONS=86)
endforeach()
