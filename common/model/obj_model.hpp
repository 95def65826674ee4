// OBJ models with their MTL materials (the book's chapters 7-9 load OBJ through Assimp).
#pragma once

#include <filesystem>

#include "common/model/model.hpp"

namespace common {

// Loads an OBJ file and the MTL files it names. Throws InputError with a one-line message naming
// the file on: a missing or unreadable file, an empty model, indices out of range, non-finite
// numbers, a missing material library.
ModelData loadObjModel(const std::filesystem::path& path);

}  // namespace common
