// Files next to the executable, shader modules and the cache directory.
#include "common/core/files.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <set>
#include <string>

#if defined(_WIN32)
#include <io.h>
#include <process.h>
#include <windows.h>
#elif defined(__APPLE__)
#include <mach-o/dyld.h>
#include <signal.h>
#include <unistd.h>
#else
#include <signal.h>
#include <unistd.h>
#endif

#include "common/core/check.hpp"

namespace common {

std::filesystem::path executableDir() {
#if defined(_WIN32)
    std::wstring name(MAX_PATH, L'\0');
    for (;;) {  // the path may be longer than MAX_PATH: grow until it fits
        DWORD length = GetModuleFileNameW(nullptr, name.data(), DWORD(name.size()));
        if (length == 0) throw Failure("cannot locate the running executable (GetModuleFileNameW failed)");
        if (length < name.size()) {
            name.resize(length);
            break;
        }
        name.resize(name.size() * 2);
    }
    return std::filesystem::path(name).parent_path();
#elif defined(__APPLE__)
    uint32_t size = 0;
    _NSGetExecutablePath(nullptr, &size);  // asks for the size
    std::string name(size, '\0');
    if (_NSGetExecutablePath(name.data(), &size) != 0)
        throw Failure("cannot locate the running executable (_NSGetExecutablePath failed)");
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::canonical(name.c_str(), ec);  // resolves symlinks
    return (ec ? std::filesystem::path(name.c_str()) : exe).parent_path();
#else
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw Failure("cannot locate the running executable (/proc/self/exe): " + ec.message());
    return exe.parent_path();
#endif
}

std::string utf8(const std::filesystem::path& path) {
    std::u8string text = path.u8string();
    return std::string(text.begin(), text.end());
}

std::filesystem::path temporarySibling(const std::filesystem::path& path) {
#if defined(_WIN32)
    int pid = _getpid();
#else
    int pid = int(getpid());
#endif
    std::filesystem::path temporary = path;
    temporary += ".tmp" + std::to_string(pid);
    return temporary;
}

namespace {
// Never destroyed: a watchdog thread may remove the temporaries while the process exits.
std::mutex& temporariesMutex() {
    static std::mutex* mutex = new std::mutex;
    return *mutex;
}
std::set<std::filesystem::path>& temporaries() {
    static auto* set = new std::set<std::filesystem::path>;
    return *set;
}
}  // namespace

void registerTemporary(const std::filesystem::path& temporary) {
    std::lock_guard lock(temporariesMutex());
    temporaries().insert(temporary);
}

void forgetTemporary(const std::filesystem::path& temporary) {
    std::lock_guard lock(temporariesMutex());
    temporaries().erase(temporary);
}

void removeRegisteredTemporaries() {
    std::lock_guard lock(temporariesMutex());
    std::error_code ec;
    for (const std::filesystem::path& temporary : temporaries()) std::filesystem::remove(temporary, ec);
    temporaries().clear();
}

void removeStaleTemporaries(const std::filesystem::path& path) {
#if defined(_WIN32)
    (void)path;
#else
    std::error_code ec;
    const std::string prefix = utf8(path.filename()) + ".tmp";
    std::filesystem::directory_iterator entries(path.parent_path().empty() ? "." : path.parent_path(), ec);
    if (ec) return;
    for (const auto& entry : entries) {
        std::string name = utf8(entry.path().filename());
        if (!name.starts_with(prefix) || name.size() == prefix.size() || name.size() > prefix.size() + 10)
            continue;
        std::string digits = name.substr(prefix.size());
        if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) continue;
        long pid = std::strtol(digits.c_str(), nullptr, 10);
        if (pid <= 0 || pid == long(getpid())) continue;
        if (kill(pid_t(pid), 0) != 0 && errno == ESRCH) std::filesystem::remove(entry.path(), ec);
    }
#endif
}

bool isWritable(const std::filesystem::path& path) {
#if defined(_WIN32)
    return _waccess(path.c_str(), 2) == 0;  // 2: write permission
#else
    return access(path.c_str(), W_OK) == 0;
#endif
}

std::vector<char> readFile(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) throw Failure("cannot read '" + utf8(path) + "'");
    std::streamsize size = file.tellg();
    std::vector<char> bytes(static_cast<size_t>(size));
    file.seekg(0);
    if (!file.read(bytes.data(), size)) throw Failure("cannot read '" + utf8(path) + "'");
    return bytes;
}

void requireInputFile(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) throw InputError(utf8(path) + ": no such file");
    if (std::filesystem::is_directory(status)) throw InputError(utf8(path) + ": is a directory, not a file");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(utf8(path) + ": not a regular file (a device, a pipe or a socket)");
}

std::string readInputFile(const std::filesystem::path& path) {
    requireInputFile(path);
    std::error_code ec;
    uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(utf8(path) + ": cannot read (" + ec.message() + ")");
    if (size > kMaxInputFileBytes)
        throw InputError(utf8(path) + ": " + std::to_string(size >> 20) + " MiB, more than the " +
                         std::to_string(kMaxInputFileBytes >> 20) + " MiB an input file may have");
    std::ifstream file(path, std::ios::binary);
    std::string text(static_cast<size_t>(size), '\0');
    if (!file || !file.read(text.data(), static_cast<std::streamsize>(size)))
        throw InputError(utf8(path) + ": cannot read");
    return text;
}

std::filesystem::path cacheDir() {
#if defined(_WIN32)
    if (const wchar_t* local = _wgetenv(L"LOCALAPPDATA"); local && *local)
        return std::filesystem::path(local) / "vulkan-book-cpp";
#endif
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "vulkan-book-cpp";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "vulkan-book-cpp";
    return {};
}

}  // namespace common
