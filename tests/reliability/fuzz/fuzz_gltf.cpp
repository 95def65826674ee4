// libFuzzer target: a glTF 2.0 file through common::loadGltfModel (our JSON and GLB checks,
// tinygltf's parser, the accessor reader, the node forest, strips and fans, generated normals and
// tangents, materials and samplers). Run by tests/reliability/fuzz/run.sh. The one acceptable failure is an
// InputError with a one-line message; any other exception, crash, sanitizer report or a model
// breaking ModelData's promises aborts the run.
//
// Random byte mutations rarely make a number near 2^64, a node graph that shares one mesh many
// times or a deep nesting, so the target brings a mutator of its own that knows the document is
// JSON (LLVMFuzzerCustomMutator): half of its mutations parse the input and change its structure
// -- a number set to a boundary value (0, -1, 2^31 +- 1, 2^32 +- 1, 2^53, 2^63, 2^64 - k, the
// loader's own limits), a key of glTF's added with such a number, an index array filled with one
// index many times, an object copied many times, a value wrapped in deep nesting -- and half are
// libFuzzer's own byte mutations.
//
// An input is the whole file: written as model.glb when it starts with the GLB magic "glTF",
// else as model.gltf, alone in a directory of its own, so that its buffers and images come from
// data: URIs or the GLB's binary chunk (an external URI names a file that does not exist).
#include <stdlib.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string_view>

#include "common/core/check.hpp"
#include "common/model/gltf_model.hpp"
#include "common/model/model.hpp"
#include "model_checks.hpp"

