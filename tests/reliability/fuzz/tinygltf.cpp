// tinygltf's implementation, compiled with the fuzzing instrumentation (the main build links
// Debian's shared library instead). Its image decoding is left out: our loader installs its own
// image callback, which keeps the encoded bytes (common/model/gltf_model.cpp).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
