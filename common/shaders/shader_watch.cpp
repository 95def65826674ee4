// The shaders a chapter loaded, and live reload (shader_watch.hpp).
#include "common/shaders/shader_watch.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <map>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_interface.hpp"
#include "common/vk/debug_names.hpp"

namespace common {
namespace {

namespace fs = std::filesystem;

// A shader a chapter loaded: where its code came from, and the files to watch.
struct Entry {
    ShaderSource source;
    std::vector<uint32_t> spirv;                   // what shaderCode returns now
    std::vector<uint32_t> reference;               // the build's: the interface its pipeline was made for
    std::vector<ShaderFile> files;                 // each file it came from, and its time when read
    std::optional<std::vector<uint32_t>> pending;  // compiled and checked, not yet every pipeline's
    std::string error;                             // why the last compile of it failed
    bool retry = false;  // its reload's pipelines could not be made: compiled again with the next change
};

struct Watch {
    std::map<std::string, Entry, std::less<>> shaders;
    bool running = false;   // the frame loop has started polling
    bool building = false;  // between a poll that returned a reload and finishShaderReload
    std::chrono::steady_clock::time_point lastPoll{};
    std::string buildError;   // why the last reload's pipelines could not be made
    std::string reloadError;  // every shader's error, then buildError
    // The reload being built or just made, reported at the next frame: its shaders, the edit's
    // time, the compile's and the pipelines' durations.
    std::string reloaded;
    fs::file_time_type editTime{};
    std::chrono::steady_clock::time_point compiled{};
    double compileMs = 0.0, pipelinesMs = 0.0;
};
Watch gWatch;

// How often the files' times are looked at: a few dozen stat calls, some microseconds each.
constexpr std::chrono::milliseconds kPollInterval{50};

std::vector<ShaderFile> withTimes(const std::vector<fs::path>& files) {
    std::vector<ShaderFile> result;
    for (const fs::path& file : files) result.push_back({file, modificationTime(file)});
    return result;
}

std::string withNewline(const std::string& text) {
    return text.ends_with('\n') ? text : text + "\n";
}

// Compiled code against the build's; the error message, or empty.
std::string checkInterface(const Entry& entry, const std::vector<uint32_t>& spirv) {
    if (entry.reference.empty()) return {};
    std::string change = shaderInterfaceChange(entry.reference, spirv);
    if (change.empty()) return {};
    return utf8(entry.source.glsl) + ": interface changed: " + change +
           " (a reload changes shader code only; a new interface needs the C++ that makes the pipeline)";
}

void collectErrors() {
    gWatch.reloadError.clear();
    for (const auto& [name, entry] : gWatch.shaders)
        if (!entry.error.empty()) gWatch.reloadError += withNewline(entry.error);
    if (!gWatch.buildError.empty()) gWatch.reloadError += withNewline(gWatch.buildError);
}

}  // namespace

std::vector<uint32_t> shaderCode(std::string_view name) {
    if (auto known = gWatch.shaders.find(name); known != gWatch.shaders.end()) {
        if (gWatch.building && known->second.pending) return *known->second.pending;
        if (!known->second.spirv.empty()) return known->second.spirv;
    }
    Entry entry;
    entry.source = findShaderSource(name);
    bool built = fs::exists(entry.source.spv);
    if (built) entry.reference = readSpirv(entry.source.spv);
    if (!entry.source.found) {
        if (!built) throw Failure("missing shader '" + utf8(entry.source.spv) + "' (is the build complete?)");
        entry.spirv = entry.reference;
        return gWatch.shaders.insert_or_assign(std::string(name), std::move(entry)).first->second.spirv;
    }
    // The book's rule, followed through the included files: compile when a file is newer than
    // the build's SPIR-V. shaderFiles tells which files those are; their times are taken now,
    // before anything is read.
    entry.files = withTimes(shaderFiles(entry.source));
    bool newer = !built;
    if (built) {
        std::optional<fs::file_time_type> spvTime = modificationTime(entry.source.spv);
        for (const ShaderFile& file : entry.files)
            newer = newer || !spvTime || (file.time && *file.time > *spvTime);
    }
    if (newer) {
        ShaderCompilation compilation = compileShader(entry.source);
        std::string error = compilation.error.empty() ? checkInterface(entry, compilation.spirv)
                                                      : firstErrorLine(compilation.error);
        if (!error.empty() && gWatch.running && built) {
            // Loaded for the first time while the chapter runs (the lab switching its G-buffer
            // layout): the build's code keeps it going, and the error is shown like a reload's
            // until the file is fixed.
            std::fprintf(stderr, "shaders: %s uses the build's SPIR-V: %s\n", std::string(name).c_str(),
                         error.c_str());
            std::fflush(stderr);
            entry.error = error;
            entry.files = std::move(compilation.files);
            entry.spirv = entry.reference;
            auto& stored = gWatch.shaders.insert_or_assign(std::string(name), std::move(entry)).first->second;
            collectErrors();
            return stored.spirv;
        }
        if (!error.empty()) throw InputError(error);
        std::printf("shaders: compiled %s (its source is newer than the build's SPIR-V)\n",
                    std::string(name).c_str());
        std::fflush(stdout);
        entry.spirv = std::move(compilation.spirv);
        entry.files = std::move(compilation.files);
    } else {
        entry.spirv = entry.reference;
    }
    return gWatch.shaders.insert_or_assign(std::string(name), std::move(entry)).first->second.spirv;
}

namespace {

VkShaderModule createModule(const Device& device, std::string_view name, const std::vector<uint32_t>& code) {
    VkShaderModuleCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
        .codeSize = code.size() * sizeof(uint32_t),
        .pCode = code.data(),
    };
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device.handle, &info, nullptr, &module));
    nameObject(device.handle, module, std::string(name));
    return module;
}

}  // namespace

