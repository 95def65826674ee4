// chapter-15-lab: --dump.
#include "output_dump.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/vk/screenshot.hpp"

// --dump DIR: the last frame's light output, light.pfm; the distance from the camera plane of
// each pixel's surface, distance.pfm (from the depth attachment: it tells which surface a layout
// sees); and -- for the layouts that store floats -- the G-buffer as position/albedo/normal/pbr.pfm
// plus coverage.pfm (1 where a surface is). The accuracy tools (tests/accuracy/) shade these on
// the CPU in double precision.
void dumpFrame(const common::Device& device, const LightPass& lightPass, const ScenePass& scenePass,
               const LightView& view, const std::filesystem::path& directory, bool withGBuffer) {
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    VkExtent2D extent = lightPass.output.extent;
    common::writePfm(directory / "light.pfm", extent.width, extent.height,
                     common::readFloatImage(device, lightPass.output.handle, kLightOutputFormat, extent,
                                            VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL),
                     3);
    std::vector<float> distance =
        common::readFloatImage(device, scenePass.gbuffer.depth.handle, scenePass.formats.depth, extent,
                               VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    for (size_t i = 0; i < distance.size();
         i += 4) {  // depth.glsl's eyeDistance(), planes swapped when reversed
        bool reversed = scenePass.layout->reversedZ;
        double n = reversed ? view.far : view.near, f = reversed ? view.near : view.far;
        distance[i] = float(n * f / (f - double(distance[i]) * (f - n)));
    }
    common::writePfm(directory / "distance.pfm", extent.width, extent.height, distance, 1);
    if (!withGBuffer) {  // --shading forward draws none
        std::printf("chapter-15-lab: wrote %s\n", common::utf8(directory).c_str());
        return;
    }
    if (scenePass.layout->formats.position == VK_FORMAT_UNDEFINED) {  // the compact layout
        // The compact normals, decoded (octahedral.glsl's decodeOctahedral): which surface each pixel shows.
        const common::Image& normals = scenePass.gbuffer.normal;
        std::vector<float> texels = common::readFloatImage(device, normals.handle, normals.format, extent,
                                                           VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
        for (size_t i = 0; i < texels.size(); i += 4) {
            glm::vec2 p(texels[i] * 2.0f - 1.0f, texels[i + 1] * 2.0f - 1.0f);
            glm::vec3 n(p, 1.0f - std::abs(p.x) - std::abs(p.y));
            if (n.z < 0.0f)
                n = glm::vec3((1.0f - std::abs(n.y)) * (n.x >= 0 ? 1.0f : -1.0f),
                              (1.0f - std::abs(n.x)) * (n.y >= 0 ? 1.0f : -1.0f), n.z);
            n = glm::normalize(n);
            texels[i] = n.x, texels[i + 1] = n.y, texels[i + 2] = n.z;
        }
        common::writePfm(directory / "normal.pfm", extent.width, extent.height, texels, 3);
        return;
    }
    const std::pair<const char*, const common::Image*> attachments[] = {
        {"position", &scenePass.gbuffer.position},
        {"albedo", &scenePass.gbuffer.albedo},
        {"normal", &scenePass.gbuffer.normal},
        {"pbr", &scenePass.gbuffer.pbr}};
    for (const auto& [name, image] : attachments) {
        std::vector<float> texels = common::readFloatImage(device, image->handle, image->format, extent,
                                                           VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
        common::writePfm(directory / (std::string(name) + ".pfm"), extent.width, extent.height, texels, 3);
        if (image == &scenePass.gbuffer.albedo)  // its alpha: 1 where a surface is
            common::writePfm(directory / "coverage.pfm", extent.width, extent.height, texels, 1, 3);
    }
    std::printf("chapter-15-lab: wrote %s\n", common::utf8(directory).c_str());
}
