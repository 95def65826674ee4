# Readers' desktops are not CI's: every chapter drawn into each present format a window system may
# offer (headless, --target-format; and in a window on a 30-bit X screen), the overlay at a HiDPI
# scale, the overlay's keyboard after a resize, and -- through the fault-injection layer, which can
# make the device look older or poorer (reliability/fault_layer/fault_layer.cpp) -- a device without
# D32_SFLOAT depth, a Vulkan 1.2 device with and without the extensions chapters 14 and 15 then
# need, and a Vulkan 1.1 device. Every run is under validation. docs/reliability.md lists them.
set(FORMATS B8G8R8A8_SRGB R8G8B8A8_SRGB B8G8R8A8_UNORM R8G8B8A8_UNORM A2R10G10B10_UNORM_PACK32
            A2B10G10R10_UNORM_PACK32)
set(SIZE --width 640 --height 360)

# desktop_image_test(NAME GOLDEN COMMAND ... [chapter_test options]): a run that writes
# ${TEST_OUT}/NAME.png, and NAME-image comparing it with GOLDEN within the golden tolerance.
function(desktop_image_test name golden)
    chapter_test(${name} ${ARGN})
    set_tests_properties(${name} PROPERTIES FIXTURES_SETUP ${name})
    add_test(NAME ${name}-image COMMAND image_compare ${TEST_OUT}/${name}.png
        --golden ${golden} --max-diff 5 --max-fraction 0.001)
    set_tests_properties(${name}-image PROPERTIES FIXTURES_REQUIRED ${name})
endfunction()

# Headless, each present format: the same image as the 8-bit sRGB golden (the passes that write the
# presented image encode where the format does not; screenshots read 8 and 10 bits).
foreach(format IN LISTS FORMATS)
    foreach(chapter 06 10 14 15)
        set(size ${SIZE})
        set(golden ${GOLDEN}/chapter-${chapter}-final.png)
        if(chapter STREQUAL "06")
            set(size)  # its golden image is 1280x720
            set(golden ${GOLDEN}/chapter-06.png)
        endif()
        desktop_image_test(desktop.format-${format}.chapter-${chapter} ${golden}
            COMMAND $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless ${size}
                    --target-format ${format} --benchmark --warmup 0 --frames 1
                    --screenshot ${TEST_OUT}/desktop.format-${format}.chapter-${chapter}.png
            EXPECT_STDOUT "target_format +${format}, SRGB_NONLINEAR" QUIET_STDERR)
    endforeach()
endforeach()
# The overlay in a UNORM and the two 10-bit formats: blended as in the sRGB golden images (there
# through a _UNORM view of the image).
foreach(format B8G8R8A8_UNORM A2R10G10B10_UNORM_PACK32 A2B10G10R10_UNORM_PACK32)
    foreach(chapter 14 15 15-lab)
        desktop_image_test(desktop.format-${format}.chapter-${chapter}-gui ${GOLDEN}/chapter-${chapter}-gui.png
            COMMAND $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless ${SIZE} --gui
                    --target-format ${format}
                    --screenshot ${TEST_OUT}/desktop.format-${format}.chapter-${chapter}-gui.png
            QUIET_STDERR)
    endforeach()
endforeach()
chapter_test(desktop.format-unknown COMMAND $<TARGET_FILE:chapter-06> --headless --target-format RGB565
    EXPECT_EXIT 2 EXPECT_STDERR "--target-format must be one of B8G8R8A8_SRGB\\|" ONE_LINE_STDERR)

# HiDPI: the overlay at scale 2 (1280x720 pixels, 640x360 points) covers what it covers at scale 1.
foreach(chapter 14 15)
    set(run $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless)
    set(out ${TEST_OUT}/desktop.gui-scale.chapter-${chapter})
    foreach(shot "1;${SIZE};--gui;--gui-scale;1" "1-base;${SIZE}" "2;--width;1280;--height;720;--gui;--gui-scale;2"
                 "2-base;--width;1280;--height;720")
        list(POP_FRONT shot suffix)
        chapter_test(desktop.gui-scale.chapter-${chapter}-${suffix}
            COMMAND ${run} ${shot} --screenshot ${out}-${suffix}.png QUIET_STDERR)
        set_tests_properties(desktop.gui-scale.chapter-${chapter}-${suffix} PROPERTIES
            FIXTURES_SETUP gui-scale-${chapter})
    endforeach()
    add_test(NAME desktop.gui-scale.chapter-${chapter}
        COMMAND image_compare ${out}-2.png --overlay-like ${out}-2-base.png ${out}-1.png ${out}-1-base.png)
    set_tests_properties(desktop.gui-scale.chapter-${chapter} PROPERTIES FIXTURES_REQUIRED gui-scale-${chapter})