VkShaderModule loadShaderModule(const Device& device, std::string_view name) {
    return createModule(device, name, shaderCode(name));  // the build's, from a newer source, or a reload's
}

ShaderModule::ShaderModule(const Device& device, std::string_view name)
    : device_(device.handle),
      name_(name),
      code_(shaderCode(name)),
      handle_(createModule(device, name, code_)) {}

VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits stage, const ShaderModule& module,
                                            const VkSpecializationInfo* specialization) {
    if (specialization) {
        std::string mismatch = specializationMismatch(module.code(), *specialization);
        if (!mismatch.empty()) throw Failure(module.name() + ": " + mismatch);
    }
    return shaderStage(stage, static_cast<VkShaderModule>(module), specialization);
}

void watchShader(std::string_view name) {
    if (!shaderSourcesFound() || gWatch.shaders.count(name)) return;
    Entry entry;
    entry.source = findShaderSource(name);
    if (!entry.source.found) return;
    if (fs::exists(entry.source.spv)) entry.reference = readSpirv(entry.source.spv);
    entry.files = withTimes(shaderFiles(entry.source));
    gWatch.shaders.emplace(std::string(name), std::move(entry));
}

void keepShaderCode(std::string_view name, const std::vector<uint32_t>& code) {
    if (auto known = gWatch.shaders.find(name); known != gWatch.shaders.end()) known->second.spirv = code;
}

std::optional<std::vector<uint32_t>> watchedShaderCode(std::string_view name) {
    auto known = gWatch.shaders.find(name);
    if (known == gWatch.shaders.end()) return std::nullopt;
    if (gWatch.building && known->second.pending) return known->second.pending;
    if (!known->second.spirv.empty()) return known->second.spirv;
    return std::nullopt;
}

bool ShaderReload::changed(const std::vector<std::string>& names) const {
    for (const std::string& name : names)
        if (std::find(shaders.begin(), shaders.end(), name) != shaders.end()) return true;
    return false;
}

