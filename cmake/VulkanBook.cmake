# Settings, dependencies and helper functions shared by the top-level build and by every
# chapter built on its own (cmake -S chapter-06 -B /tmp/b06). Included once per build tree.
include_guard(GLOBAL)

set(CMAKE_CXX_STANDARD 20)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
set(CMAKE_EXPORT_COMPILE_COMMANDS ON)
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
    set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()

# Every chapter lands in <build>/bin with its shaders in <build>/bin/shaders/<chapter>/, so an
# executable finds its data next to itself, whatever the working directory.
set(CMAKE_RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
# Multi-configuration generators (Visual Studio, Xcode) would put them in bin/Release/ and so on,
# away from the shaders and the scene: every configuration goes to bin/ too.
foreach(config IN LISTS CMAKE_CONFIGURATION_TYPES)
    string(TOUPPER ${config} config)
    set(CMAKE_RUNTIME_OUTPUT_DIRECTORY_${config} ${CMAKE_BINARY_DIR}/bin)
endforeach()
cmake_path(GET CMAKE_CURRENT_LIST_DIR PARENT_PATH VKBOOK_ROOT)
set(VKBOOK_SHADER_OUTPUT_DIR ${CMAKE_BINARY_DIR}/bin/shaders)

option(VKBOOK_WERROR "Treat compiler warnings as errors" ON)

# Source-level shader debugging (RenderDoc and other graphics debuggers show the GLSL and step
# through it): every shader built with glslang's -gVS (non-semantic debug information with the
# source text), and shaders compiled at run time with shaderc's debug information. On by default
# in Debug builds.
if(CMAKE_BUILD_TYPE STREQUAL "Debug")
    set(vkbook_shader_debug_default ON)
else()
    set(vkbook_shader_debug_default OFF)
endif()
option(VKBOOK_SHADER_DEBUG_INFO "Build shaders with debug information for source-level debugging"
       ${vkbook_shader_debug_default})

include(${CMAKE_CURRENT_LIST_DIR}/Dependencies.cmake)

# -DVKBOOK_SANITIZE=ON: AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer on
# every target, the first report ending the program. scripts/setup.sh test builds this into
# build-sanitize/ and runs the headless tests there (docs/reliability.md).
option(VKBOOK_SANITIZE "Build with AddressSanitizer, LeakSanitizer and UndefinedBehaviorSanitizer" OFF)
if(VKBOOK_SANITIZE AND (MSVC OR WIN32))
    message(FATAL_ERROR "VKBOOK_SANITIZE is for GCC or Clang on Linux (AddressSanitizer, LeakSanitizer, UBSan)")
endif()
if(VKBOOK_SANITIZE)
    # -O1 -g1 after the build type's flags (the last -O and -g win): AddressSanitizer's advice for
    # speed, and line tables for symbolized reports -- half the compile time of -O2 -g.
    add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1 -g1)
    add_link_options(-fsanitize=address,undefined)
    # Keeps the driver and layer libraries loaded until exit, so their leaks, if any, are named.
    add_library(vkbook_keep_libraries_loaded OBJECT ${CMAKE_CURRENT_LIST_DIR}/keep_libraries_loaded.cpp)
    link_libraries(vkbook_keep_libraries_loaded)
endif()

# -DVKBOOK_TSAN=ON: ThreadSanitizer on every target (chapter-20's test build: tests/chapters/chapter-20.cmake
# configures chapter-20 alone with it, into build/tsan).
option(VKBOOK_TSAN "Build with ThreadSanitizer" OFF)
if(VKBOOK_TSAN AND (MSVC OR WIN32 OR VKBOOK_SANITIZE))
    message(FATAL_ERROR "VKBOOK_TSAN is for GCC or Clang on Linux, without VKBOOK_SANITIZE")
endif()
if(VKBOOK_TSAN)
    add_compile_options(-fsanitize=thread -fno-omit-frame-pointer -O1 -g1)
    add_link_options(-fsanitize=thread)
    # The driver and layers stay loaded: ThreadSanitizer's suppressions name the validation layer
    # (tests/reliability/tsan/tsan.supp), and refuse a library unloaded under them.
    add_library(vkbook_keep_libraries_loaded OBJECT ${CMAKE_CURRENT_LIST_DIR}/keep_libraries_loaded.cpp)
    link_libraries(vkbook_keep_libraries_loaded)
endif()

