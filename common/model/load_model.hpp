// A model file of any format we read, by its extension, and a run's cache of models read.
#pragma once

#include <filesystem>
#include <map>

#include "common/model/model.hpp"

namespace common {

// loadObjModel, loadGltfModel or loadBookModel, by the file's extension (.obj, .gltf, .glb, .json).
ModelData loadModel(const std::filesystem::path& path);

// Models already read in this run, by path: a scene that places one model many times, or --model
// (read once for its bounds, then uploaded), reads each file once, however its path is spelled
// ("a.gltf", "./a.gltf", "dir/../a.gltf": the key is modelKey's).
using ModelCache = std::map<std::filesystem::path, ModelData>;
std::filesystem::path modelKey(const std::filesystem::path& path);
const ModelData& loadModelCached(ModelCache& cache, const std::filesystem::path& path);

}  // namespace common
