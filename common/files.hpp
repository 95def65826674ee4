// Where a chapter finds its data (next to its executable, whatever the working directory),
// and the per-user cache directory. (Shader modules: common/shader_compiler.hpp.)
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/device.hpp"

namespace common {

// The directory holding the running executable, e.g. <build>/bin: asked of the system
// (GetModuleFileNameW on Windows, _NSGetExecutablePath on macOS, /proc/self/exe on Linux), so it
// does not depend on the working directory or on how the program was started.
std::filesystem::path executableDir();

// The path as UTF-8 text: for messages, and for C libraries that take a char* file name (stb,
// built with STBI_WINDOWS_UTF8 on Windows). path::string() would use the Windows code page there,
// which cannot hold every character a user's path may have.
std::string utf8(const std::filesystem::path& path);

// `path` with a suffix unique to this process: write a file there, then rename it over `path`,
// so that no reader ever sees it half-written.
std::filesystem::path temporarySibling(const std::filesystem::path& path);

// Whether this process may write the file or directory `path` (which must exist).
bool isWritable(const std::filesystem::path& path);

// The whole file; throws Failure naming the file when it cannot be read.
std::vector<char> readFile(const std::filesystem::path& path);

// The largest OBJ, MTL or scene file the loaders read: it is held in memory whole, and parsing
// needs several times its size again.
inline constexpr uintmax_t kMaxInputFileBytes = uintmax_t{2} << 30;  // 2 GiB

// Throws InputError with one line naming the file unless it exists and is a regular file (not a
// directory, a device or a pipe).
void requireInputFile(const std::filesystem::path& path);

// A reader's input file (a model, a material library, a scene), whole. Throws InputError with
// one line naming the file when it does not exist, is a directory or a device or a pipe (which
// could be endless: /dev/zero), is larger than kMaxInputFileBytes, or cannot be read.
std::string readInputFile(const std::filesystem::path& path);

// %LOCALAPPDATA%\vulkan-book-cpp on Windows; elsewhere $XDG_CACHE_HOME/vulkan-book-cpp or
// ~/.cache/vulkan-book-cpp; empty when none of them is set.
std::filesystem::path cacheDir();

}  // namespace common
