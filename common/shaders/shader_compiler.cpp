// Runtime shader compilation (shader_compiler.hpp): where the sources are, shaderc, and the files
// a shader is made from. The shaderc calls are the ones chapter-06/shader_compiler.cpp writes out
// for the book's chapter 6.
#include "common/shaders/shader_compiler.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>
#include <thread>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_interface.hpp"

#if defined(VKBOOK_RUNTIME_SHADERS)
#include <shaderc/shaderc.h>
#endif

namespace common {
namespace {

namespace fs = std::filesystem;

struct Sources {
    fs::path sourceDir;       // empty: no sources this run
    fs::path buildSourceDir;  // the build's shaders/ (<bin>/shaders/source-dir.txt), where its depfiles point
    std::string why;          // why there are none, for shaderSourcesSummary
    bool explicitDir = false;
};
Sources gSources;

#if defined(VKBOOK_RUNTIME_SHADERS)

//> include-callback
// #include "file" is looked up next to the including file, then in shaders/include;
// #include <file> in shaders/include only: glslangValidator's rules with -I shaders/include.
struct IncludeContext {
    fs::path includeDir;
    std::vector<ShaderFile>* files;
};
struct IncludeResult {
    shaderc_include_result result{};
    std::string name, content;
};

shaderc_include_result* resolveInclude(void* userData, const char* requested, int type,
                                       const char* requesting, size_t /*depth*/) {
    auto* context = static_cast<IncludeContext*>(userData);
    auto* include = new IncludeResult;
    std::vector<fs::path> candidates;
    if (type == shaderc_include_type_relative)
        candidates.push_back(fs::u8path(requesting).parent_path() / fs::u8path(requested));  // UTF-8 names
    candidates.push_back(context->includeDir / fs::u8path(requested));
    // Every place looked at is watched: a file that appears in an earlier one is used from then on.
    for (const fs::path& candidate : candidates) {
        std::optional<fs::file_time_type> time = modificationTime(candidate);  // before reading
        context->files->push_back({candidate, time});
        std::ifstream file(candidate, std::ios::binary);
        if (!file) continue;
        std::ostringstream text;
        text << file.rdbuf();
        include->name = utf8(candidate);
        include->content = text.str();
        break;
    }
    if (include->name.empty()) include->content = std::string("cannot find include file '") + requested + "'";
    include->result = {include->name.c_str(), include->name.size(), include->content.c_str(),
                       include->content.size(), include};
    return &include->result;
}

void releaseInclude(void* /*userData*/, shaderc_include_result* result) {
    delete static_cast<IncludeResult*>(result->user_data);
}
//< include-callback

shaderc_shader_kind shaderKind(const fs::path& glsl) {
    std::string extension = glsl.extension().string();
    if (extension == ".vert") return shaderc_glsl_vertex_shader;
    if (extension == ".frag") return shaderc_glsl_fragment_shader;
    if (extension == ".comp") return shaderc_glsl_compute_shader;
    if (extension == ".geom") return shaderc_glsl_geometry_shader;  // chapter-16's shadow pass
    throw Failure("'" + utf8(glsl) + "': unknown shader stage (expected .vert, .frag, .geom or .comp)");
}

#endif  // VKBOOK_RUNTIME_SHADERS

}  // namespace

std::optional<fs::file_time_type> modificationTime(const fs::path& path) {
    std::error_code error;
    fs::file_time_type time = fs::last_write_time(path, error);
    if (error) return std::nullopt;
    return time;
}

std::vector<uint32_t> readSpirv(const fs::path& path) {
    std::vector<char> bytes = readFile(path);
    if (bytes.empty() || bytes.size() % 4 != 0) throw Failure("'" + utf8(path) + "' is not SPIR-V");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    return words;
}

std::string firstErrorLine(const std::string& message) {
    size_t end = message.find('\n');
    std::string line = message.substr(0, end);
    size_t more = 0;
    for (size_t at = message.find(": error:", end); at != std::string::npos;
         at = message.find(": error:", at + 1))
        ++more;
    if (more > 0) line += " (and " + std::to_string(more) + " more error" + (more > 1 ? "s" : "") + ")";
    return line;
}

bool runtimeShaderCompilation() {
#if defined(VKBOOK_RUNTIME_SHADERS)
    return true;
#else
    return false;
#endif
}

void configureShaderSources(const fs::path& shaderDir) {
    gSources = {};
    if (!shaderDir.empty() && !runtimeShaderCompilation())
        throw InputError(
            "--shader-dir: this build has no runtime shader compilation (built without shaderc)");
    if (!shaderDir.empty() && !fs::is_directory(shaderDir))
        throw InputError("--shader-dir '" + utf8(shaderDir) + "' is not a directory");
    if (!runtimeShaderCompilation()) {
        gSources.why = "this build has no runtime compilation (built without shaderc)";
        return;
    }
    fs::path recorded = executableDir() / "shaders" / "source-dir.txt";
    std::ifstream file(recorded);
    std::string line;
    if (file && std::getline(file, line)) gSources.buildSourceDir = fs::u8path(line);
    if (!shaderDir.empty()) {
        gSources.sourceDir = fs::absolute(shaderDir);
        gSources.explicitDir = true;
    } else if (line.empty()) {
        gSources.why = "no " + utf8(recorded);
    } else if (!fs::is_directory(gSources.buildSourceDir)) {
        gSources.why = "the build's sources (" + line + ") are not there";
    } else {
        gSources.sourceDir = gSources.buildSourceDir;
    }
}

bool shaderSourcesFound() {
    return !gSources.sourceDir.empty();
}

std::string shaderSourcesSummary() {
    if (!gSources.sourceDir.empty())
        return "shaders: compiled at run time from " + utf8(gSources.sourceDir) +
               " when newer than the build's SPIR-V, reloaded when edited";
    return "shaders: the build's SPIR-V (" + gSources.why + ")";
}

ShaderSource findShaderSource(std::string_view name) {
    ShaderSource source;
    fs::path compiled = executableDir() / "shaders" / fs::u8path(std::string(name));
    source.spv = fs::path(compiled).concat(".spv");
    if (gSources.sourceDir.empty()) return source;
    std::ifstream manifest(fs::path(compiled).concat(".source"));
    std::string relative, define;
    if (!manifest || !std::getline(manifest, relative) || relative.empty()) return source;
    while (std::getline(manifest, define))
        if (!define.empty()) source.defines.push_back(define);
    source.glsl = gSources.sourceDir / fs::u8path(relative);
    source.includeDir = gSources.sourceDir / "include";
    source.found = fs::is_regular_file(source.glsl);
    return source;
}

namespace {

// shaderc on one source: SPIR-V, or only the preprocessor's work (which is what finds the files
// it includes, at a fraction of a compile's time).
ShaderCompilation runShaderc(const ShaderSource& source, bool preprocessOnly) {
    ShaderCompilation compilation;
#if defined(VKBOOK_RUNTIME_SHADERS)
    std::optional<fs::file_time_type> time = modificationTime(source.glsl);  // before reading
    std::string text = readInputFile(source.glsl);
    compilation.files.push_back({source.glsl, time});
    // A test's slow compile (tests/chapters/live_reload.sh, "during-compile"): an edit saved while a
    // compile runs must be compiled next. The line says the file has been read, so that the test
    // saves its second edit during the compile, not before it.
    if (const char* delay = std::getenv("VKBOOK_TEST_COMPILE_DELAY_MS"); delay && !preprocessOnly) {
        std::printf("test-event: compiling %s (read, delayed)\n", utf8(source.glsl).c_str());
        std::fflush(stdout);
        std::this_thread::sleep_for(std::chrono::milliseconds(std::atoi(delay)));
    }
    // One compiler for the whole run: glslang then sets up its built-in symbol tables once, not at
    // every compile (most of a small shader's compile time).
    static shaderc_compiler_t compiler = shaderc_compiler_initialize();
    shaderc_compile_options_t options = shaderc_compile_options_initialize();
    for (const std::string& define : source.defines) {
        size_t equals = define.find('=');
        std::string name = define.substr(0, equals);
        std::string value = equals == std::string::npos ? "" : define.substr(equals + 1);
        shaderc_compile_options_add_macro_definition(options, name.data(), name.size(), value.data(),
                                                     value.size());
    }
    shaderc_compile_options_set_target_env(options, shaderc_target_env_vulkan,
                                           shaderc_env_version_vulkan_1_1);
    shaderc_compile_options_set_target_spirv(options, shaderc_spirv_version_1_3);
#if defined(VKBOOK_SHADER_DEBUG_INFO)
    shaderc_compile_options_set_generate_debug_info(options);
#endif
    IncludeContext includes{source.includeDir, &compilation.files};
    shaderc_compile_options_set_include_callbacks(options, resolveInclude, releaseInclude, &includes);
    std::string fileName = utf8(source.glsl);
    shaderc_compilation_result_t result =
        preprocessOnly ? shaderc_compile_into_preprocessed_text(compiler, text.data(), text.size(),
                                                                shaderKind(source.glsl), fileName.c_str(),
                                                                "main", options)
                       : shaderc_compile_into_spv(compiler, text.data(), text.size(), shaderKind(source.glsl),
                                                  fileName.c_str(), "main", options);
    if (shaderc_result_get_compilation_status(result) != shaderc_compilation_status_success) {
        compilation.error = shaderc_result_get_error_message(result);
        if (compilation.error.empty()) compilation.error = fileName + ": shaderc failed";
    } else if (!preprocessOnly) {
        const char* bytes = shaderc_result_get_bytes(result);
        compilation.spirv.resize(shaderc_result_get_length(result) / 4);
        std::memcpy(compilation.spirv.data(), bytes, compilation.spirv.size() * 4);
    }
    shaderc_result_release(result);
    shaderc_compile_options_release(options);
#else
    (void)preprocessOnly;
    compilation.error = utf8(source.glsl) + ": this build has no runtime shader compilation";
#endif
    return compilation;
}

}  // namespace

ShaderCompilation compileShader(const ShaderSource& source) {
    return runShaderc(source, false);
}

std::vector<fs::path> shaderFiles(const ShaderSource& source) {
    // The build's depfile (glslangValidator --depfile: "out.spv: source include..."), with the
    // build's source directory replaced by this run's: reading it costs nothing, where running
    // the preprocessor on every shader would add a good part of a second to every start.
    std::ifstream depfile(fs::path(source.spv).concat(".d"), std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(depfile)), std::istreambuf_iterator<char>());
    size_t colon = text.find(": ");
    std::string buildDir = utf8(gSources.buildSourceDir);
    std::vector<fs::path> files;
    if (colon != std::string::npos && !buildDir.empty()) {
        std::string word;
        auto add = [&] {
            if (word.empty() || word == "\\") return word.clear();
            if (word.starts_with(buildDir + "/"))
                files.push_back(gSources.sourceDir / fs::u8path(word.substr(buildDir.size() + 1)));
            else
                files.push_back(fs::u8path(word));
            word.clear();
        };
        for (size_t i = colon + 2; i < text.size(); ++i) {
            char c = text[i];
            if (c == '\\' && i + 1 < text.size() && text[i + 1] == ' ')
                word += text[++i];  // an escaped space
            else if (c == ' ' || c == '\n' || c == '\r' || c == '\t')
                add();
            else
                word += c;
        }
        add();
    }
    if (!files.empty() && files.front() == source.glsl) return files;
    // No depfile, or another source than the build's: the preprocessor follows the #includes.
    ShaderCompilation preprocessed = runShaderc(source, true);
    if (!preprocessed.error.empty()) throw InputError(firstErrorLine(preprocessed.error));
    files.clear();
    for (const ShaderFile& file : preprocessed.files) files.push_back(file.path);
    return files;
}

std::string checkShaderInterface(const ShaderSource& source, const std::vector<uint32_t>& spirv) {
    if (!fs::exists(source.spv)) return {};
    std::string change = shaderInterfaceChange(readSpirv(source.spv), spirv);
    if (change.empty()) return {};
    return utf8(source.glsl) + ": interface changed: " + change +
           " (a reload changes shader code only; a new interface needs the C++ that makes the pipeline)";
}

}  // namespace common
