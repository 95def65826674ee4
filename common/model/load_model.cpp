// Which loader reads a model file, and the models already read in a run.
#include "common/model/load_model.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/model/book_model.hpp"
#include "common/model/gltf_model.hpp"
#include "common/model/obj_model.hpp"

namespace common {

ModelData loadModel(const std::filesystem::path& path) {
    requireInputFile(path);  // "no such file" before "not a model file" for a mistyped name
    // For test scripts (tests/reliability/stop_run.sh): a signal after this line lands in the load.
    static const bool testEvents = std::getenv("VKBOOK_TEST_EVENTS") != nullptr;
    if (testEvents) {
        std::printf("test-event: loading %s\n", utf8(path.filename()).c_str());
        std::fflush(stdout);
    }
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](char c) { return char(std::tolower(static_cast<unsigned char>(c))); });
    ModelData model;
    if (extension == ".gltf" || extension == ".glb")
        model = loadGltfModel(path);
    else if (extension == ".obj")
        model = loadObjModel(path);
    else if (extension == ".json")  // the book's converted models (its chapter-16 tree)
        model = loadBookModel(path);
    else
        throw InputError(utf8(path) +
                         ": not a model file we read (.obj, .gltf, .glb or the book's converted .json)");
    // Every coordinate finite is not enough: a model from -3e38 to 3e38 has an infinite extent,
    // and the camera framed on it, the bounds and the distances the renderer squares overflow.
    for (const glm::vec3& corner : {model.boundsMin, model.boundsMax})
        for (int axis = 0; axis < 3; ++axis)
            if (!(std::abs(corner[axis]) <= kMaxModelCoordinate)) {
                char value[32];
                std::snprintf(value, sizeof(value), "%g", double(corner[axis]));
                throw InputError(utf8(path) + ": a vertex lies at " + value +
                                 " on an axis; coordinates from -1e15 to 1e15 are drawn");
            }
    return model;
}

std::filesystem::path modelKey(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : canonical;
}

const ModelData& loadModelCached(ModelCache& cache, const std::filesystem::path& path) {
    const std::filesystem::path key = modelKey(path);
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, loadModel(path)).first;
    return it->second;
}

}  // namespace common
