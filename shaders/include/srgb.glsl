// The sRGB transfer function (IEC 61966-2-1) both ways. A pass that writes a presented image
// encodes with it when the image's format does not (a _UNORM format: common/vk/formats.hpp); the GUI
// decodes Dear ImGui's sRGB-authored colours with it where it must blend in linear light.
#ifndef SRGB_GLSL
#define SRGB_GLSL

vec3 encodeSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

vec3 decodeSrgb(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

#endif
