// tinyobjloader's implementation, compiled with the fuzzing instrumentation (the main build links
// Debian's shared library instead; same float variant).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
