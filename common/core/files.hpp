// Where a chapter finds its data (next to its executable, whatever the working directory),
// and the per-user cache directory. (Shader modules: common/shaders/shader_compiler.hpp.)
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

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

// The temporaries being written: a run cut short by Ctrl+C or SIGTERM (common/app/run_control.hpp)
// removes the registered ones before it exits. Safe to call from several threads.
void registerTemporary(const std::filesystem::path& temporary);
void forgetTemporary(const std::filesystem::path& temporary);
void removeRegisteredTemporaries();
// temporarySibling(target), registered while this lives.
struct RegisteredTemporary {
    std::filesystem::path path;
    explicit RegisteredTemporary(const std::filesystem::path& target) : path(temporarySibling(target)) {
        registerTemporary(path);
    }
    ~RegisteredTemporary() { forgetTemporary(path); }
    RegisteredTemporary(const RegisteredTemporary&) = delete;
    RegisteredTemporary& operator=(const RegisteredTemporary&) = delete;
};
// Removes the temporaries of `path` that processes no longer running left behind (killed with
// SIGKILL, or a machine that lost power, halfway through writing): "NAME.tmpPID" beside it.
// Where a process cannot be asked whether it runs (Windows), nothing is removed.
void removeStaleTemporaries(const std::filesystem::path& path);

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
