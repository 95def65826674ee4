# Cross-compiling for 64-bit Windows with MinGW-w64 (Debian: g++-mingw-w64-x86-64-posix), used by
# the windows-cross preset (CMakePresets.json, scripts/windows-cross.sh). The executables run here
# under Wine, whose winevulkan hands Vulkan to the host's driver (lavapipe).
#
# VKBOOK_MINGW_SYSROOT holds what the MinGW compiler cannot find on its own: the Vulkan headers
# and an import library for vulkan-1.dll. Never the host's /usr/include: glibc's headers break a
# MinGW build. The other libraries come through FetchContent (cmake/Dependencies.cmake).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(VKBOOK_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${VKBOOK_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${VKBOOK_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${VKBOOK_MINGW_TRIPLE}-windres)
set(CMAKE_AR ${VKBOOK_MINGW_TRIPLE}-ar CACHE FILEPATH "")
set(CMAKE_RANLIB ${VKBOOK_MINGW_TRIPLE}-ranlib CACHE FILEPATH "")

if(NOT VKBOOK_MINGW_SYSROOT AND DEFINED ENV{VKBOOK_MINGW_SYSROOT})
    set(VKBOOK_MINGW_SYSROOT $ENV{VKBOOK_MINGW_SYSROOT})
endif()
set(VKBOOK_MINGW_SYSROOT "${VKBOOK_MINGW_SYSROOT}" CACHE PATH "Vulkan headers and vulkan-1 import library for MinGW")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES VKBOOK_MINGW_SYSROOT)
set(CMAKE_FIND_ROOT_PATH /usr/${VKBOOK_MINGW_TRIPLE} ${VKBOOK_MINGW_SYSROOT})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)  # host programs: glslangValidator
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# pkg-config must not find the host's packages (stb then comes through FetchContent).
set(ENV{PKG_CONFIG_LIBDIR} ${VKBOOK_MINGW_SYSROOT}/lib/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")

# One .exe with no MinGW runtime DLLs beside it (libstdc++, libgcc, winpthread linked in).
set(CMAKE_EXE_LINKER_FLAGS_INIT -static)

# Programs built here run under Wine: the build-time scene generator and every test. The prefix
# lives in the build tree.
set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/wine-run.sh)
