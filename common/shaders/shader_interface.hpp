// The interface check of live reload: whether SPIR-V compiled from an edited source still fits the
// pipeline the C++ made for the build's SPIR-V of the same shader. A reload changes shader code
// only; the pipeline layout, descriptor set layouts, buffers bound, vertex input, attachments,
// specialization data and dispatch sizes stay as the C++ made them. docs/live-shaders.md lists
// the rules with an example message each.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace common {

// Empty when `edited` fits what the C++ made for `built` (both whole SPIR-V modules of one
// shader stage); else why not, in one line naming the binding, block member, location or
// constant and both types or sizes ("set 2 binding 0 (uniform block Scene): member extraTint
// (vec4[64], bytes 32..1055) lies past the 32 bytes the shader its pipeline was made for
// declares"). Reflection by SPIRV-Cross; without it (a build without runtime compilation)
// nothing is compared.
std::string shaderInterfaceChange(const std::vector<uint32_t>& built, const std::vector<uint32_t>& edited);

// Empty when every constant `specialization` sets is one the SPIR-V declares, with a value of its
// size (4 bytes for bool, int, uint and float); else why not, naming the constant_id. Vulkan
// ignores a map entry whose ID the shader does not declare, so a mistyped constant_id would
// leave the constant at its default without a word. Without SPIRV-Cross nothing is checked.
std::string specializationMismatch(const std::vector<uint32_t>& spirv,
                                   const VkSpecializationInfo& specialization);

}  // namespace common
