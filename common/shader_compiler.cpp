// Runtime shader compilation and live reload (shader_compiler.hpp). The shaderc calls are the
// ones chapter-06/shader_compiler.cpp writes out for the book's chapter 6.
#include "common/shader_compiler.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <system_error>
#include <tuple>

#include "common/check.hpp"
#include "common/debug_names.hpp"
#include "common/files.hpp"

#if defined(VKBOOK_RUNTIME_SHADERS)
#include <shaderc/shaderc.h>
#include <spirv_cross/spirv_cross_c.h>
#endif

namespace common {
namespace {

namespace fs = std::filesystem;

// A shader a chapter loaded: where its code came from, and the files to watch.
struct Entry {
    ShaderSource source;
    std::vector<uint32_t> spirv;                   // what shaderCode returns now
    std::vector<uint32_t> reference;               // the build's: the interface its pipeline was made for
    std::map<fs::path, fs::file_time_type> files;  // each file it came from, and its time when read
    std::optional<std::vector<uint32_t>> pending;  // compiled, waiting for the other changed ones
    std::string error;                             // why the last compile of it failed
};

struct State {
    fs::path sourceDir;       // empty: no sources this run
    fs::path buildSourceDir;  // the build's shaders/ (<bin>/shaders/source-dir.txt), where its depfiles point
    std::string why;          // why there are none, for shaderSourcesSummary
    bool explicitDir = false;
    std::map<std::string, Entry, std::less<>> shaders;
    std::chrono::steady_clock::time_point lastPoll{};
    std::string reloadError;
    // The reload just made, reported at the next frame: its shaders, the edit's time, the compile's.
    std::string reloaded;
    fs::file_time_type editTime{};
    double compileMs = 0.0;
};
State gState;

std::optional<fs::file_time_type> modified(const fs::path& path) {
    std::error_code error;
    fs::file_time_type time = fs::last_write_time(path, error);
    if (error) return std::nullopt;
    return time;
}

std::vector<uint32_t> readWords(const fs::path& path) {
    std::vector<char> bytes = readFile(path);
    if (bytes.empty() || bytes.size() % 4 != 0) throw Failure("'" + utf8(path) + "' is not SPIR-V");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    return words;
}

// The first line of a compiler message, and how many more errors it has.
std::string firstLine(const std::string& message) {
    size_t end = message.find('\n');
    std::string line = message.substr(0, end);
    size_t more = 0;
    for (size_t at = message.find(": error:", end); at != std::string::npos;
         at = message.find(": error:", at + 1))
        ++more;
    if (more > 0) line += " (and " + std::to_string(more) + " more error" + (more > 1 ? "s" : "") + ")";
    return line;
}

#if defined(VKBOOK_RUNTIME_SHADERS)

//> include-callback
// #include "file" is looked up next to the including file, then in shaders/include;
// #include <file> in shaders/include only: glslangValidator's rules with -I shaders/include.
struct IncludeContext {
    fs::path includeDir;
    std::vector<fs::path>* files;
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
        candidates.push_back(fs::path(requesting).parent_path() / fs::u8path(requested));
    candidates.push_back(context->includeDir / fs::u8path(requested));
    for (const fs::path& candidate : candidates) {
        std::ifstream file(candidate, std::ios::binary);
        if (!file) continue;
        std::ostringstream text;
        text << file.rdbuf();
        include->name = utf8(candidate);
        include->content = text.str();
        context->files->push_back(candidate);
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
    throw Failure("'" + utf8(glsl) + "': unknown shader stage (expected .vert, .frag or .comp)");
}

// The interface of a SPIR-V module that its pipeline depends on, as SPIRV-Cross reflects it: the
// descriptors (set, binding, kind) and push constant bytes, the inputs and outputs by location and
// type. The pipeline's layout and neighbouring stages were made for the build's shader, so that
// one is taken with everything it declares; a recompiled one with what its code uses. It fits when
// it uses no descriptor the build's declares not (or declares as another kind), no more push
// constant bytes, reads no input location the build's does not declare (with that type), and still
// writes every output location the build's declares (with that type).
struct Interface {
    std::map<std::pair<unsigned, unsigned>, std::string> descriptors;  // (set, binding) -> kind
    size_t pushConstantBytes = 0;
    std::map<unsigned, std::string> inputs, outputs;  // location -> type
};

std::string typeName(spvc_compiler compiler, spvc_type_id id) {
    spvc_type type = spvc_compiler_get_type_handle(compiler, id);
    static const char* kBase[] = {"unknown", "void",   "bool",          "int8",    "uint8",
                                  "int16",   "uint16", "int",           "uint",    "int64",
                                  "uint64",  "atomic", "float16",       "float",   "double",
                                  "struct",  "image",  "sampled image", "sampler", "accel"};
    unsigned base = unsigned(spvc_type_get_basetype(type));
    std::string name = base < std::size(kBase) ? kBase[base] : "other";
    unsigned columns = spvc_type_get_columns(type), size = spvc_type_get_vector_size(type);
    if (columns > 1) return name + " mat" + std::to_string(columns) + "x" + std::to_string(size);
    if (size > 1) return name + " vec" + std::to_string(size);
    return name;
}

Interface reflect(const std::vector<uint32_t>& spirv, bool usedOnly) {
    Interface result;
    spvc_context context = nullptr;
    if (spvc_context_create(&context) != SPVC_SUCCESS) throw Failure("SPIRV-Cross: no context");
    struct Guard {
        spvc_context context;
        ~Guard() { spvc_context_destroy(context); }
    } guard{context};
    spvc_parsed_ir ir = nullptr;
    spvc_compiler compiler = nullptr;
    if (spvc_context_parse_spirv(context, spirv.data(), spirv.size(), &ir) != SPVC_SUCCESS ||
        spvc_context_create_compiler(context, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                     &compiler) != SPVC_SUCCESS)
        throw Failure(std::string("SPIRV-Cross: ") + spvc_context_get_last_error_string(context));
    spvc_set active = nullptr;
    spvc_resources used = nullptr, declared = nullptr;
    spvc_compiler_get_active_interface_variables(compiler, &active);
    spvc_compiler_create_shader_resources_for_active_variables(compiler, &used, active);
    spvc_compiler_create_shader_resources(compiler, &declared);
    auto each = [](spvc_resources resources, spvc_resource_type type, auto&& body) {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources, type, &list, &count);
        for (size_t i = 0; i < count; ++i) body(list[i]);
    };
    const std::pair<spvc_resource_type, const char*> kinds[] = {
        {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, "uniform buffer"},
        {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, "storage buffer"},
        {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, "combined image sampler"},
        {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, "sampled image"},
        {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, "sampler"},
        {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, "storage image"},
        {SPVC_RESOURCE_TYPE_SUBPASS_INPUT, "input attachment"},
    };
    spvc_resources resources = usedOnly ? used : declared;
    for (const auto& [type, kind] : kinds)
        each(resources, type, [&](const spvc_reflected_resource& resource) {
            unsigned set = spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationDescriptorSet);
            unsigned binding = spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationBinding);
            result.descriptors[{set, binding}] = kind;
        });
    each(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, [&](const spvc_reflected_resource& resource) {
        size_t size = 0;
        spvc_compiler_get_declared_struct_size(
            compiler, spvc_compiler_get_type_handle(compiler, resource.base_type_id), &size);
        result.pushConstantBytes = std::max(result.pushConstantBytes, size);
    });
    each(resources, SPVC_RESOURCE_TYPE_STAGE_INPUT, [&](const spvc_reflected_resource& resource) {
        unsigned location = spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationLocation);
        result.inputs[location] = typeName(compiler, resource.type_id);
    });
    each(declared, SPVC_RESOURCE_TYPE_STAGE_OUTPUT, [&](const spvc_reflected_resource& resource) {
        unsigned location = spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationLocation);
        result.outputs[location] = typeName(compiler, resource.type_id);
    });
    return result;
}