endforeach()
chapter_test(desktop.gui-scale-bad COMMAND $<TARGET_FILE:chapter-15> --headless --gui --gui-scale 0.5
    EXPECT_EXIT 2 EXPECT_STDERR "--gui-scale must be a number from 1 to 4, got '0.5'" ONE_LINE_STDERR)

if(XVFB_RUN)
    # A 30-bit X screen: the window surface offers A2R10G10B10_UNORM_PACK32 only.
    set(DEPTH30 ${XVFB_RUN} -a -s "-screen 0 1600x1200x30")
    foreach(chapter 06 10 14 15)
        set(size ${SIZE})
        set(golden ${GOLDEN}/chapter-${chapter}-final.png)
        if(chapter STREQUAL "06")
            set(size)
            set(golden ${GOLDEN}/chapter-06.png)
        endif()
        desktop_image_test(desktop.depth30.chapter-${chapter} ${golden}
            COMMAND ${DEPTH30} $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation ${size}
                    --benchmark --warmup 0 --frames 3 --screenshot ${TEST_OUT}/desktop.depth30.chapter-${chapter}.png
            EXPECT_STDOUT "target_format +A2R10G10B10_UNORM_PACK32, SRGB_NONLINEAR" QUIET_STDERR)
    endforeach()
    foreach(chapter 14 15 15-lab)
        desktop_image_test(desktop.depth30.chapter-${chapter}-gui ${GOLDEN}/chapter-${chapter}-gui.png
            COMMAND ${DEPTH30} $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation ${SIZE}
                    --gui --gui-still --frames 3 --screenshot ${TEST_OUT}/desktop.depth30.chapter-${chapter}-gui.png
            QUIET_STDERR)
    endforeach()
    # A swapchain that cannot be viewed as _UNORM (no VK_KHR_swapchain_mutable_format): the overlay's
    # vertex shader decodes its colours instead, so its opaque pixels are those of the sRGB golden
    # image and its translucent panels blend in linear light (their own golden image,
    # chapter-NN-gui-linear-blend.png: the panels a little lighter, nothing else differs).
    foreach(chapter 14 15)
        set(name desktop.no-mutable-swapchain.chapter-${chapter}-gui)
        desktop_image_test(${name} ${GOLDEN}/chapter-${chapter}-gui-linear-blend.png
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:chapter-${chapter}> --device llvmpipe
                    --validation ${SIZE} --gui --gui-still --frames 3 --screenshot ${TEST_OUT}/${name}.png
            QUIET_STDERR)
        set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_HIDE=VK_KHR_swapchain_mutable_format")
    endforeach()
    # A format the surface does not offer, and a surface that offers none we can use.
    chapter_test(desktop.window-format-not-offered
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:chapter-06> --device llvmpipe
                --validation --frames 1 --target-format A2B10G10R10_UNORM_PACK32
        EXPECT_EXIT 2 EXPECT_STDERR "--target-format A2B10G10R10_UNORM_PACK32: the window surface does not offer it"
        ONE_LINE_STDERR)
    chapter_test(desktop.window-no-usable-format
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:chapter-06> --device llvmpipe
                --validation --frames 1
        EXPECT_EXIT 1 EXPECT_STDERR "the window surface offers no format this program can draw to" ONE_LINE_STDERR)
    set_tests_properties(desktop.window-no-usable-format PROPERTIES ENVIRONMENT
        "${FAULT_ENV};VKBOOK_HIDE=B8G8R8A8_SRGB,R8G8B8A8_SRGB,B8G8R8A8_UNORM,R8G8B8A8_UNORM,A2R10G10B10_UNORM_PACK32,A2B10G10R10_UNORM_PACK32")
    find_program(XDOTOOL xdotool)
    if(XDOTOOL)
        # After a resize the overlay still gets Ctrl, Backspace, Enter (our key callback is
        # installed once, before Dear ImGui's, which chains to it).
        chapter_test(desktop.window-type-after-resize
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${CMAKE_CURRENT_SOURCE_DIR}/desktops/window_gui.sh
                    type-after-resize $<TARGET_FILE:chapter-15> --device llvmpipe --validation ${SIZE} --gui
            EXPECT_STDOUT "sun at 300.0 degrees" QUIET_STDERR)
    endif()
