// libFuzzer target: scene JSON through common::parseScene (what loadSceneFile does after reading
// the file), then the round trip sceneToJson -> parseScene, which must give the same scene.
// Run by tests/reliability/fuzz/run.sh. The one acceptable failure is an
// InputError with a one-line message; anything else aborts the run. The models a scene names are
// not read (parseScene never opens them).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include "common/core/check.hpp"
#include "common/scene/scene.hpp"

namespace {

const std::filesystem::path kBaseDir = "/fuzz-scenes";                // need not exist
const bool gVerbose = std::getenv("VKBOOK_FUZZ_VERBOSE") != nullptr;  // say what became of each input

void checkOneLine(const common::InputError& error) {
    std::string_view message = error.what();
    if (message.empty() || message.find_first_of("\n\r") != std::string_view::npos) {
        std::fprintf(stderr, "fuzz_scene: InputError without a one-line message: '%s'\n", error.what());
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    common::Scene scene;
    try {
        scene =
            common::parseScene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json", kBaseDir);
    } catch (const common::InputError& error) {
        if (gVerbose) std::fprintf(stderr, "fuzz_scene: InputError: %s\n", error.what());
        checkOneLine(error);
        return 0;
    }
    if (gVerbose) std::fprintf(stderr, "fuzz_scene: parsed, %zu models\n", scene.models.size());
    // A scene we accepted, written by us, reads back as the same scene.
    std::string written = common::sceneToJson(scene);
    try {
        if (!(common::parseScene(written, "written.json", kBaseDir) == scene)) {
            std::fprintf(stderr, "fuzz_scene: the scene written reads back differently:\n%s",
                         written.c_str());
            std::abort();
        }
    } catch (const common::InputError& error) {
        std::fprintf(stderr, "fuzz_scene: the scene written does not read back (%s):\n%s", error.what(),
                     written.c_str());
        std::abort();
    }
    return 0;
}
