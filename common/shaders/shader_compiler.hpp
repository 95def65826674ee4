// Shaders compiled while a chapter runs: the book's ShaderCompiler (written out in chapter-06,
// chapter-06/shader_compiler.cpp) for the later chapters. Three modules: this one finds the
// sources and compiles them; shader_interface.hpp checks that compiled code fits its pipeline;
// shader_watch.hpp hands out each shader's code and watches the files for live reload.
//
// The build compiles every shader (cmake/VulkanBook.cmake), so a GLSL error stays a build error.
// When the sources are found at run time -- the build's shaders/ directory, named in
// <bin>/shaders/source-dir.txt, or --shader-dir DIR -- a shader whose source or any file it
// includes is newer than the build's .spv is compiled again with shaderc when the chapter loads
// it, and from then on edits of those files are noticed while the chapter runs
// (shader_watch.hpp). A copied bin/ whose source tree is gone uses the build's SPIR-V.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

// A file a shader is made from, and its modification time taken just before it was read (none:
// it was not there), so that a save landing during a compile is seen by the next look.
struct ShaderFile {
    std::filesystem::path path;
    std::optional<std::filesystem::file_time_type> time;
};
std::optional<std::filesystem::file_time_type> modificationTime(const std::filesystem::path& path);

// The outcome of one shaderc compilation: SPIR-V words, or the compiler's message (every line of
// it "file:line: error: ..."); every file the source included (or looked for), with its time.
struct ShaderCompilation {
    std::vector<uint32_t> spirv;
    std::string error;
    std::vector<ShaderFile> files;  // the source, then what it included
};
ShaderCompilation compileShader(const ShaderSource& source);

// The source and every file it includes: the build's dependency file (glslangValidator --depfile)
// says which, with the build's source directory replaced by this run's; where there is none, or
// it names another source, shaderc's preprocessor follows the #includes (InputError when it fails).
std::vector<std::filesystem::path> shaderFiles(const ShaderSource& source);

// Empty when SPIR-V compiled from `source` fits the pipeline the code makes for the build's
// shader (common/shaders/shader_interface.hpp); else "file: interface changed: why (...)".
std::string checkShaderInterface(const ShaderSource& source, const std::vector<uint32_t>& spirv);

// The words of a SPIR-V file (Failure when it is not one).
std::vector<uint32_t> readSpirv(const std::filesystem::path& path);

// Whether this run has shader sources (shaderSourcesSummary says where).
bool shaderSourcesFound();

// The first line of a compiler message, and how many more errors it has.
std::string firstErrorLine(const std::string& message);

}  // namespace common
