// tinygltf's implementation, compiled once, against the nlohmann-json and stb the rest of the
// build uses (tinygltf's repository carries copies of both). Only built where tinygltf comes as a
// bare header (cmake/Dependencies.cmake): Debian's libtinygltf has it compiled.
#include <stb_image.h>
#include <stb_image_write.h>
#include <nlohmann/json.hpp>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_INCLUDE_JSON
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_INCLUDE_STB_IMAGE_WRITE
#include <tiny_gltf.h>