// Empty when `now` fits the pipeline made for `before`; else what does not, in one phrase.
std::string interfaceChange(const Interface& before, const Interface& now) {
    for (const auto& [slot, kind] : now.descriptors) {
        auto old = before.descriptors.find(slot);
        std::string where = "set " + std::to_string(slot.first) + " binding " + std::to_string(slot.second);
        if (old == before.descriptors.end())
            return "it uses " + where + " (" + kind +
                   "), which the shader its pipeline was made for does not declare";
        if (old->second != kind)
            return where + " is now a " + kind + "; the shader its pipeline was made for has a " +
                   old->second;
    }
    if (now.pushConstantBytes > before.pushConstantBytes)
        return "its push constants grew from " + std::to_string(before.pushConstantBytes) + " to " +
               std::to_string(now.pushConstantBytes) + " bytes";
    for (const auto& [location, type] : now.inputs) {
        auto old = before.inputs.find(location);
        if (old == before.inputs.end() || old->second != type)
            return "it reads input location " + std::to_string(location) + " (" + type +
                   "), which the shader its pipeline was made for does not";
    }
    for (const auto& [location, type] : before.outputs) {
        auto old = now.outputs.find(location);
        if (old == now.outputs.end() || old->second != type)
            return "it no longer writes output location " + std::to_string(location) + " (" + type + ")";
    }
    return {};
}

