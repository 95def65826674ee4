// chapter-15: the G-buffer layout, described once. Everything that depends on the layout reads
// this description: the --gbuffer option's names, the attachments' formats (and through them the
// scene pipeline and the light pass), the bytes per pixel that --benchmark reports, reversed-Z
// (depth test, depth clear, projection, reconstruction), the shader variant, and --dump.
//
// The book has one layout, kBookGBuffer below. The others are beyond the book and live in
// beyond/gbuffer_layouts.cpp.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "common/gbuffer.hpp"

struct GBufferLayout {
    const char* name;     // --gbuffer NAME
    const char* summary;  // for --help
    common::GBufferFormats formats;
    // Depth 1 at the near plane and 0 at the far one: the depth test is GREATER_OR_EQUAL, depth is
    // cleared to 0, and the projection swaps its planes (beyond/gbuffer_layouts.cpp).
    bool reversedZ;
    // Which compiled shaders: scene<suffix>.frag, light<suffix>.frag, light<suffix>.comp.
    const char* shaderSuffix;
};

//> book-gbuffer
// The book's G-buffer: world position, albedo, normal and (AO, roughness, metallic), each
// R16G16B16A16_SFLOAT, and D32_SFLOAT depth: 4 x 8 + 4 = 36 bytes per pixel.
inline constexpr GBufferLayout kBookGBuffer{
    .name = "book",
    .summary = "the book's: position, albedo, normal, AO/roughness/metallic, all RGBA16F",
    .formats = {.position = VK_FORMAT_R16G16B16A16_SFLOAT,
                .albedo = VK_FORMAT_R16G16B16A16_SFLOAT,
                .normal = VK_FORMAT_R16G16B16A16_SFLOAT,
                .pbr = VK_FORMAT_R16G16B16A16_SFLOAT,
                .depth = VK_FORMAT_D32_SFLOAT},
    .reversedZ = false,
    .shaderSuffix = "",
};
//< book-gbuffer

// Every layout --gbuffer offers, the book's first (the default): beyond/gbuffer_layouts.cpp.
const std::vector<const GBufferLayout*>& gbufferLayouts();
// Their names, in that order, and a --help line giving each one's bytes per pixel.
std::vector<std::string> gbufferLayoutNames();
std::string gbufferLayoutHelp();
