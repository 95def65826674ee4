// Shaders compiled while a chapter runs: the book's ShaderCompiler (written out in chapter-06,
// chapter-06/shader_compiler.cpp) for the later chapters, and live reload.
//
// The build compiles every shader (cmake/VulkanBook.cmake), so a GLSL error stays a build error.
// When the sources are found at run time -- the build's shaders/ directory, named in
// <bin>/shaders/source-dir.txt, or --shader-dir DIR -- a shader whose source or any file it
// includes is newer than the build's .spv is compiled again with shaderc when the chapter loads
// it, and from then on edits of those files are noticed while the chapter runs
// (shaderSourcesChanged). A copied bin/ whose source tree is gone uses the build's SPIR-V.
//
// One table for the whole process, keyed by shader name ("chapter-15/light.frag"): the shader
// modules are made deep inside the passes (loadShaderModule), and each of them asks it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/device.hpp"

namespace common {

// Whether this build compiles shaders at run time (shaderc and SPIRV-Cross were found).
bool runtimeShaderCompilation();

// Where this run's shader sources are: --shader-dir DIR when given (InputError when it is not a
// directory, or when this build cannot compile at run time), else the build's. Called once, by
// runChapter, before the chapter starts.
void configureShaderSources(const std::filesystem::path& shaderDir);

// One line, for --help (and at the start of a run with --shader-dir): which applies, runtime
// compilation from where, or the build's SPIR-V and why.
std::string shaderSourcesSummary();

// What the build compiled a shader from (<bin>/shaders/<name>.source): the GLSL file in this
// run's source directory and its macro definitions. `found` is false when runtime compilation is
// off or the file is not there; `spv` is the build's compiled file either way.
struct ShaderSource {
    bool found = false;
    std::filesystem::path glsl;
    std::vector<std::string> defines;  // "NAME" or "NAME=VALUE"
    std::filesystem::path includeDir;  // shaders/include of the same tree
    std::filesystem::path spv;
};
ShaderSource findShaderSource(std::string_view name);

// The outcome of one shaderc compilation: SPIR-V words, or the compiler's message (every line of
// it "file:line: error: ..."); every file the source included, for the modification times.
struct ShaderCompilation {
    std::vector<uint32_t> spirv;
    std::string error;
    std::vector<std::filesystem::path> files;  // the source, then what it included
};
ShaderCompilation compileShader(const ShaderSource& source);

// The source and every file it includes: the build's dependency file (glslangValidator --depfile)
// says which, with the build's source directory replaced by this run's; where there is none, or
// it names another source, shaderc's preprocessor follows the #includes (InputError when it fails).
std::vector<std::filesystem::path> shaderFiles(const ShaderSource& source);

// Empty when SPIR-V compiled from `source` fits the pipeline the code makes for the build's
// shader (the rules: Interface in shader_compiler.cpp); else "file: interface changed: why".
std::string shaderInterfaceChange(const ShaderSource& source, const std::vector<uint32_t>& spirv);

// The SPIR-V for a shader name: compiled from its source when the source or a file it includes is
// newer than the build's .spv (the book's rule), else the build's .spv. A compile error throws
// InputError "file:line: error: ..." and a compiled shader whose interface no longer fits the
// pipeline the code makes for it "file: interface changed: ..." (exit code 2). Remembers the
// shader for shaderSourcesChanged.
std::vector<uint32_t> shaderCode(std::string_view name);

// shaderCode, then vkCreateShaderModule (written out in chapter-06, which introduces it), the
// module named after the shader for graphics debuggers.
VkShaderModule loadShaderModule(const Device& device, std::string_view name);

// Remembers a shader a chapter compiled itself (chapter-06), so its edits are noticed too.
void watchShader(std::string_view name);

// Live reload, called once a frame: looks at the modification times of every file the loaded
// shaders came from (at most four times a second) and recompiles the shaders whose files changed.
// True when at least one changed and every loaded shader now compiles and fits its pipelines: the
// caller then rebuilds its pipelines at this frame boundary, and shaderCode returns the new code.
// While any shader fails, nothing changes and false is returned; each failure is printed once
// and kept (shaderReloadError) until its file is fixed. Also prints the last reload's latency,
// at the start of the frame after the first one that used it.
bool shaderSourcesChanged();

// The error of the last failed reload, empty when every shader compiled (the --gui overlay shows it).
const std::string& shaderReloadError();

}  // namespace common
