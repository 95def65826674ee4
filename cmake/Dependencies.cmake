# The libraries every chapter uses, found the same way on every system: a system or SDK package
# first (Debian's -dev packages, vcpkg, the LunarG SDK, Homebrew), otherwise CMake fetches the
# pinned upstream release itself (FetchContent), so a reader needs no package manager. Nothing is
# vendored into the repository.
#
# Offline builds point FetchContent at local sources instead of downloading, e.g.
#   -DFETCHCONTENT_SOURCE_DIR_GLFW3=/src/glfw3-3.3.8
# which is how the windows-cross preset builds from Debian's source packages
# (scripts/windows-cross.sh).
#
# After this file, these targets exist whichever way they came: glfw, glm::glm,
# tinyobjloader::tinyobjloader, nlohmann_json::nlohmann_json, vkbook::stb (stb_image,
# stb_image_write, stb_image_resize, with their implementations), vkbook::imgui (Dear ImGui with
# its GLFW platform backend, used for input only), vkbook::tinygltf (glTF 2.0), CLI11::CLI11 (the
# command line) and Vulkan::Vulkan with
# Vulkan::glslangValidator (the Vulkan SDK on Windows and macOS; not fetched).
include_guard(GLOBAL)
include(FetchContent)

find_package(Vulkan 1.3 REQUIRED COMPONENTS glslangValidator)

# The same versions as Debian 12's packages, which the Linux build uses.
set(GLFW_BUILD_EXAMPLES OFF CACHE BOOL "")
set(GLFW_BUILD_TESTS OFF CACHE BOOL "")
set(GLFW_BUILD_DOCS OFF CACHE BOOL "")
set(GLFW_INSTALL OFF CACHE BOOL "")
set(JSON_BuildTests OFF CACHE BOOL "")
set(JSON_Install OFF CACHE BOOL "")
set(CMAKE_POLICY_DEFAULT_CMP0063 NEW)  # tinyobjloader's CMakeLists predates it
if(CMAKE_VERSION VERSION_GREATER_EQUAL 3.24)
    FetchContent_Declare(glfw3
        GIT_REPOSITORY https://github.com/glfw/glfw.git
        GIT_TAG 3.3.8
        FIND_PACKAGE_ARGS 3.3)
    FetchContent_Declare(glm
        GIT_REPOSITORY https://github.com/g-truc/glm.git
        GIT_TAG 0.9.9.8
        FIND_PACKAGE_ARGS)
    FetchContent_Declare(tinyobjloader
        GIT_REPOSITORY https://github.com/tinyobjloader/tinyobjloader.git
        GIT_TAG v2.0.0rc10
        FIND_PACKAGE_ARGS)
    FetchContent_Declare(nlohmann_json
        GIT_REPOSITORY https://github.com/nlohmann/json.git
        GIT_TAG v3.11.2
        FIND_PACKAGE_ARGS 3)
    FetchContent_MakeAvailable(glfw3 glm tinyobjloader nlohmann_json)
else()
    # CMake before 3.24 cannot try a package first: the packages must be installed (Ubuntu 22.04:
    # apt-get install libglfw3-dev libglm-dev libtinyobjloader-dev nlohmann-json3-dev).
    find_package(glfw3 3.3 REQUIRED)
    find_package(glm REQUIRED)
    find_package(tinyobjloader REQUIRED)
    find_package(nlohmann_json 3 REQUIRED)
endif()
# Debian's tinyobjloader source builds its test programs with the library: not here.
if(tinyobjloader_SOURCE_DIR AND EXISTS ${tinyobjloader_SOURCE_DIR}/tests/CMakeLists.txt)
    get_property(tinyobjloader_tests DIRECTORY ${tinyobjloader_SOURCE_DIR}/tests PROPERTY BUILDSYSTEM_TARGETS)
    if(tinyobjloader_tests)
        set_target_properties(${tinyobjloader_tests} PROPERTIES EXCLUDE_FROM_ALL ON)
    endif()
endif()
# A fetched library's headers are included as system headers, as an installed package's are: our
# warnings (and -Werror) are for our code, not for theirs.
foreach(target glfw glm tinyobjloader nlohmann_json)
    if(TARGET ${target})
        get_target_property(aliased ${target} ALIASED_TARGET)
        if(aliased)
            set(target ${aliased})
        endif()
        get_target_property(imported ${target} IMPORTED)
        get_target_property(includes ${target} INTERFACE_INCLUDE_DIRECTORIES)
        if(NOT imported AND includes)
            set_property(TARGET ${target} APPEND PROPERTY INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${includes})
        endif()
    endif()
endforeach()
# The names a package's CMake config gives, also for the targets a fetched source defines.
if(NOT TARGET glm::glm)
    add_library(glm::glm ALIAS glm)