namespace {

std::filesystem::path gDirectory;  // this process's own, under $TMPDIR or /dev/shm
bool gVerbose = false;             // VKBOOK_FUZZ_VERBOSE=1: say what became of each input

using nlohmann::json;

// Numbers at the edges: of the integer types a loader may compute in, of what a double holds
// exactly, and of this loader's limits (2^25 elements, 2^31 - 1 bytes); 2^64 - k makes sums
// with a few elements' bytes wrap to small numbers.
const std::vector<json> kBoundaries = {json(0),
                                       json(-1),
                                       json(1),
                                       json(3),
                                       json(4),
                                       json(252),
                                       json(256),
                                       json(65535),
                                       json(65536),
                                       json(2147483647),
                                       json(2147483648ull),
                                       json(2147483649ull),
                                       json(4294967295ull),
                                       json(4294967296ull),
                                       json(4294967297ull),
                                       json(33554432),
                                       json(33554433),
                                       json(16777216),
                                       json(16777217),
                                       json(9007199254740992ull),
                                       json(9223372036854775807ull),
                                       json(9223372036854775808ull),
                                       json(18446744073709551615ull),
                                       json(18446744073709551612ull),
                                       json(18446744073709551604ull),
                                       json(18446744073709551580ull),
                                       json(18446744073608888320ull),
                                       json(-2147483648ll),
                                       json(1e300),
                                       json(-0.0)};

// Keys of glTF 2.0 whose values are numbers the loader sizes or indexes with.
const char* const kNumberKeys[] = {"byteOffset", "byteLength",    "byteStride", "count",      "bufferView",
                                   "buffer",     "componentType", "mode",       "indices",    "material",
                                   "mesh",       "scene",         "source",     "sampler",    "index",
                                   "texCoord",   "POSITION",      "NORMAL",     "TEXCOORD_0", "TANGENT"};

// Every value in the document, for picking one (with its parent, to add keys or copies).
void collect(json& value, std::vector<json*>& all) {
    all.push_back(&value);
    if (value.is_structured())
        for (json& child : value) collect(child, all);
}

// One structural change to the document; false when it found nothing to change.
bool mutateJson(json& root, std::mt19937& random) {
    std::vector<json*> all;
    collect(root, all);
    auto pick = [&](size_t n) { return size_t(random() % n); };
    json& target = *all[pick(all.size())];
    switch (random() % 6) {
        case 0: {  // a number becomes a boundary value
            std::vector<json*> numbers;
            for (json* v : all)
                if (v->is_number()) numbers.push_back(v);
            if (numbers.empty()) return false;
            *numbers[pick(numbers.size())] = kBoundaries[pick(kBoundaries.size())];
            return true;
        }
        case 1: {  // a glTF key with a boundary value, in some object
            std::vector<json*> objects;
            for (json* v : all)
                if (v->is_object()) objects.push_back(v);
            if (objects.empty()) return false;
            (*objects[pick(objects.size())])[kNumberKeys[pick(std::size(kNumberKeys))]] =
                random() % 2 ? kBoundaries[pick(kBoundaries.size())] : json(random() % 4);
            return true;
        }
        case 2: {  // an array of indices filled with one of its values, many times
            std::vector<json*> arrays;
            for (json* v : all)
                if (v->is_array() && !v->empty() && (*v)[0].is_number_integer()) arrays.push_back(v);
            if (arrays.empty()) return false;
            json& array = *arrays[pick(arrays.size())];
            json value = array[pick(array.size())];
            for (size_t k = 1 + pick(200); k > 0; --k) array.push_back(value);
            return true;
        }
        case 3: {  // an element of an array of objects (a node, an accessor) copied many times
            std::vector<json*> arrays;
            for (json* v : all)
                if (v->is_array() && !v->empty() && (*v)[0].is_object()) arrays.push_back(v);
            if (arrays.empty()) return false;
            json& array = *arrays[pick(arrays.size())];
            json copy = array[pick(array.size())];
            for (size_t k = 1 + pick(50); k > 0; --k) array.push_back(copy);
            return true;
        }
        case 4: {  // nesting: a value wrapped in arrays, deeper than any parser's comfort
            json wrapped = target;
            for (size_t k = 1 + pick(2000); k > 0; --k) wrapped = json::array({std::move(wrapped)});
            target = std::move(wrapped);
            return true;
        }
        default: {  // a value copied over another (an index where a count was, an object for a number)
            target = *all[pick(all.size())];
            return true;
        }
    }
}

}  // namespace

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t maxSize);

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t maxSize, unsigned seed) {
    std::mt19937 random(seed);
    if (random() % 2 == 0 && size > 0 && data[0] == '{') {
        json root = json::parse(data, data + size, nullptr, false);
        if (!root.is_discarded() && mutateJson(root, random)) {
            std::string text = root.dump();
            if (text.size() <= maxSize) {
                std::memcpy(data, text.data(), text.size());
                return text.size();
            }
        }
    }
    return LLVMFuzzerMutate(data, size, maxSize);
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gDirectory = fuzz::makeScratchDirectory("fuzz-gltf");
    gVerbose = std::getenv("VKBOOK_FUZZ_VERBOSE") != nullptr;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    bool glb = input.substr(0, 4) == "glTF";
    std::filesystem::path path = gDirectory / (glb ? "model.glb" : "model.gltf");
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(input.data(), std::streamsize(input.size()));
        if (!out) {
            std::fprintf(stderr, "fuzz_gltf: cannot write %s\n", path.c_str());
            std::abort();
        }
    }
    try {
        common::ModelData model = common::loadGltfModel(path);
        fuzz::checkModel(model);
        for (const common::MaterialData& material : model.materials) fuzz::checkMaterial(material);
        if (gVerbose) std::fprintf(stderr, "fuzz_gltf: loaded, %zu meshes\n", model.meshes.size());
    } catch (const common::InputError& error) {
        if (gVerbose) std::fprintf(stderr, "fuzz_gltf: InputError: %s\n", error.what());
        std::string_view message = error.what();
        if (message.empty() || message.find_first_of("\n\r") != std::string_view::npos) {
            std::fprintf(stderr, "fuzz_gltf: InputError without a one-line message: '%s'\n", error.what());
            std::abort();
        }
    }
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return 0;
}
