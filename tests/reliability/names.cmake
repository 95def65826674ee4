# Names and labels (docs/live-shaders.md): every Vulkan object of the kinds a debugger lists is
# named (vkSetDebugUtilsObjectNameEXT) and every pass is labelled with its benchmark row's name
# (vkCmdBeginDebugUtilsLabelEXT), checked by a layer that records those calls
# (reliability/names_layer/names_layer.cpp), an implicit layer like the fault-injection one (reliability/fault.cmake).
set(NAMES_LAYER_DIR ${CMAKE_CURRENT_BINARY_DIR}/names_layer)
add_library(VkLayer_vkbook_object_names MODULE reliability/names_layer/names_layer.cpp)
target_link_libraries(VkLayer_vkbook_object_names PRIVATE Vulkan::Headers)
vkbook_warnings(VkLayer_vkbook_object_names)
set_target_properties(VkLayer_vkbook_object_names PROPERTIES
    LIBRARY_OUTPUT_DIRECTORY ${NAMES_LAYER_DIR} CXX_VISIBILITY_PRESET hidden)
file(GENERATE OUTPUT ${NAMES_LAYER_DIR}/vulkan/implicit_layer.d/VkLayer_vkbook_object_names.json CONTENT [[{
    "file_format_version": "1.1.2",
    "layer": {
        "name": "VK_LAYER_VKBOOK_object_names",
        "type": "GLOBAL",
        "library_path": "$<TARGET_FILE:VkLayer_vkbook_object_names>",
        "api_version": "1.3.0",
        "implementation_version": "1",
        "description": "vulkan-book-cpp tests: records object names and labels (VKBOOK_NAMES_REPORT=file)",
        "enable_environment": {"VKBOOK_NAMES_LAYER": "1"},
        "disable_environment": {"VKBOOK_NAMES_LAYER_DISABLE": "1"}
    }
}
]])

# names_test(NAME LABELS a,b,c [WINDOW] COMMAND chapter options...): the run's objects all named,
# its passes labelled a, b, c; with --validation, whose messages then name our objects. Headless,
# or in a window under Xvfb (the swapchain, its images and semaphores).
function(names_test name)
    cmake_parse_arguments(N "WINDOW" "LABELS" "COMMAND" ${ARGN})
    set(prefix "")
    set(mode --headless)
    if(N_WINDOW)
        if(NOT XVFB_RUN)
            return()
        endif()
        set(prefix ${XVFB_RUN} -a -s "-screen 0 1280x1024x24")
        set(mode "")
    endif()
    chapter_test(${name}
        COMMAND ${prefix} ${CMAKE_CURRENT_SOURCE_DIR}/reliability/names_check.sh ${TEST_OUT}/${name}.names ${N_LABELS} ${N_COMMAND}
                ${mode} --validation --width 320 --height 180 --frames 3
        EXPECT_STDOUT "image: [0-9]+ named.*buffer: [1-9].*pipeline: [1-9].*shader-module: [1-9].*descriptor-set-layout: .*command-pool: [1-9].*semaphore: [1-9].*fence: [1-9]")
    set_tests_properties(${name} PROPERTIES
        ENVIRONMENT "${TEST_ENV};XDG_DATA_HOME=${NAMES_LAYER_DIR};VKBOOK_NAMES_LAYER=1")
endfunction()

names_test(names.chapter-06 LABELS triangle COMMAND $<TARGET_FILE:chapter-06>)
names_test(names.chapter-10 LABELS geometry,lighting COMMAND $<TARGET_FILE:chapter-10>)
names_test(names.chapter-14 LABELS scene,light,post,gui COMMAND $<TARGET_FILE:chapter-14> --gui)
names_test(names.chapter-15 LABELS scene,light,post,gui COMMAND $<TARGET_FILE:chapter-15> --gui)
names_test(names.chapter-15-lab LABELS scene,cull,light,post,gui
    COMMAND $<TARGET_FILE:chapter-15-lab> --gui --light-culling tiled --light-pass compute)
names_test(names.chapter-15-window LABELS scene,light,post,gui WINDOW COMMAND $<TARGET_FILE:chapter-15> --gui)
names_test(names.chapter-06-window LABELS triangle WINDOW COMMAND $<TARGET_FILE:chapter-06>)
names_test(names.chapter-15-lab-forward LABELS forward,post COMMAND $<TARGET_FILE:chapter-15-lab> --shading forward)
names_test(names.chapter-16 LABELS shadow,scene,light,post,gui COMMAND $<TARGET_FILE:chapter-16> --gui)
names_test(names.chapter-17 LABELS skinning,shadow,scene,light,post,gui COMMAND $<TARGET_FILE:chapter-17> --gui)
names_test(names.chapter-18 LABELS skinning,shadow,scene,light,post,gui COMMAND $<TARGET_FILE:chapter-18> --gui)
names_test(names.chapter-19 LABELS skinning,shadow,scene,light,post,gui COMMAND $<TARGET_FILE:chapter-19> --gui)
names_test(names.chapter-20 LABELS skinning,shadow,scene,light,post,gui COMMAND $<TARGET_FILE:chapter-20> --gui)
names_test(names.chapter-15-lab-shadows LABELS shadow,scene,light,post
    COMMAND $<TARGET_FILE:chapter-15-lab> --shadows pcf3 --shadow-layers passes)
