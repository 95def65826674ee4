// The shaders a chapter loaded, and live reload: each shader's code handed out by name
// ("chapter-15/light.frag"), and the files it came from watched while the chapter runs.
//
// One table for the whole process, keyed by shader name: the shader modules are made deep inside
// the passes (loadShaderModule), and each of them asks it. A reload is made in three steps, so
// that a failure at any of them leaves the running pipelines as they were:
//   1. pollShaderSources, once a frame: the shaders whose files changed are compiled and checked
//      against their pipelines (common/shaders/shader_interface.hpp); all of them good, it returns them;
//   2. the chapter makes new pipelines for the passes that use them (loadShaderModule hands out
//      the new code now, never reading a file again) while the old pipelines keep drawing;
//   3. finishShaderReload: with no error, the new code is the shaders' code from now on, and the
//      chapter swaps the pipelines once no frame in flight uses the old ones; with an error, the
//      old code stays, and the error is printed and shown (shaderReloadError) until a file changes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/shaders/shader_compiler.hpp"
#include "common/vk/device.hpp"
#include "common/vk/pipeline.hpp"

namespace common {

// The SPIR-V for a shader name: compiled from its source when the source or a file it includes is
// newer than the build's .spv (the book's rule), else the build's .spv. A compile error throws
// InputError "file:line: error: ..." and a compiled shader whose interface no longer fits the
// pipeline the code makes for it "file: interface changed: ..." (exit code 2). Remembers the
// shader for live reload. While a reload is being built, the reload's new code.
std::vector<uint32_t> shaderCode(std::string_view name);

// shaderCode, then vkCreateShaderModule (written out in chapter-06, which introduces it), the
// module named after the shader for graphics debuggers.
VkShaderModule loadShaderModule(const Device& device, std::string_view name);

// A shader module for the time a pipeline is made from it: loadShaderModule, and destroyed when it
// goes out of scope, also when making the pipeline throws (a failed reload leaks nothing). Keeps
// its name and code, so that the constants a pipeline sets can be checked against it.
class ShaderModule {
public:
    ShaderModule(const Device& device, std::string_view name);
    ~ShaderModule() { vkDestroyShaderModule(device_, handle_, nullptr); }
    ShaderModule(const ShaderModule&) = delete;
    ShaderModule& operator=(const ShaderModule&) = delete;
    operator VkShaderModule() const { return handle_; }
    const std::string& name() const { return name_; }
    const std::vector<uint32_t>& code() const { return code_; }

private:
    VkDevice device_;
    std::string name_;
    std::vector<uint32_t> code_;
    VkShaderModule handle_;
};

// common::shaderStage for a ShaderModule, with `specialization` (when given) checked against the
// constants its shader declares: one it sets that the shader does not declare, or with a value of
// another size, throws Failure naming the shader and the constant (Vulkan would ignore the entry
// and leave the constant at its default).
VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits stage, const ShaderModule& module,
                                            const VkSpecializationInfo* specialization = nullptr);

// Remembers a shader a chapter compiled itself (chapter-06), so its edits are noticed too.
void watchShader(std::string_view name);

// A shader a chapter compiled itself (chapter-06): its code kept with it (keepShaderCode), so that
// a pipeline made again does not compile the file again; while a reload is being built, the
// reload's new code. None for a shader not watched.
void keepShaderCode(std::string_view name, const std::vector<uint32_t>& code);
std::optional<std::vector<uint32_t>> watchedShaderCode(std::string_view name);

// The shaders of a reload being built: each compiled and checked, not yet every pipeline's.
struct ShaderReload {
    std::vector<std::string> shaders;
    explicit operator bool() const { return !shaders.empty(); }
    // Whether any of `names` (a pipeline's shaders) is among them.
    bool changed(const std::vector<std::string>& names) const;
};

// Once a frame: looks at the modification times of every file the loaded shaders came from (at
// most every 50 ms) and compiles the shaders whose files changed. Returns them when every
// one compiled and fits its pipelines, and every other loaded shader is good too; the caller then
// makes new pipelines for them and calls finishShaderReload. Else returns none: each failure is
// printed once and kept (shaderReloadError) until its file is fixed. A file missing or changing
// while it is read is looked at again at the next poll; a save that lands during a compile is
// compiled at the next. Also prints the last reload's latency, at the start of the frame after
// the first one that used it.
ShaderReload pollShaderSources();

// Ends the reload pollShaderSources returned: `error` empty when every new pipeline was made (the
// new code becomes the shaders' code), else why not (the old code stays; the error is printed
// and kept until a shader's file changes again).
void finishShaderReload(const std::string& error = {});

// The error of the last failed reload, empty when every shader compiled (the --gui overlay shows it).
const std::string& shaderReloadError();

}  // namespace common
