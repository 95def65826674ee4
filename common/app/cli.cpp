// Command-line parsing shared by every chapter (with CLI11), and the mapping of failures to exit
// codes.
#include "common/app/cli.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <string_view>

#if defined(_WIN32)
#include <fcntl.h>
#include <io.h>
#endif

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/core/stop.hpp"
#include "common/shaders/shader_compiler.hpp"
#include "common/vk/formats.hpp"
#include "common/vk/instance.hpp"

namespace common {
namespace {

constexpr const char* kUsage =
    "usage: %s [--headless] [--width W] [--height H] [--frames N] [--screenshot FILE.png]\n"
    "          [--device NAME] [--validation] [--frames-in-flight N] [--resize WxH]\n"
    "          [--target-format FORMAT] [--shader-dir DIR] [--help]\n"
    "          [--benchmark [--warmup N] [--json FILE]]%s\n"
    "\n"
    "  --headless         render offscreen, no window or display needed\n"
    "  --width W          image width, 1..16384 (default 1280)\n"
    "  --height H         image height, 1..16384 (default 720)\n"
    "  --frames N         frames to render, 1..10000000 (default: 1 headless, until closed in a window)\n"
    "  --frames-in-flight N  frames recorded ahead of the GPU, 1..3 (default 2)\n"
    "  --screenshot FILE  write the last frame as a PNG\n"
    "  --device NAME      use the best Vulkan device (in the default's order: discrete, integrated,\n"
    "                     virtual, CPU) whose name contains NAME (case-insensitive)\n"
    "  --validation       enable VK_LAYER_KHRONOS_validation with synchronization validation;\n"
    "                     exit with code 3 if it reports any warning or error\n"
    "  --resize WxH       (testing) resize the window or offscreen target to WxH after half of\n"
    "                     --frames\n"
    "  --target-format FORMAT  the format of the presented (or headless) images, instead of the\n"
    "                     first the window offers of B8G8R8A8_SRGB, R8G8B8A8_SRGB, B8G8R8A8_UNORM,\n"
    "                     R8G8B8A8_UNORM, A2R10G10B10_UNORM_PACK32, A2B10G10R10_UNORM_PACK32\n"
    "                     (headless: B8G8R8A8_SRGB)\n"
    "  --shader-dir DIR   compile the shaders from DIR (a copy of the sources' shaders/) instead of\n"
    "                     the build's sources, and reload them when edited\n"
    "  --benchmark        render --warmup frames (default 10), then --frames (default 100) measured\n"
    "                     ones without vsync; print CPU and GPU frame and pass times\n"
    "  --json FILE        with --benchmark: also write the report as JSON\n"
    "  --help             print this text\n";

constexpr const char* kSceneUsage =
    "  --scene FILE.json  render the scene described by FILE.json (default: the generated default scene)\n"
    "  --model FILE       render one model, framed by the camera: OBJ (with its MTL and textures)\n"
    "                     or glTF 2.0 (.gltf with its files, or .glb), or the book's converted\n"
    "                     models (.json with its .vtx, .idx and _mat.json)\n"
    "  --book-scene PATH  the book's scene: its Sponza.gltf (PATH: the book's clone, or the .gltf)\n"
    "                     with chapter 15's camera and lights (chapter-16: chapter 16's, and its tree;\n"
    "                     chapter-17: chapter 17's, and Bob)\n"
    "  --view NAME        show one attachment instead of the final image: %s\n";

constexpr const char* kExitCodes =
    "\nan option given twice takes its last value\n"
    "exit codes: 0 success, 1 failure, 2 bad usage or input, 3 validation messages,\n"
    "            130/143 Ctrl+C/SIGTERM cut a frame or a load short\n";

uint32_t parseNumber(std::string_view flag, std::string_view text, uint32_t min, uint32_t max) {
    uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error == std::errc::invalid_argument || end != text.data() + text.size())
        throw InputError(std::string(flag) + " expects a whole number, got '" + std::string(text) + "'");
    if (error == std::errc::result_out_of_range || value < min || value > max)
        throw InputError(std::string(flag) + " must be between " + std::to_string(min) + " and " +
                         std::to_string(max) + ", got " + std::string(text));
    return value;
}

VkExtent2D parseExtent(std::string_view flag, std::string_view text) {
    size_t x = text.find('x');
    if (x == std::string_view::npos)
        throw InputError(std::string(flag) + " expects WIDTHxHEIGHT, got '" + std::string(text) + "'");
    return {parseNumber(flag, text.substr(0, x), 1, kMaxWindowDimension),
            parseNumber(flag, text.substr(x + 1), 1, kMaxWindowDimension)};
}

// Refuses an output path we could not write at the end of the run, before any work is done.
// The file itself is only written at the end (through a temporary file and a rename, so an
// existing file is never left half-written). `what` names it: "screenshot", "benchmark report".
void checkOutputPath(const std::filesystem::path& path, const std::string& what) {
    namespace fs = std::filesystem;
    std::string name = "cannot write " + what + " '" + utf8(path) + "': ";
    fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::error_code ec;
    if (!fs::is_directory(directory, ec))
        throw InputError(name + "directory '" + utf8(directory) + "' does not exist");
    if (fs::is_directory(path, ec)) throw InputError(name + "it is a directory");
    if (!isWritable(directory))
        throw InputError(name + "directory '" + utf8(directory) + "' is not writable");
    if (fs::exists(path, ec) && !isWritable(path)) throw InputError(name + "the file is not writable");
}

void checkScreenshotPath(const std::filesystem::path& path) {
    std::string extension = utf8(path.extension());
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png") throw InputError("--screenshot '" + utf8(path) + "' must end in .png");
    checkOutputPath(path, "screenshot");
}

// "a|b|c"
std::string joined(const std::vector<std::string>& values) {
    std::string out;
    for (const std::string& value : values) out += (out.empty() ? "" : "|") + value;
    return out;
}

}  // namespace