endif()
if(NOT TARGET tinyobjloader::tinyobjloader)
    add_library(tinyobjloader::tinyobjloader ALIAS tinyobjloader)
endif()

# stb has no CMake package. Debian's libstb-dev is found through pkg-config and brings the
# implementations compiled (libstb.so); anywhere else the headers are fetched (the commit of
# Debian's snapshot) and compiled here, once, by stb_implementation.cpp.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
    pkg_check_modules(stb QUIET IMPORTED_TARGET stb)
endif()
if(TARGET PkgConfig::stb)
    add_library(vkbook_stb INTERFACE)
    target_link_libraries(vkbook_stb INTERFACE PkgConfig::stb)
else()
    FetchContent_Declare(stb
        GIT_REPOSITORY https://github.com/nothings/stb.git
        GIT_TAG 8b5f1f37b5b75829fc72d38e7b5d4bcbf8a26d55)
    FetchContent_GetProperties(stb)
    if(NOT stb_POPULATED)
        FetchContent_Populate(stb)
    endif()
    add_library(vkbook_stb STATIC ${CMAKE_CURRENT_LIST_DIR}/stb_implementation.cpp)
    target_include_directories(vkbook_stb SYSTEM PUBLIC ${stb_SOURCE_DIR})
    # File names given to stb are UTF-8 (common::utf8); on Windows stb converts them itself.
    target_compile_definitions(vkbook_stb PRIVATE STBI_WINDOWS_UTF8 STBIW_WINDOWS_UTF8)
endif()
add_library(vkbook::stb ALIAS vkbook_stb)

# Dear ImGui has no CMake package either. Debian's libimgui-dev (1.86) is found through pkg-config:
# a static library with the backends compiled, headers under imgui/. Anywhere else the same
# release is fetched and its core plus the GLFW backend compiled here. Either way a chapter
# includes <imgui.h> and <backends/imgui_impl_glfw.h>.
if(PKG_CONFIG_FOUND)
    pkg_check_modules(imgui QUIET IMPORTED_TARGET imgui)
endif()
if(TARGET PkgConfig::imgui)
    add_library(vkbook_imgui INTERFACE)
    target_link_libraries(vkbook_imgui INTERFACE PkgConfig::imgui glfw)
else()
    FetchContent_Declare(imgui
        GIT_REPOSITORY https://github.com/ocornut/imgui.git
        GIT_TAG v1.86)
    FetchContent_GetProperties(imgui)
    if(NOT imgui_POPULATED)
        FetchContent_Populate(imgui)
    endif()
    add_library(vkbook_imgui STATIC ${imgui_SOURCE_DIR}/imgui.cpp ${imgui_SOURCE_DIR}/imgui_draw.cpp
                                    ${imgui_SOURCE_DIR}/imgui_tables.cpp ${imgui_SOURCE_DIR}/imgui_widgets.cpp
                                    ${imgui_SOURCE_DIR}/imgui_demo.cpp
                                    ${imgui_SOURCE_DIR}/backends/imgui_impl_glfw.cpp)
    target_include_directories(vkbook_imgui SYSTEM PUBLIC ${imgui_SOURCE_DIR})
    target_link_libraries(vkbook_imgui PUBLIC glfw)
endif()
add_library(vkbook::imgui ALIAS vkbook_imgui)


# tinygltf (glTF 2.0): Debian's libtinygltf-dev (2.7) has a CMake package with the implementation
# compiled against Debian's nlohmann-json and stb. Anywhere else the same release is fetched and
# its implementation compiled here by tinygltf_implementation.cpp, against the nlohmann-json and
# stb above (not the copies in tinygltf's repository, which would clash with them).
find_package(TinyGLTF 2.7 QUIET)
if(TARGET TinyGLTF::TinyGLTF)
    add_library(vkbook_tinygltf INTERFACE)
    target_link_libraries(vkbook_tinygltf INTERFACE TinyGLTF::TinyGLTF)
else()
    FetchContent_Declare(tinygltf
        GIT_REPOSITORY https://github.com/syoyo/tinygltf.git
        GIT_TAG v2.7.0)
    FetchContent_GetProperties(tinygltf)
    if(NOT tinygltf_POPULATED)
        FetchContent_Populate(tinygltf)
    endif()
    add_library(vkbook_tinygltf STATIC ${CMAKE_CURRENT_LIST_DIR}/tinygltf_implementation.cpp)
    target_include_directories(vkbook_tinygltf SYSTEM PUBLIC ${tinygltf_SOURCE_DIR})
    target_link_libraries(vkbook_tinygltf PUBLIC nlohmann_json::nlohmann_json vkbook::stb)
    # stb and the file names tinygltf passes it are UTF-8 on Windows too.
    target_compile_definitions(vkbook_tinygltf PRIVATE STBI_WINDOWS_UTF8)
