// The implementations of the stb headers the repository uses, compiled once. Only built where
// stb comes without them (cmake/Dependencies.cmake): Debian's libstb already has them compiled.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_RESIZE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_resize.h>
#include <stb_image_write.h>