#endif  // VKBOOK_RUNTIME_SHADERS

// Checks compiled code against the build's; returns the error message, or empty.
std::string checkInterface(const ShaderSource& source, const std::vector<uint32_t>& reference,
                           const std::vector<uint32_t>& spirv) {
#if defined(VKBOOK_RUNTIME_SHADERS)
    if (reference.empty()) return {};
    std::string change = interfaceChange(reflect(reference, false), reflect(spirv, true));
    if (change.empty()) return {};
    return utf8(source.glsl) + ": interface changed: " + change +
           " (a reload changes shader code only; a new interface needs the C++ that makes the pipeline)";
#else
    (void)source;
    (void)reference;
    (void)spirv;
    return {};
#endif
}

std::string checkInterface(const Entry& entry, const std::vector<uint32_t>& spirv) {
    return checkInterface(entry.source, entry.reference, spirv);
}

void remember(Entry& entry, const std::vector<fs::path>& files) {
    entry.files.clear();
    for (const fs::path& file : files)
        if (std::optional<fs::file_time_type> time = modified(file)) entry.files[file] = *time;
}

}  // namespace

bool runtimeShaderCompilation() {
#if defined(VKBOOK_RUNTIME_SHADERS)
    return true;
#else
    return false;
#endif
}

void configureShaderSources(const fs::path& shaderDir) {
    gState = {};
    if (!shaderDir.empty() && !runtimeShaderCompilation())
        throw InputError(
            "--shader-dir: this build has no runtime shader compilation (built without shaderc)");
    if (!shaderDir.empty() && !fs::is_directory(shaderDir))
        throw InputError("--shader-dir '" + utf8(shaderDir) + "' is not a directory");
    if (!runtimeShaderCompilation()) {
        gState.why = "this build has no runtime compilation (built without shaderc)";
        return;
    }
    fs::path recorded = executableDir() / "shaders" / "source-dir.txt";
    std::ifstream file(recorded);
    std::string line;
    if (file && std::getline(file, line)) gState.buildSourceDir = fs::u8path(line);
    if (!shaderDir.empty()) {
        gState.sourceDir = fs::absolute(shaderDir);
        gState.explicitDir = true;
    } else if (line.empty()) {
        gState.why = "no " + utf8(recorded);
    } else if (!fs::is_directory(gState.buildSourceDir)) {
        gState.why = "the build's sources (" + line + ") are not there";
    } else {
        gState.sourceDir = gState.buildSourceDir;
    }
}