# vkbook_warnings(target): the warning set every target of ours builds with.
function(vkbook_warnings target)
    if(MSVC)
        # /utf-8: the sources are UTF-8; /permissive-: standard C++; 4324: padding by alignas.
        target_compile_options(${target} PRIVATE /W4 /utf-8 /permissive- /wd4324)
        target_compile_definitions(${target} PRIVATE NOMINMAX WIN32_LEAN_AND_MEAN _CRT_SECURE_NO_WARNINGS)
        if(VKBOOK_WERROR)
            target_compile_options(${target} PRIVATE /WX)
        endif()
        return()
    endif()
    # GCC and Clang (MinGW-w64 included). Vulkan structs are filled with C++20 designated
    # initializers, which zero every member they leave out; that is the point, so
    # -Wmissing-field-initializers is off.
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                             -Wno-sign-conversion -Wno-missing-field-initializers)
    if(WIN32)
        target_compile_definitions(${target} PRIVATE NOMINMAX WIN32_LEAN_AND_MEAN)
    endif()
    if(VKBOOK_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()

# vkbook_shaders(target chapter src...): compiles shaders/<chapter>/<src> to
# <build>/bin/shaders/<chapter>/<src>.spv at build time. glslangValidator writes a depfile, so
# editing a file under shaders/include/ rebuilds every shader that includes it. A GLSL error
# fails the build with the compiler's message. A source written `name.frag:variant:DEFINE` is
# compiled once more with -DDEFINE into name-variant.frag.spv (e.g. a G-buffer layout). A source
# with a directory, `chapter-15/scene.vert`, is another chapter's (shaders/chapter-15/scene.vert),
# compiled into this chapter's directory under its own name.
function(vkbook_shaders target chapter)
    set(outputs)
    set(debug_info)
    if(VKBOOK_SHADER_DEBUG_INFO)
        set(debug_info -gVS)
    endif()
    foreach(spec IN LISTS ARGN)
        string(REPLACE ":" ";" parts "${spec}")
        list(GET parts 0 src)
        set(defines)
        set(name ${src})
        list(LENGTH parts count)
        if(count EQUAL 3)
            list(GET parts 1 variant)
            list(GET parts 2 define)
            string(REPLACE "+" ";" define_list "${define}")  # NAME+OTHER: two defines
            foreach(d IN LISTS define_list)
                list(APPEND defines -D${d})
            endforeach()
            string(REGEX REPLACE "^([^.]+)\\." "\\1-${variant}." name "${src}")
        endif()
        set(in ${VKBOOK_ROOT}/shaders/${chapter}/${src})
        if(src MATCHES "/")
            set(in ${VKBOOK_ROOT}/shaders/${src})
            get_filename_component(name ${name} NAME)
        endif()
        set(out ${VKBOOK_SHADER_OUTPUT_DIR}/${chapter}/${name}.spv)
        # What the build compiled it from, for runtime compilation (common/shaders/shader_compiler.cpp):
        # the source relative to shaders/, then one macro definition a line.
        file(RELATIVE_PATH relative ${VKBOOK_ROOT}/shaders ${in})
        string(REPLACE "-D" "" define_lines "${defines}")
        string(REPLACE ";" "\n" define_lines "${define_lines}")
        file(GENERATE OUTPUT ${VKBOOK_SHADER_OUTPUT_DIR}/${chapter}/${name}.source
             CONTENT "${relative}\n${define_lines}")
        add_custom_command(
            OUTPUT ${out}
            COMMAND ${CMAKE_COMMAND} -E make_directory ${VKBOOK_SHADER_OUTPUT_DIR}/${chapter}
            COMMAND Vulkan::glslangValidator --target-env vulkan1.1 -I${VKBOOK_ROOT}/shaders/include ${defines}
                    ${debug_info}
                    --depfile ${out}.d -o ${out} ${in}
            MAIN_DEPENDENCY ${in}
            DEPFILE ${out}.d
            COMMENT "glslangValidator ${chapter}/${name}"
            VERBATIM)
        list(APPEND outputs ${out})
    endforeach()
    add_custom_target(${target}-shaders DEPENDS ${outputs})
    add_dependencies(${target} ${target}-shaders)
endfunction()

# Where the shader sources are, for runtime compilation: the build's shaders/, written next to
# the compiled shaders (a copied bin/ whose tree is gone falls back to the build's SPIR-V).
file(GENERATE OUTPUT ${VKBOOK_SHADER_OUTPUT_DIR}/source-dir.txt CONTENT "${VKBOOK_ROOT}/shaders\n")

# The common library, added once whichever CMakeLists comes first.
if(NOT TARGET common)
    add_subdirectory(${VKBOOK_ROOT}/common ${CMAKE_BINARY_DIR}/common)
endif()

# vkbook_default_scene(target): the chapter renders the generated default scene, so building it
# generates the scene first (scenes/CMakeLists.txt), also when the chapter is built on its own.
function(vkbook_default_scene target)
    if(NOT TARGET default-scene)
        add_subdirectory(${VKBOOK_ROOT}/scenes ${CMAKE_BINARY_DIR}/scenes)
    endif()
    add_dependencies(${target} default-scene)
endfunction()
