// Linked into every program of a sanitizer build (-DVKBOOK_SANITIZE=ON or -DVKBOOK_TSAN=ON) only.
//
// The Vulkan loader dlclose()s the driver (lavapipe) and the layers at vkDestroyInstance, before
// LeakSanitizer looks for leaks at exit. Anything those libraries leaked would then be reported
// with "<unknown module>" frames: impossible to attribute, so impossible to suppress by library
// in tests/reliability/sanitizer/lsan.supp. This definition interposes the C library's dlclose for the whole
// process (the loader's reference binds to the executable's symbol first) and leaves every
// library loaded until exit, which is all a short-lived program loses by it.
extern "C" int dlclose(void*) {
    return 0;
}