std::string shaderSourcesSummary() {
    if (!gState.sourceDir.empty())
        return "shaders: compiled at run time from " + utf8(gState.sourceDir) +
               " when newer than the build's SPIR-V, reloaded when edited";
    return "shaders: the build's SPIR-V (" + gState.why + ")";
}

ShaderSource findShaderSource(std::string_view name) {
    ShaderSource source;
    fs::path compiled = executableDir() / "shaders" / fs::u8path(std::string(name));
    source.spv = fs::path(compiled).concat(".spv");
    if (gState.sourceDir.empty()) return source;
    std::ifstream manifest(fs::path(compiled).concat(".source"));
    std::string relative, define;
    if (!manifest || !std::getline(manifest, relative) || relative.empty()) return source;
    while (std::getline(manifest, define))
        if (!define.empty()) source.defines.push_back(define);
    source.glsl = gState.sourceDir / fs::u8path(relative);
    source.includeDir = gState.sourceDir / "include";
    source.found = fs::is_regular_file(source.glsl);
    return source;
}

namespace {

// shaderc on one source: SPIR-V, or only the preprocessor's work (which is what finds the files
// it includes, at a fraction of a compile's time).
ShaderCompilation runShaderc(const ShaderSource& source, bool preprocessOnly) {
    ShaderCompilation compilation;
#if defined(VKBOOK_RUNTIME_SHADERS)
    std::string text = readInputFile(source.glsl);
    compilation.files.push_back(source.glsl);
    shaderc_compiler_t compiler = shaderc_compiler_initialize();
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
    shaderc_compiler_release(compiler);
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
    std::string buildDir = utf8(gState.buildSourceDir);
    std::vector<fs::path> files;
    if (colon != std::string::npos && !buildDir.empty()) {
        std::string word;
        auto add = [&] {
            if (word.empty() || word == "\\") return word.clear();
            if (word.starts_with(buildDir + "/"))
                files.push_back(gState.sourceDir / fs::u8path(word.substr(buildDir.size() + 1)));
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
    if (!preprocessed.error.empty()) throw InputError(firstLine(preprocessed.error));
    return preprocessed.files;
}

std::string shaderInterfaceChange(const ShaderSource& source, const std::vector<uint32_t>& spirv) {
    if (!fs::exists(source.spv)) return {};
    return checkInterface(source, readWords(source.spv), spirv);
}

std::vector<uint32_t> shaderCode(std::string_view name) {
    if (auto known = gState.shaders.find(name); known != gState.shaders.end() && !known->second.spirv.empty())
        return known->second.spirv;
    Entry entry;
    entry.source = findShaderSource(name);
    bool built = fs::exists(entry.source.spv);
    if (built) entry.reference = readWords(entry.source.spv);
    if (!entry.source.found) {
        if (!built) throw Failure("missing shader '" + utf8(entry.source.spv) + "' (is the build complete?)");
        entry.spirv = entry.reference;
        return gState.shaders.emplace(std::string(name), std::move(entry)).first->second.spirv;
    }
    // The book's rule, followed through the included files: compile when a file is newer than
    // the build's SPIR-V. shaderFiles tells which files those are.
    remember(entry, shaderFiles(entry.source));
    bool newer = !built;
    if (built) {
        std::optional<fs::file_time_type> spvTime = modified(entry.source.spv);
        for (const auto& [file, time] : entry.files) newer = newer || !spvTime || time > *spvTime;
    }
    if (newer) {
        ShaderCompilation compilation = compileShader(entry.source);
        if (!compilation.error.empty()) throw InputError(firstLine(compilation.error));
        if (std::string change = checkInterface(entry, compilation.spirv); !change.empty())
            throw InputError(change);
        std::printf("shaders: compiled %s (its source is newer than the build's SPIR-V)\n",
                    std::string(name).c_str());
        std::fflush(stdout);
        entry.spirv = std::move(compilation.spirv);
    } else {
        entry.spirv = entry.reference;
    }
    return gState.shaders.emplace(std::string(name), std::move(entry)).first->second.spirv;
}

VkShaderModule loadShaderModule(const Device& device, std::string_view name) {
    std::vector<uint32_t> code = shaderCode(name);  // the build's, or compiled from a newer source
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

void watchShader(std::string_view name) {
    if (gState.sourceDir.empty() || gState.shaders.count(name)) return;
    Entry entry;
    entry.source = findShaderSource(name);
    if (!entry.source.found) return;
    if (fs::exists(entry.source.spv)) entry.reference = readWords(entry.source.spv);
    remember(entry, shaderFiles(entry.source));
    gState.shaders.emplace(std::string(name), std::move(entry));
}

bool shaderSourcesChanged() {
    if (gState.sourceDir.empty()) return false;
    // The last reload's report, now that a frame has been recorded and submitted with it: how long
    // from the edit (the newest changed file's modification time) to that frame.
    if (!gState.reloaded.empty()) {
        auto latency =
            std::chrono::duration<double, std::milli>(fs::file_time_type::clock::now() - gState.editTime);
        std::printf(
            "shaders: reloaded %s (compiled in %.0f ms; first frame with it %.0f ms after the edit)\n",
            gState.reloaded.c_str(), gState.compileMs, latency.count());
        std::fflush(stdout);
        gState.reloaded.clear();
    }
    auto now = std::chrono::steady_clock::now();
    if (now - gState.lastPoll < std::chrono::milliseconds(250)) return false;
    gState.lastPoll = now;

    // Which shaders' files changed since they were read. A file that cannot be read just now (an
    // editor replacing it) is looked at again on the next poll.
    std::vector<std::pair<const std::string*, Entry*>> changed;
    fs::file_time_type editTime = fs::file_time_type::min();
    for (auto& [name, entry] : gState.shaders) {
        bool edited = false, readable = true;
        for (const auto& [file, time] : entry.files) {
            std::optional<fs::file_time_type> current = modified(file);
            if (!current)
                readable = false;
            else if (*current != time)
                edited = true, editTime = std::max(editTime, *current);
        }
        if (edited && readable) changed.emplace_back(&name, &entry);
    }
    if (changed.empty()) return false;

    auto started = std::chrono::steady_clock::now();
    for (auto& [name, entry] : changed) {
        ShaderCompilation compilation = compileShader(entry->source);
        remember(*entry,
                 compilation.files.empty() ? std::vector<fs::path>{entry->source.glsl} : compilation.files);
        entry->error =
            compilation.error.empty() ? checkInterface(*entry, compilation.spirv) : compilation.error;
        if (entry->error.empty())
            entry->pending = std::move(compilation.spirv);
        else
            std::fprintf(stderr, "shaders: %s did not reload: %s", name->c_str(),
                         (entry->error + (entry->error.ends_with('\n') ? "" : "\n")).c_str());
    }
    // Every shader must be good before any pipeline changes.
    gState.reloadError.clear();
    for (const auto& [name, entry] : gState.shaders)
        if (!entry.error.empty())
            gState.reloadError += entry.error + (entry.error.ends_with('\n') ? "" : "\n");
    if (!gState.reloadError.empty()) {
        std::fflush(stderr);
        return false;
    }
    std::string names;
    for (auto& [name, entry] : gState.shaders)
        if (entry.pending) {
            entry.spirv = std::move(*entry.pending);
            entry.pending.reset();
            names += (names.empty() ? "" : ", ") + name;
        }
    gState.reloaded = names;
    gState.editTime = editTime;
    gState.compileMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    return true;
}

const std::string& shaderReloadError() {
    return gState.reloadError;
}

}  // namespace common