Options parseCommandLine(int argc, const char* const* argv, const ChapterInfo& chapter) {
    Options options;
    options.command = argc > 0 ? utf8(std::filesystem::path(argv[0]).filename()) : chapter.name;
    for (int i = 1; i < argc; ++i) options.command += std::string(" ") + argv[i];

    // CLI11 binds each option to its field; our validators check each value as it is given and
    // throw InputError with our one-line message (CLI11 passes any exception but its own through).
    // --help is ours (runChapter prints it); extra arguments are collected and refused below.
    CLI::App app{chapter.summary, chapter.name};
    app.set_help_flag();
    app.allow_extras();
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    auto check = [](std::function<void(const std::string&)> test) {
        return CLI::Validator(
            [test](std::string& value) {
                test(value);
                return std::string();
            },
            "");
    };
    auto number = [&](const char* flag, uint32_t min, uint32_t max) {
        return check([=](const std::string& text) { parseNumber(flag, text, min, max); });
    };
    auto nonEmpty = [&](const std::string& message) {
        return check([=](const std::string& text) {
            if (text.empty()) throw InputError(message);
        });
    };
    app.add_flag("--headless", options.headless);
    app.add_option("--width", options.width)->check(number("--width", 1, kMaxWindowDimension));
    app.add_option("--height", options.height)->check(number("--height", 1, kMaxWindowDimension));
    app.add_option("--frames", options.frames)->check(number("--frames", 1, 10'000'000));
    app.add_option("--frames-in-flight", options.framesInFlight)->check(number("--frames-in-flight", 1, 3));
    app.add_flag("--benchmark", options.benchmark);
    app.add_option("--warmup", options.warmup)->check(number("--warmup", 0, 100000));
    std::string json, screenshot, resize, scene, model, bookScene, view, targetFormat, shaderDir;
    app.add_option("--json", json)->check(check([](const std::string& file) {
        if (file.empty()) throw InputError("--json needs a file name");
        checkOutputPath(file, "benchmark report");
    }));
    app.add_option("--screenshot", screenshot)->check(check([](const std::string& file) {
        checkScreenshotPath(file);
    }));
    app.add_option("--device", options.device)->check(nonEmpty("--device needs a non-empty name"));
    app.add_flag("--validation", options.validation);
    app.add_option("--resize", resize)->check(check([](const std::string& text) {
        parseExtent("--resize", text);
    }));
    app.add_option("--target-format", targetFormat)->check(check([](const std::string& name) {
        if (!presentFormatByName(name))
            throw InputError("--target-format must be one of " + presentFormatNames() + ", got '" + name +
                             "'");
    }));
    app.add_option("--shader-dir", shaderDir)->check(nonEmpty("--shader-dir needs a directory"));
    // The scene chapters' options; a chapter without a scene refuses them by name (below).
    app.add_option("--scene", scene)->check(nonEmpty("--scene needs a file name"));
    app.add_option("--model", model)->check(nonEmpty("--model needs a file name"));
    app.add_option("--book-scene", bookScene)->check(nonEmpty("--book-scene needs a path"));
    app.add_option("--view", view)->check(check([&](const std::string& name) {
        if (std::find(chapter.views.begin(), chapter.views.end(), name) == chapter.views.end())
            throw InputError("--view must be one of " + joined(chapter.views) + ", got '" + name + "'");
    }));
    // The chapter's own: fixed choices, free values, switches.
    std::map<std::string, std::string> given;
    for (const Choice& choice : chapter.choices) {
        std::string flag = "--" + choice.name;
        app.add_option(flag, given[choice.name])->check(check([flag, &choice](const std::string& value) {
            if (choice.values.empty()) {
                if (value.empty()) throw InputError(flag + " needs a non-empty value");
            } else if (std::find(choice.values.begin(), choice.values.end(), value) == choice.values.end()) {
                throw InputError(flag + " must be one of " + joined(choice.values) + ", got '" + value + "'");
            }
        }));
    }
    for (const auto& [name, help] : chapter.switches) app.add_flag("--" + name);
    app.add_flag("-h,--help", options.help);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ArgumentMismatch& error) {
        // An option at the end, or followed by another option, without its value.
        std::string what = error.what();
        throw InputError(what.substr(0, what.find(':')) + " needs a value");
    } catch (const CLI::ParseError& error) {
        throw InputError(error.what());
    }
    for (const std::string& extra : app.remaining()) {
        if (extra.starts_with("-")) throw InputError("unknown option '" + extra + "' (see --help)");
        throw InputError("unexpected argument '" + extra + "' (see --help)");
    }

    for (const char* flag : {"--scene", "--model", "--book-scene", "--view"})
        if (chapter.views.empty() && app.count(flag))
            throw InputError(std::string(chapter.name) + " draws no scene and takes no " + flag);
    options.json = json;
    options.shaderDir = std::filesystem::u8path(shaderDir);
    options.screenshot = screenshot;
    if (app.count("--resize")) options.resizeTo = parseExtent("--resize", resize);
    if (app.count("--target-format")) options.targetFormat = presentFormatByName(targetFormat);
    options.scene = scene;
    options.model = model;
    options.bookScene = bookScene;
    if (app.count("--view"))
        options.view =
            uint32_t(std::find(chapter.views.begin(), chapter.views.end(), view) - chapter.views.begin());
    for (const Choice& choice : chapter.choices) {
        if (!app.count("--" + choice.name)) continue;
        const std::string& value = given[choice.name];
        if (choice.values.empty())
            options.values[choice.name] = value;
        else
            options.choices[choice.name] = uint32_t(
                std::find(choice.values.begin(), choice.values.end(), value) - choice.values.begin());
    }
    for (const auto& [name, help] : chapter.switches)
        if (app.count("--" + name)) options.switches.insert(name);

    if (!options.json.empty() && !options.benchmark) throw InputError("--json goes with --benchmark");
    if (app.count("--warmup") && !options.benchmark) throw InputError("--warmup goes with --benchmark");
    if (int(!options.scene.empty()) + int(!options.model.empty()) + int(!options.bookScene.empty()) > 1)
        throw InputError("--scene, --model and --book-scene exclude each other");
    if (options.resizeTo && (!app.count("--frames") || options.frames < 2))
        throw InputError("--resize needs --frames 2 or more (it happens after half of them)");
    return options;
}

