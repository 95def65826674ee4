// chapter-15, beyond the book: reading the last frame back. --check-output fails the run on a
// NaN, infinite or negative value in the light output; --dump writes the light output and the
// G-buffer, decoded to floats, as PFM files for the accuracy tools (tests/accuracy/); without the
// G-buffer (withGBuffer false: --shading forward), the light output and the distances only.
#pragma once

#include <filesystem>

#include "common/device.hpp"
#include "light_pass.hpp"
#include "scene_pass.hpp"

void checkLightOutput(const common::Device& device, const LightPass& lightPass);
void dumpFrame(const common::Device& device, const LightPass& lightPass, const ScenePass& scenePass,
               const LightView& view, const std::filesystem::path& directory, bool withGBuffer = true);
