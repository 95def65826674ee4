// The book's own converted models: what its ModelGenerator writes from a model Assimp reads -- a
// JSON file naming each mesh's byte ranges in a .vtx and an .idx file, and NAME_mat.json beside it
// with the materials. The book's chapter 16 ships its tree only so (resources/models/tree/
// tree.json), not as glTF; chapter-16's --book-scene loads it from there.
//
// The format, from the book's ModelGenerator.java (booksamples/chapter-16 of
// github.com/lwjglgamedev/vulkanbook): big-endian (Java's DataOutputStream) 32-bit floats, 14 a
// vertex -- position, normal, tangent, bitangent, texture coordinates with v already top-down --
// and 32-bit indices, each mesh's counted from its own first vertex; the JSON gives each mesh's
// "offset_vtx", "vtx_size", "offset_idx", "idx_size" in bytes and its "material_id"; the
// materials' "texture_path", "normal_map_path" and "metal_rough_map" are paths from the book's
// sample directory (with Windows' backslashes), looked up beside the JSON by file name.
#pragma once

#include <filesystem>

#include "common/model/model.hpp"

namespace common {

// InputError naming the file and the problem for anything the format does not allow or our
// limits refuse (common/model/model.hpp): a missing or malformed file or field, a byte range outside
// its file or not a whole number of vertices or triangles, an index past its mesh's vertices, a
// value that is not finite.
ModelData loadBookModel(const std::filesystem::path& json);

}  // namespace common
