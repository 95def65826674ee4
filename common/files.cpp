// Files next to the executable, shader modules and the cache directory.
#include "common/files.hpp"

#include <cstdlib>
#include <fstream>
#include <string>

#include "common/check.hpp"

namespace common {

std::filesystem::path executableDir() {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw Failure("cannot locate the running executable (/proc/self/exe): " + ec.message());
    return exe.parent_path();
}

std::vector<char> readFile(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) throw Failure("cannot read '" + path.string() + "'");
    std::streamsize size = file.tellg();
    std::vector<char> bytes(static_cast<size_t>(size));
    file.seekg(0);
    if (!file.read(bytes.data(), size)) throw Failure("cannot read '" + path.string() + "'");
    return bytes;
}

std::string readInputFile(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) throw InputError(path.string() + ": no such file");
    if (std::filesystem::is_directory(status))
        throw InputError(path.string() + ": is a directory, not a file");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(path.string() + ": not a regular file (a device, a pipe or a socket)");
    uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(path.string() + ": cannot read (" + ec.message() + ")");
    if (size > kMaxInputFileBytes)
        throw InputError(path.string() + ": " + std::to_string(size >> 20) + " MiB, more than the " +
                         std::to_string(kMaxInputFileBytes >> 20) + " MiB an input file may have");
    std::ifstream file(path, std::ios::binary);
    std::string text(static_cast<size_t>(size), '\0');
    if (!file || !file.read(text.data(), static_cast<std::streamsize>(size)))
        throw InputError(path.string() + ": cannot read");
    return text;
}

std::vector<char> readSpirv(std::string_view name) {
    std::filesystem::path path = executableDir() / "shaders" / (std::string(name) + ".spv");
    if (!std::filesystem::exists(path))
        throw Failure("missing shader '" + path.string() + "' (is the build complete?)");
    std::vector<char> code = readFile(path);
    if (code.empty() || code.size() % 4 != 0) throw Failure("'" + path.string() + "' is not SPIR-V");
    return code;
}

VkShaderModule loadShaderModule(const Device& device, std::string_view name) {
    std::vector<char> code = readSpirv(name);
    VkShaderModuleCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
        .codeSize = code.size(),
        .pCode = reinterpret_cast<const uint32_t*>(code.data()),  // vector storage is suitably aligned
    };
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device.handle, &info, nullptr, &module));
    return module;
}

std::filesystem::path cacheDir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "vulkan-book-cpp";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "vulkan-book-cpp";
    return {};
}

}  // namespace common