bool genericPipelines(const Options& options) {
    auto chosen = options.choices.find(kPipelinesChoice.name);
    return chosen != options.choices.end() && chosen->second == 1;
}

uint32_t frameCount(const Options& options) {
    if (options.benchmark) return options.warmup + (options.frames != 0 ? options.frames : 100);
    if (options.frames != 0) return options.frames;
    return options.headless ? 1 : 0;
}

namespace {
const std::chrono::steady_clock::time_point gStart = std::chrono::steady_clock::now();
}

double millisecondsSinceStart() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - gStart).count();
}

int runChapter(int argc, const char* const* argv, const ChapterInfo& info,
               const std::function<void(const Options&)>& chapter) {
    const char* name = info.name;
#if defined(_WIN32)
    // "\n", not "\r\n": the same bytes on stdout and stderr as on the other systems.
    _setmode(_fileno(stdout), _O_BINARY);
    _setmode(_fileno(stderr), _O_BINARY);
#endif
    try {
        Options options = parseCommandLine(argc, argv, info);
        configureShaderSources(options.shaderDir);
        if (options.help) {
            std::printf("%s: %s\n\n", name, info.summary);
            std::printf(kUsage, name,
                        info.views.empty()
                            ? ""
                            : " [--scene FILE.json | --model FILE | --book-scene PATH] [--view NAME]");
            if (!info.views.empty()) {
                std::string names;
                for (const std::string& view : info.views) names += (names.empty() ? "" : "|") + view;
                std::printf(kSceneUsage, names.c_str());
            }
            for (const Choice& choice : info.choices) {
                std::string values;
                for (const std::string& value : choice.values) values += (values.empty() ? "" : "|") + value;
                if (choice.values.empty())
                    std::printf("  --%s VALUE\n                     %s\n", choice.name.c_str(),
                                choice.help.c_str());
                else
                    std::printf("  --%s %s\n                     %s (default %s)\n", choice.name.c_str(),
                                values.c_str(), choice.help.c_str(), choice.values.front().c_str());
            }
            for (const auto& [switchName, help] : info.switches)
                std::printf("  --%-17s%s\n", switchName.c_str(), help.c_str());
            std::printf("\n%s\n", shaderSourcesSummary().c_str());
            std::printf("%s", kExitCodes);
            return 0;
        }
        if (!options.shaderDir.empty()) {
            std::printf("%s\n", shaderSourcesSummary().c_str());
            std::fflush(stdout);  // for whoever waits for it (a test, a script)
        }
        watchForStop(name);
        chapter(options);
    } catch (const InputError& error) {
        std::fprintf(stderr, "%s: error: %s\n", name, oneLine(error.what()).c_str());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s: error: %s\n", name, oneLine(error.what()).c_str());
        return 1;
    }
    if (uint32_t count = validationMessageCount(); count != 0) {
        std::fprintf(stderr, "%s: the validation layer reported %u message(s)\n", name, count);
        return 3;
    }
    return 0;
}

}  // namespace common
