// chapter-15: the G-buffer layout, described once. Everything that depends on the layout reads
// this description: the attachments' formats (and through them the scene pipeline and the light
// pass's set 0), the bytes per pixel that --benchmark reports, and the depth convention (depth
// test, depth clear, and the light pass's depth view).
#pragma once

#include <vulkan/vulkan.h>

#include "common/passes/gbuffer.hpp"

struct GBufferLayout {
    const char* name;
    common::GBufferFormats formats;  // an attachment whose format is UNDEFINED is not made
    // Depth 1 at the near plane and 0 at the far one (reversed-Z): the depth test is
    // GREATER_OR_EQUAL and depth is cleared to 0. The book's depth is 0 at the near plane.
    bool reversedZ;
};

//> book-gbuffer
// The book's G-buffer: world position, albedo, normal and (AO, roughness, metallic), each
// R16G16B16A16_SFLOAT, and D32_SFLOAT depth: 4 x 8 + 4 = 36 bytes per pixel. (A device that cannot
// render to D32_SFLOAT gets X8_D24_UNORM_PACK32, the same 4 bytes: chapter-15/scene_pass.cpp.)
inline constexpr GBufferLayout kBookGBuffer{
    .name = "book",
    .formats = {.position = VK_FORMAT_R16G16B16A16_SFLOAT,
                .albedo = VK_FORMAT_R16G16B16A16_SFLOAT,
                .normal = VK_FORMAT_R16G16B16A16_SFLOAT,
                .pbr = VK_FORMAT_R16G16B16A16_SFLOAT,
                .depth = VK_FORMAT_D32_SFLOAT},
    .reversedZ = false,
};
//< book-gbuffer
