// glTF 2.0 models through tinygltf, checked against the limits of common/model/model.hpp.
#pragma once

#include <filesystem>

#include "common/model/model.hpp"

namespace common {

// Loads a glTF 2.0 model, .gltf (with its .bin and images beside it, or data: URIs) or .glb
// (common/model/gltf_model.cpp). Throws InputError with one line naming the file and the problem.
ModelData loadGltfModel(const std::filesystem::path& path);

}  // namespace common