endif()

# Devices poorer or older than lavapipe, made so by the fault-injection layer (it changes what the
# chapter is told, not what the validation layer below it checks).
# desktop_device_test(NAME ENV COMMAND ... [chapter_test options]): chapter_test with the layer and ENV.
function(desktop_device_test name env)
    chapter_test(${name} ${ARGN})
    set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FAULT_ENV};${env}")
endfunction()
set(REFUSED_13 "needs Vulkan 1.3, or 1.2 with VK_KHR_dynamic_rendering and VK_KHR_synchronization2")
foreach(chapter 06 10 14 15 15-lab)
    set(run $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless)
    set(size ${SIZE})
    set(golden ${GOLDEN}/chapter-${chapter}-final.png)
    if(chapter STREQUAL "06")
        set(size)
        set(golden ${GOLDEN}/chapter-06.png)
    elseif(chapter STREQUAL "15-lab")
        set(golden ${GOLDEN}/chapter-15-final.png)
    endif()
    # Vulkan 1.2: chapters 06 and 10 in their 1.0/1.1 core; 14 and 15 through the two extensions.
    set(expect "vulkan +Vulkan 1.2\n")
    if(NOT chapter MATCHES "^(06|10)$")
        set(expect "vulkan +Vulkan 1.2 \\+ VK_KHR_dynamic_rendering \\+ VK_KHR_synchronization2\n")
    endif()
    set(name desktop.vulkan-1.2.chapter-${chapter})
    desktop_image_test(${name} ${golden}
        COMMAND ${run} ${size} --benchmark --warmup 0 --frames 2 --screenshot ${TEST_OUT}/${name}.png
        EXPECT_STDOUT "${expect}" QUIET_STDERR)
    set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_DEVICE_API=1.2")
    # Vulkan 1.1: chapters 06 and 10 run, the others are refused in one line.
    set(name desktop.vulkan-1.1.chapter-${chapter})
    if(chapter MATCHES "^(06|10)$")
        desktop_image_test(${name} ${golden}
            COMMAND ${run} ${size} --benchmark --warmup 0 --frames 2 --screenshot ${TEST_OUT}/${name}.png
            EXPECT_STDOUT "vulkan +Vulkan 1.1\n" QUIET_STDERR)
        set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_DEVICE_API=1.1")
    else()
        desktop_device_test(${name} VKBOOK_DEVICE_API=1.1 COMMAND ${run}
            EXPECT_EXIT 1 EXPECT_STDERR "it supports Vulkan 1.1. this chapter ${REFUSED_13}" ONE_LINE_STDERR)
        # Vulkan 1.2 without one or both extensions: refused, naming what is missing.
        desktop_device_test(desktop.vulkan-1.2-no-extensions.chapter-${chapter}
            "VKBOOK_DEVICE_API=1.2;VKBOOK_HIDE=VK_KHR_dynamic_rendering,VK_KHR_synchronization2" COMMAND ${run}
            EXPECT_EXIT 1
            EXPECT_STDERR "it supports Vulkan 1.2 without VK_KHR_dynamic_rendering and VK_KHR_synchronization2. this chapter ${REFUSED_13}"
            ONE_LINE_STDERR)
        desktop_device_test(desktop.vulkan-1.2-no-synchronization2.chapter-${chapter}
            "VKBOOK_DEVICE_API=1.2;VKBOOK_HIDE=VK_KHR_synchronization2" COMMAND ${run}
            EXPECT_EXIT 1 EXPECT_STDERR "it supports Vulkan 1.2 without VK_KHR_synchronization2. " ONE_LINE_STDERR)
    endif()
    # No D32_SFLOAT: a 24-bit depth buffer, the same image (chapter-06 has no depth).
    if(NOT chapter STREQUAL "06")
        set(name desktop.no-d32.chapter-${chapter})
        desktop_image_test(${name} ${golden}
            COMMAND ${run} ${size} --benchmark --warmup 0 --frames 2 --screenshot ${TEST_OUT}/${name}.png
            EXPECT_STDOUT "depth_format +X8_D24_UNORM_PACK32\n" QUIET_STDERR)
        set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_HIDE=D32_SFLOAT")
    endif()