endif()
add_library(vkbook::tinygltf ALIAS vkbook_tinygltf)

# CLI11 (the command line): Debian's libcli11-dev (2.1); elsewhere the same release, fetched. Header
# only either way.
find_package(CLI11 2.1 CONFIG QUIET)
if(NOT TARGET CLI11::CLI11)
    set(CLI11_BUILD_TESTS OFF CACHE BOOL "")
    set(CLI11_BUILD_EXAMPLES OFF CACHE BOOL "")
    set(CLI11_BUILD_DOCS OFF CACHE BOOL "")
    FetchContent_Declare(cli11
        GIT_REPOSITORY https://github.com/CLIUtils/CLI11.git
        GIT_TAG v2.1.2)
    FetchContent_MakeAvailable(cli11)
endif()

# Runtime shader compilation (common/shaders/shader_compiler.cpp, chapter-06/shader_compiler.cpp): shaderc
# compiles GLSL while a chapter runs, as the book's ShaderCompiler does, and SPIRV-Cross reflects a
# recompiled shader's interface so that a reload never gives a pipeline a shader its layout does
# not fit. Debian: libshaderc-dev, glslang-dev and libspirv-cross-c-shared-dev; Windows and macOS:
# the Vulkan SDK has them. Without them the chapters build as before and use the build's SPIR-V only
# (--help says so). Target: vkbook::runtime_shaders, with VKBOOK_RUNTIME_SHADERS=1 defined.
option(VKBOOK_RUNTIME_SHADERS "Compile shaders at run time with shaderc when found (live reload)" ON)
add_library(vkbook_runtime_shaders INTERFACE)
if(VKBOOK_RUNTIME_SHADERS)
    # Debian's libshaderc.so leaves glslang's symbols to the program (and crashes when they come
    # from elsewhere): its libshaderc_combined.a is linked with glslang's static libraries
    # (glslang-dev's CMake package) instead. The Vulkan SDK's shaderc_combined has them inside.
    find_library(VKBOOK_SHADERC_COMBINED NAMES shaderc_combined)
    find_package(Threads REQUIRED)  # glslang's package names Threads::Threads without finding it
    find_package(glslang CONFIG QUIET)
    if(PKG_CONFIG_FOUND)
        pkg_check_modules(spirv_cross_c QUIET IMPORTED_TARGET spirv-cross-c-shared)
    endif()
    if(NOT (VKBOOK_SHADERC_COMBINED AND TARGET glslang::SPIRV) AND CMAKE_VERSION VERSION_GREATER_EQUAL 3.24)
        find_package(Vulkan QUIET COMPONENTS shaderc_combined)  # the Vulkan SDK's
    endif()
    if(NOT TARGET PkgConfig::spirv_cross_c)
        find_package(spirv_cross_c_shared CONFIG QUIET)  # the Vulkan SDK's
    endif()
    set(vkbook_shaderc_target)
    if(VKBOOK_SHADERC_COMBINED AND TARGET glslang::SPIRV)
        set(vkbook_shaderc_target ${VKBOOK_SHADERC_COMBINED} glslang::SPIRV glslang::glslang)
        if(TARGET glslang::HLSL)
            list(APPEND vkbook_shaderc_target glslang::HLSL)
        endif()
    elseif(TARGET Vulkan::shaderc_combined)
        set(vkbook_shaderc_target Vulkan::shaderc_combined)
    endif()
    set(vkbook_spirv_cross_target)
    if(TARGET PkgConfig::spirv_cross_c)
        set(vkbook_spirv_cross_target PkgConfig::spirv_cross_c)
    elseif(TARGET spirv-cross-c-shared)
        set(vkbook_spirv_cross_target spirv-cross-c-shared)
    endif()
    if(vkbook_shaderc_target AND vkbook_spirv_cross_target)
        target_link_libraries(vkbook_runtime_shaders INTERFACE ${vkbook_shaderc_target} ${vkbook_spirv_cross_target})
        target_compile_definitions(vkbook_runtime_shaders INTERFACE VKBOOK_RUNTIME_SHADERS=1)
        set(VKBOOK_HAVE_RUNTIME_SHADERS ON)
    else()
        message(STATUS "shaderc or SPIRV-Cross not found: the chapters use the build's SPIR-V only "
                       "(Debian: apt-get install libshaderc-dev glslang-dev libspirv-cross-c-shared-dev)")
    endif()
endif()
add_library(vkbook::runtime_shaders ALIAS vkbook_runtime_shaders)
