// chapter-06: the book's ShaderCompiler with shaderc (shaderc/shaderc.h, its C API).
#include "shader_compiler.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "common/core/check.hpp"
#include "common/core/files.hpp"

#if defined(VKBOOK_RUNTIME_SHADERS)
#include <shaderc/shaderc.h>
#endif

namespace {

#if defined(VKBOOK_RUNTIME_SHADERS)
//> includes
// shaderc asks the program for each #include: "file" next to the including file first, then in
// shaders/include; <file> in shaders/include only (the build's glslangValidator -I rules). The
// result it gets back holds the file's name and text until shaderc releases it.
struct Include {
    shaderc_include_result result{};
    std::string name, text;
};

shaderc_include_result* findInclude(void* includeDir, const char* requested, int type, const char* requesting,
                                    size_t /*depth*/) {
    auto* include = new Include;
    // shaderc's names are UTF-8 (the file names we give it are): u8path reads them so on Windows too.
    std::filesystem::path candidates[] = {
        std::filesystem::u8path(requesting).parent_path() / std::filesystem::u8path(requested),
        *static_cast<std::filesystem::path*>(includeDir) / std::filesystem::u8path(requested)};
    for (size_t i = type == shaderc_include_type_relative ? 0 : 1; i < 2 && include->name.empty(); ++i) {
        std::ifstream file(candidates[i], std::ios::binary);
        if (!file) continue;
        std::ostringstream text;
        text << file.rdbuf();
        include->name = common::utf8(candidates[i]);
        include->text = text.str();
    }
    if (include->name.empty()) include->text = std::string("cannot find include file '") + requested + "'";
    include->result = {include->name.c_str(), include->name.size(), include->text.c_str(),
                       include->text.size(), include};
    return &include->result;
}

void releaseInclude(void* /*includeDir*/, shaderc_include_result* result) {
    delete static_cast<Include*>(result->user_data);
}
//< includes
#endif

std::vector<uint32_t> buildSpirv(const common::ShaderSource& source) {
    std::vector<char> bytes = common::readFile(source.spv);
    if (bytes.empty() || bytes.size() % 4 != 0)
        throw common::Failure("'" + common::utf8(source.spv) + "' is not SPIR-V");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    return words;
}

}  // namespace

//> compile-shader
std::vector<uint32_t> compileShader(const common::ShaderSource& source) {
#if defined(VKBOOK_RUNTIME_SHADERS)
    std::string glsl = common::readInputFile(source.glsl);
    std::string fileName = common::utf8(source.glsl);  // what error messages name
    shaderc_shader_kind kind =
        source.glsl.extension() == ".vert" ? shaderc_glsl_vertex_shader : shaderc_glsl_fragment_shader;

    // A compiler and its options: the macros the build defines, the include lookup, SPIR-V for
    // Vulkan 1.1 like the build's, and debug information when the build has it.
    shaderc_compiler_t compiler = shaderc_compiler_initialize();
    shaderc_compile_options_t options = shaderc_compile_options_initialize();
    for (const std::string& define : source.defines) {  // NAME or NAME=VALUE
        size_t equals = std::min(define.find('='), define.size());
        const char* value = equals < define.size() ? define.c_str() + equals + 1 : "";
        shaderc_compile_options_add_macro_definition(options, define.c_str(), equals, value,
                                                     std::strlen(value));
    }
    std::filesystem::path includeDir = source.includeDir;
    shaderc_compile_options_set_include_callbacks(options, findInclude, releaseInclude, &includeDir);
    shaderc_compile_options_set_target_env(options, shaderc_target_env_vulkan,
                                           shaderc_env_version_vulkan_1_1);
#if defined(VKBOOK_SHADER_DEBUG_INFO)
    shaderc_compile_options_set_generate_debug_info(options);
#endif

    shaderc_compilation_result_t result =
        shaderc_compile_into_spv(compiler, glsl.data(), glsl.size(), kind, fileName.c_str(), "main", options);
    bool compiled = shaderc_result_get_compilation_status(result) == shaderc_compilation_status_success;
    std::string error = compiled ? "" : shaderc_result_get_error_message(result);
    std::vector<uint32_t> spirv(compiled ? shaderc_result_get_length(result) / 4 : 0);
    if (compiled) std::memcpy(spirv.data(), shaderc_result_get_bytes(result), spirv.size() * 4);
    shaderc_result_release(result);
    shaderc_compile_options_release(options);
    shaderc_compiler_release(compiler);
    if (!compiled) throw common::InputError(error.substr(0, error.find('\n')));  // "file:line: error: ..."
    return spirv;
#else
    throw common::Failure(common::utf8(source.glsl) + ": this build has no runtime shader compilation");
#endif
}
//< compile-shader

//> compile-if-changed
std::vector<uint32_t> compileShaderIfChanged(std::string_view name) {
    // Once compiled, or compiled and checked by live reload after an edit, a shader's code is
    // kept: a pipeline made again uses it, never the file again.
    if (std::optional<std::vector<uint32_t>> kept = common::watchedShaderCode(name)) return *kept;
    common::ShaderSource source = common::findShaderSource(name);
    if (!source.found) return buildSpirv(source);  // no sources here: the build's SPIR-V

    // The book compares the GLSL file's time with the SPIR-V file's; we also look at every file it
    // includes (the build's dependency file lists them).
    bool changed = !std::filesystem::exists(source.spv);
    for (const std::filesystem::path& file : common::shaderFiles(source))
        changed =
            changed || std::filesystem::last_write_time(file) > std::filesystem::last_write_time(source.spv);
    common::watchShader(name);  // edits from now on reload the pipeline (main.cpp)
    std::vector<uint32_t> spirv;
    if (changed) {
        std::printf("shaders: compiled %s (its source is newer than the build's SPIR-V)\n",
                    std::string(name).c_str());
        std::fflush(stdout);
        spirv = ::compileShader(source);  // ours, not common::compileShader
        // The pipeline is made for the build's shader: an edit that needs another layout is refused.
        if (std::string change = common::checkShaderInterface(source, spirv); !change.empty())
            throw common::InputError(change);
    } else {
        spirv = buildSpirv(source);
    }
    common::keepShaderCode(name, spirv);
    return spirv;
}
//< compile-if-changed
