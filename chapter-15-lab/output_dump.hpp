// chapter-15-lab: reading the last frame back (--check-output is chapter-15's checkLightOutput).
// --dump writes the light output and the G-buffer, decoded to floats, as PFM files for the
// accuracy tools (tests/accuracy/); without the G-buffer (withGBuffer false: --shading forward),
// the light output and the distances only.
#pragma once

#include <filesystem>

#include "chapter-15/light_pass.hpp"
#include "chapter-15/scene_pass.hpp"
#include "common/vk/device.hpp"

void dumpFrame(const common::Device& device, const LightPass& lightPass, const ScenePass& scenePass,
               const LightView& view, const std::filesystem::path& directory, bool withGBuffer = true);