ShaderReload pollShaderSources() {
    if (!shaderSourcesFound()) return {};
    gWatch.running = true;
    // The last reload's report, now that a frame has been recorded and submitted with it: how long
    // from the edit (the newest changed file's modification time) to that frame.
    if (!gWatch.reloaded.empty()) {
        auto latency =
            std::chrono::duration<double, std::milli>(fs::file_time_type::clock::now() - gWatch.editTime);
        std::printf(
            "shaders: reloaded %s (compiled in %.0f ms, pipelines made in %.0f ms; first frame with it "
            "%.0f ms after the edit)\n",
            gWatch.reloaded.c_str(), gWatch.compileMs, gWatch.pipelinesMs, latency.count());
        std::fflush(stdout);
        gWatch.reloaded.clear();
    }
    auto now = std::chrono::steady_clock::now();
    if (now - gWatch.lastPoll < kPollInterval) return {};
    gWatch.lastPoll = now;

    // Which shaders' files changed since they were read. While the source itself is missing (an
    // editor replacing it), the shader is looked at again on the next poll.
    std::vector<std::pair<const std::string*, Entry*>> changed;
    fs::file_time_type editTime = fs::file_time_type::min();
    for (auto& [name, entry] : gWatch.shaders) {
        if (!entry.source.found) continue;
        bool edited = false;
        for (const ShaderFile& file : entry.files) {
            std::optional<fs::file_time_type> current = modificationTime(file.path);
            if (current != file.time) {
                edited = true;
                if (current) editTime = std::max(editTime, *current);
            }
        }
        if (edited && modificationTime(entry.source.glsl)) changed.emplace_back(&name, &entry);
    }
    if (changed.empty()) return {};
    // Shaders whose last reload could not be made go with any change (their files were seen).
    for (auto& [name, entry] : gWatch.shaders)
        if (entry.retry &&
            std::none_of(changed.begin(), changed.end(), [&](const auto& c) { return c.second == &entry; }))
            changed.emplace_back(&name, &entry);
    if (editTime == fs::file_time_type::min())
        editTime = fs::file_time_type::clock::now();  // a file went away

    gWatch.buildError.clear();
    for (auto& [name, entry] : changed) {
        ShaderCompilation compilation;
        std::string checked;
        try {
            compilation = compileShader(entry->source);
            if (compilation.error.empty()) checked = checkInterface(*entry, compilation.spirv);
        } catch (const std::exception& e) {
            // The file went away or changed size while it was read: its times stay as they were,
            // so the next poll compiles it again. Said once, not at every poll.
            std::string error = std::string(e.what());
            if (error != entry->error)
                std::fprintf(stderr, "shaders: %s did not reload: %s\n", name->c_str(), error.c_str());
            entry->error = error;
            continue;
        }
        entry->files = std::move(compilation.files);  // the times taken before each file was read
        entry->retry = false;
        entry->error = compilation.error.empty() ? checked : compilation.error;
        if (entry->error.empty())
            entry->pending = std::move(compilation.spirv);
        else
            std::fprintf(stderr, "shaders: %s did not reload: %s", name->c_str(),
                         withNewline(entry->error).c_str());
    }
    // Every shader must be good before any pipeline changes.
    collectErrors();
    if (!gWatch.reloadError.empty()) {
        std::fflush(stderr);
        return {};
    }
    ShaderReload reload;
    for (auto& [name, entry] : gWatch.shaders)
        if (entry.pending) reload.shaders.push_back(name);
    if (reload.shaders.empty()) return {};
    gWatch.building = true;
    gWatch.editTime = editTime;
    gWatch.compiled = std::chrono::steady_clock::now();
    gWatch.compileMs = std::chrono::duration<double, std::milli>(gWatch.compiled - now).count();
    return reload;
}

void finishShaderReload(const std::string& error) {
    gWatch.building = false;
    std::string names;
    for (auto& [name, entry] : gWatch.shaders)
        if (entry.pending) {
            if (error.empty()) {
                entry.spirv = std::move(*entry.pending);
            } else {
                entry.retry = true;  // its edit is not lost: compiled again with the next change
            }
            entry.pending.reset();
            names += (names.empty() ? "" : ", ") + name;
        }
    if (!error.empty()) {
        gWatch.buildError = "shaders: " + names + " did not reload: " + error;
        std::fprintf(stderr, "%s", withNewline(gWatch.buildError).c_str());
        std::fflush(stderr);
        collectErrors();
        return;
    }
    gWatch.reloaded = names;
    gWatch.pipelinesMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - gWatch.compiled).count();
}

const std::string& shaderReloadError() {
    return gWatch.reloadError;
}

}  // namespace common
