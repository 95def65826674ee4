// Command-line parsing shared by every chapter, and the mapping of failures to exit codes.
#include "common/cli.hpp"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <string_view>

#if defined(_WIN32)
#include <fcntl.h>
#include <io.h>
#endif

#include "common/check.hpp"
#include "common/files.hpp"
#include "common/instance.hpp"

namespace common {
namespace {

constexpr const char* kUsage =
    "usage: %s [--headless] [--width W] [--height H] [--frames N] [--screenshot FILE.png]\n"
    "          [--device NAME] [--validation] [--frames-in-flight N] [--resize WxH] [--help]\n"
    "          [--benchmark [--warmup N] [--json FILE]]%s\n"
    "\n"
    "  --headless         render offscreen, no window or display needed\n"
    "  --width W          image width, 1..16384 (default 1280)\n"
    "  --height H         image height, 1..16384 (default 720)\n"
    "  --frames N         frames to render, 1..10000000 (default: 1 headless, until closed in a window)\n"
    "  --frames-in-flight N  frames recorded ahead of the GPU, 1..3 (default 2)\n"
    "  --screenshot FILE  write the last frame as a PNG\n"
    "  --device NAME      use the first Vulkan device whose name contains NAME (case-insensitive)\n"
    "  --validation       enable VK_LAYER_KHRONOS_validation with synchronization validation;\n"
    "                     exit with code 3 if it reports any warning or error\n"
    "  --resize WxH       (testing) resize the window or offscreen target to WxH after half of\n"
    "                     --frames\n"
    "  --benchmark        render --warmup frames (default 10), then --frames (default 100) measured\n"
    "                     ones without vsync; print CPU and GPU frame and pass times\n"
    "  --json FILE        with --benchmark: also write the report as JSON\n"
    "  --help             print this text\n";

constexpr const char* kSceneUsage =
    "  --scene FILE.json  render the scene described by FILE.json (default: the generated default scene)\n"
    "  --model FILE       render one model, framed by the camera: OBJ (with its MTL and textures)\n"
    "                     or glTF 2.0 (.gltf with its files, or .glb)\n"
    "  --book-scene PATH  the book's chapter-15 scene: its Sponza.gltf (PATH: the book's clone, or the\n"
    "                     .gltf), its camera and lights\n"
    "  --view NAME        show one attachment instead of the final image: %s\n";

constexpr const char* kExitCodes =
    "\nan option given twice takes its last value\n"
    "exit codes: 0 success, 1 failure, 2 bad usage or input, 3 validation messages\n";

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

const Choice* findChoice(const ChapterInfo& chapter, std::string_view arg) {
    for (const Choice& choice : chapter.choices)
        if (arg == "--" + choice.name) return &choice;
    return nullptr;
}

bool isSwitch(const ChapterInfo& chapter, std::string_view name) {
    for (const auto& [switchName, help] : chapter.switches)
        if (switchName == name) return true;
    return false;
}

// An error message as one printable line, whatever the input put into it (a file name or a token
// with a line break, a megabyte of garbage).
std::string oneLine(std::string message) {
    for (char& c : message)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    constexpr size_t kMaxLength = 1000;
    if (message.size() > kMaxLength) message = message.substr(0, kMaxLength) + "...";
    return message;
}

}  // namespace

Options parseCommandLine(int argc, const char* const* argv, const ChapterInfo& chapter) {
    Options options;
    bool framesGiven = false, warmupGiven = false;
    options.command = argc > 0 ? utf8(std::filesystem::path(argv[0]).filename()) : chapter.name;
    for (int i = 1; i < argc; ++i) options.command += std::string(" ") + argv[i];
    for (int i = 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        auto value = [&]() -> std::string_view {
            if (i + 1 >= argc) throw InputError(std::string(arg) + " needs a value");
            return argv[++i];
        };
        if (arg == "--headless") {
            options.headless = true;
        } else if (arg == "--width") {
            options.width = parseNumber(arg, value(), 1, kMaxWindowDimension);
        } else if (arg == "--height") {
            options.height = parseNumber(arg, value(), 1, kMaxWindowDimension);
        } else if (arg == "--frames") {
            options.frames = parseNumber(arg, value(), 1, 10'000'000);
            framesGiven = true;
        } else if (arg == "--benchmark") {
            options.benchmark = true;
        } else if (arg == "--warmup") {
            options.warmup = parseNumber(arg, value(), 0, 100000);
            warmupGiven = true;
        } else if (arg == "--json") {
            options.json = value();
            if (options.json.empty()) throw InputError("--json needs a file name");
            checkOutputPath(options.json, "benchmark report");
        } else if (arg == "--frames-in-flight") {
            options.framesInFlight = parseNumber(arg, value(), 1, 3);
        } else if (arg == "--screenshot") {
            options.screenshot = value();
            checkScreenshotPath(options.screenshot);
        } else if (arg == "--device") {
            options.device = value();
            if (options.device.empty()) throw InputError("--device needs a non-empty name");
        } else if (arg == "--validation") {
            options.validation = true;
        } else if (arg == "--resize") {
            options.resizeTo = parseExtent(arg, value());
        } else if ((arg == "--scene" || arg == "--model" || arg == "--book-scene" || arg == "--view") &&
                   chapter.views.empty()) {
            throw InputError(std::string(chapter.name) + " draws no scene and takes no " + std::string(arg));
        } else if (arg == "--scene") {
            options.scene = value();
            if (options.scene.empty()) throw InputError("--scene needs a file name");
        } else if (arg == "--model") {
            options.model = value();
            if (options.model.empty()) throw InputError("--model needs a file name");
        } else if (arg == "--book-scene") {
            options.bookScene = value();
            if (options.bookScene.empty()) throw InputError("--book-scene needs a path");
        } else if (arg == "--view") {
            std::string_view name = value();
            std::string names;
            bool found = false;
            for (uint32_t v = 0; v < chapter.views.size(); ++v) {
                names += (v ? "|" : "") + chapter.views[v];
                if (chapter.views[v] == name) options.view = v, found = true;
            }
            if (!found)
                throw InputError("--view must be one of " + names + ", got '" + std::string(name) + "'");
        } else if (const Choice* choice = findChoice(chapter, arg)) {
            std::string_view given = value();
            if (choice->values.empty()) {
                if (given.empty()) throw InputError(std::string(arg) + " needs a non-empty value");
                options.values[choice->name] = given;
                continue;
            }
            std::string names;
            bool found = false;
            for (uint32_t v = 0; v < choice->values.size(); ++v) {
                names += (v ? "|" : "") + choice->values[v];
                if (choice->values[v] == given) options.choices[choice->name] = v, found = true;
            }
            if (!found)
                throw InputError(std::string(arg) + " must be one of " + names + ", got '" +
                                 std::string(given) + "'");
        } else if (arg.starts_with("--") && isSwitch(chapter, arg.substr(2))) {
            options.switches.insert(std::string(arg.substr(2)));
        } else if (arg == "--help" || arg == "-h") {
            options.help = true;
        } else if (arg.starts_with("-")) {
            throw InputError("unknown option '" + std::string(arg) + "' (see --help)");
        } else {
            throw InputError("unexpected argument '" + std::string(arg) + "' (see --help)");
        }
    }
    if (!options.json.empty() && !options.benchmark) throw InputError("--json goes with --benchmark");
    if (warmupGiven && !options.benchmark) throw InputError("--warmup goes with --benchmark");
    if (int(!options.scene.empty()) + int(!options.model.empty()) + int(!options.bookScene.empty()) > 1)
        throw InputError("--scene, --model and --book-scene exclude each other");
    if (options.resizeTo && (!framesGiven || options.frames < 2))
        throw InputError("--resize needs --frames 2 or more (it happens after half of them)");
    return options;
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
            std::printf("%s", kExitCodes);
            return 0;
        }
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