endforeach()
desktop_image_test(desktop.no-d32.chapter-15-depth ${GOLDEN}/chapter-15-depth.png
    COMMAND $<TARGET_FILE:chapter-15> --device llvmpipe --validation --headless ${SIZE} --view depth
            --screenshot ${TEST_OUT}/desktop.no-d32.chapter-15-depth.png QUIET_STDERR)
set_tests_properties(desktop.no-d32.chapter-15-depth PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_HIDE=D32_SFLOAT")
# Vulkan 1.0: every chapter refused in one line (chapters 06 and 10 need 1.1).
foreach(chapter 06 10)
    desktop_device_test(desktop.vulkan-1.0.chapter-${chapter} VKBOOK_DEVICE_API=1.0
        COMMAND $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless
        EXPECT_EXIT 1 EXPECT_STDERR "it supports Vulkan 1.0. this chapter needs Vulkan 1.1" ONE_LINE_STDERR)
endforeach()
# chapter-16 on poorer devices: Vulkan 1.1 refused; no geometry shaders refused, naming the
# feature; no D32_SFLOAT: the shadow map's depth in X8_D24 as the G-buffer's, the same image; no
# depth clamping: a slab high over the camera (far toward the sun from every cascade's box) still
# casts its shadow, the boxes reaching toward the sun as far as the scene does instead -- with
# neither, the shadow is gone (tools/gltf_cases.cpp, shadows/slab_overhead.json).
set(run16 $<TARGET_FILE:chapter-16> --device llvmpipe --validation --headless)
desktop_device_test(desktop.vulkan-1.1.chapter-16 VKBOOK_DEVICE_API=1.1 COMMAND ${run16}
    EXPECT_EXIT 1 EXPECT_STDERR "it supports Vulkan 1.1. this chapter ${REFUSED_13}" ONE_LINE_STDERR)
desktop_device_test(desktop.no-geometry-shader.chapter-16 VKBOOK_HIDE=geometryShader COMMAND ${run16}
    EXPECT_EXIT 1 EXPECT_STDERR "it lacks the geometryShader feature" ONE_LINE_STDERR)
desktop_image_test(desktop.no-d32.chapter-16 ${GOLDEN}/chapter-16-final.png
    COMMAND ${run16} ${SIZE} --benchmark --warmup 0 --frames 2 --screenshot ${TEST_OUT}/desktop.no-d32.chapter-16.png
    EXPECT_STDOUT "depth_format +X8_D24_UNORM_PACK32\n" QUIET_STDERR)
set_tests_properties(desktop.no-d32.chapter-16 PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_HIDE=D32_SFLOAT")
foreach(clamp with without)
    set(name desktop.slab-overhead-${clamp}-depth-clamp.chapter-16)
    set(reported "depth_clamp +yes")
    if(clamp STREQUAL "without")
        set(reported "depth_clamp +no: cascades reach the scene's casters")
    endif()
    chapter_test(${name} WORKDIR /
        COMMAND ${run16} --width 320 --height 180 --scene ${CMAKE_CURRENT_BINARY_DIR}/gltf/shadows/slab_overhead.json
                --benchmark --warmup 0 --frames 1 --screenshot ${TEST_OUT}/${name}.png
        EXPECT_STDOUT "chapter-16: 2 draws.*${reported}" QUIET_STDERR)
    set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED gltf-cases FIXTURES_SETUP ${name})
    if(clamp STREQUAL "without")
        set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_HIDE=depthClamp")
    endif()
    # Under the slab (x -4, z -3 and 3): black; beside it (x -1.5): lit, 187.
    add_test(NAME ${name}-shadow COMMAND image_compare ${TEST_OUT}/${name}.png --size 320 180
        --pixel 207 28 0 0 0 --pixel 113 28 0 0 0 --pixel 113 67 187 187 187 --pixel 207 67 187 187 187
        --pixel-tolerance 3)
    set_tests_properties(${name}-shadow PROPERTIES FIXTURES_REQUIRED ${name})
endforeach()

# A device without the scalarBlockLayout feature: chapters 15 and 16 and the lab refused in one
# line naming it.
foreach(chapter 15 15-lab 16 17 18 19)
    desktop_device_test(desktop.no-scalar-block-layout.chapter-${chapter} VKBOOK_HIDE=scalarBlockLayout
        COMMAND $<TARGET_FILE:chapter-${chapter}> --device llvmpipe --validation --headless
        EXPECT_EXIT 1 EXPECT_STDERR "it lacks the scalarBlockLayout feature" ONE_LINE_STDERR)
endforeach()
# chapter-18 on a device without buffer device addresses or 64-bit integers in shaders: refused in
# one line naming the feature, before anything is made.
foreach(feature bufferDeviceAddress shaderInt64)
    desktop_device_test(desktop.no-${feature}.chapter-18 VKBOOK_HIDE=${feature}
        COMMAND $<TARGET_FILE:chapter-18> --device llvmpipe --validation --headless
        EXPECT_EXIT 1 EXPECT_STDERR "it lacks the ${feature} feature" ONE_LINE_STDERR)
endforeach()
# chapter-19 on a device that cannot draw many indirect commands at once, or give each its first
# instance: refused in one line naming the feature.
foreach(feature multiDrawIndirect drawIndirectFirstInstance)
    desktop_device_test(desktop.no-${feature}.chapter-19 VKBOOK_HIDE=${feature}
        COMMAND $<TARGET_FILE:chapter-19> --device llvmpipe --validation --headless
        EXPECT_EXIT 1 EXPECT_STDERR "it lacks the ${feature} feature" ONE_LINE_STDERR)
endforeach()
# chapter-20 asks for chapter-19's features: the same line, before any thread is started.
desktop_device_test(desktop.no-multiDrawIndirect.chapter-20 VKBOOK_HIDE=multiDrawIndirect
    COMMAND $<TARGET_FILE:chapter-20> --device llvmpipe --validation --headless
    EXPECT_EXIT 1 EXPECT_STDERR "it lacks the multiDrawIndirect feature" ONE_LINE_STDERR)
# Headless on a device that cannot render to B8G8R8A8_SRGB: R8G8B8A8_SRGB, the same image.
desktop_image_test(desktop.no-bgra-srgb.chapter-06 ${GOLDEN}/chapter-06.png
    COMMAND $<TARGET_FILE:chapter-06> --device llvmpipe --validation --headless --benchmark --warmup 0 --frames 1
            --screenshot ${TEST_OUT}/desktop.no-bgra-srgb.chapter-06.png
    EXPECT_STDOUT "target_format +R8G8B8A8_SRGB, SRGB_NONLINEAR" QUIET_STDERR)
set_tests_properties(desktop.no-bgra-srgb.chapter-06 PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_HIDE=B8G8R8A8_SRGB")
# Reversed-Z needs float depth: the lab's compact layout is refused in one line.
desktop_device_test(desktop.no-d32.lab-reversed-z VKBOOK_HIDE=D32_SFLOAT
    COMMAND $<TARGET_FILE:chapter-15-lab> --device llvmpipe --validation --headless --gbuffer compact
    EXPECT_EXIT 1 EXPECT_STDERR "the G-buffer layout 'compact' \\(reversed-Z\\) needs D32_SFLOAT depth" ONE_LINE_STDERR)
desktop_device_test(desktop.no-depth-format VKBOOK_HIDE=D32_SFLOAT,X8_D24_UNORM_PACK32
    COMMAND $<TARGET_FILE:chapter-10> --device llvmpipe --validation --headless
    EXPECT_EXIT 1 EXPECT_STDERR "can render to and sample neither D32_SFLOAT nor X8_D24_UNORM_PACK32" ONE_LINE_STDERR)

# The window moved to a screen with other formats: after the first swapchain, the layer takes
# B8G8R8A8_SRGB out of the surface's formats (VKBOOK_HIDE_LATER), so the swapchain made at the
# resize is B8G8R8A8_UNORM. Whatever writes the image (render passes, pipelines, the post pass's sRGB
# encoding, the overlay) must follow: the image after the resize is the golden one, validation-clean.
if(XVFB_RUN)
    foreach(chapter 06 10 14 15 15-lab)
        set(start --width 320 --height 180)
        set(end 640x360)
        set(golden ${GOLDEN}/chapter-${chapter}-final.png)
        if(chapter STREQUAL "06")
            set(start ${SIZE})
            set(end 1280x720)
            set(golden ${GOLDEN}/chapter-06.png)
        elseif(chapter STREQUAL "15-lab")
            set(golden ${GOLDEN}/chapter-15-final.png)
        endif()
        set(name desktop.format-change.chapter-${chapter})
        desktop_image_test(${name} ${golden}
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" $<TARGET_FILE:chapter-${chapter}> --device llvmpipe
                    --validation ${start} --benchmark --warmup 0 --frames 6 --resize ${end}
                    --screenshot ${TEST_OUT}/${name}.png
            EXPECT_STDOUT "target_format +B8G8R8A8_UNORM, SRGB_NONLINEAR" QUIET_STDERR)
        set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FAULT_ENV};VKBOOK_HIDE_LATER=B8G8R8A8_SRGB")
    endforeach()
    foreach(chapter 14 15 15-lab)
        set(name desktop.format-change.chapter-${chapter}-gui)
        desktop_image_test(${name} ${GOLDEN}/chapter-${chapter}-gui.png
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" $<TARGET_FILE:chapter-${chapter}> --device llvmpipe
                    --validation --width 320 --height 180 --gui --gui-still --frames 6 --resize 640x360
                    --screenshot ${TEST_OUT}/${name}.png
            QUIET_STDERR)
        # Without _UNORM views of the swapchain the overlay draws through the image's own format,
        # so its pipeline must follow the change too (B8G8R8A8_SRGB, then B8G8R8A8_UNORM).
        set_tests_properties(${name} PROPERTIES ENVIRONMENT
            "${FAULT_ENV};VKBOOK_HIDE_LATER=B8G8R8A8_SRGB;VKBOOK_HIDE=VK_KHR_swapchain_mutable_format")
    endforeach()
endif()

# Old swapchains destroyed only once the presentation engine is done with them
# (VUID-vkDestroySwapchainKHR-swapchain-01282): the fault-injection layer checks every
# vkDestroySwapchainKHR (reliability/fault_layer/fault_layer.cpp) and prints a line when the rule is broken. Without
# VK_EXT_swapchain_maintenance1 (lavapipe has none): resizes in a window, each chapter, and 100 resizes
# whose resident memory must not grow (a retired swapchain kept to the end would add its images).
if(XVFB_RUN)
    foreach(chapter 06 10 14 15 15-lab)
        desktop_device_test(desktop.retire-swapchains.chapter-${chapter} VKBOOK_HIDE=VK_EXT_swapchain_maintenance1
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:chapter-${chapter}> --device llvmpipe
                    --validation ${SIZE} --benchmark --warmup 0 --frames 40 --resize 500x300
            EXPECT_STDOUT "present +window, no vsync\n" QUIET_STDERR)
    endforeach()
    if(JWM AND XDOTOOL)
        desktop_device_test(desktop.retire-swapchains-window-life VKBOOK_HIDE=VK_EXT_swapchain_maintenance1
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CMAKE_CURRENT_SOURCE_DIR}/desktops/window_life.sh
                    $<TARGET_FILE:chapter-15> --device llvmpipe --validation ${SIZE}
            EXPECT_STDOUT "resident memory slope over 100 resizes: -?[0-9]+ kB per resize" QUIET_STDERR)
    endif()
endif()

# Old swapchains retired by present fences (VK_EXT_swapchain_maintenance1, which the layer emulates
# on lavapipe): a run with resizes under validation, and 100 resizes whose resident memory must not
# grow (a retired swapchain kept to the end would add its images at every resize).
if(XVFB_RUN)
    desktop_device_test(desktop.present-fences VKBOOK_EMULATE=swapchain_maintenance1
        COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:chapter-15> --device llvmpipe
                --validation ${SIZE} --benchmark --warmup 0 --frames 40 --resize 500x300
        EXPECT_STDOUT "present +window, no vsync, present fences \\(VK_EXT_swapchain_maintenance1\\)" QUIET_STDERR)
    if(JWM AND XDOTOOL)
        desktop_device_test(desktop.present-fences-window-life VKBOOK_EMULATE=swapchain_maintenance1
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CMAKE_CURRENT_SOURCE_DIR}/desktops/window_life.sh
                    $<TARGET_FILE:chapter-15> --device llvmpipe --validation ${SIZE}
            EXPECT_STDOUT "resident memory slope over 100 resizes: -?[0-9]+ kB per resize" QUIET_STDERR)
    endif()
endif()
