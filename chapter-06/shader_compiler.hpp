// chapter-06: the book's ShaderCompiler -- GLSL compiled to SPIR-V with shaderc while the program
// runs, when the source is newer than the SPIR-V the build made.
//
// Deliberate repetition: common/shaders/shader_compiler.cpp holds the same shaderc calls for the later
// chapters (with live reload); this chapter introduces them, so here they are.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "common/shaders/shader_watch.hpp"

// The book's compileShader: one GLSL file (with its macro definitions and #includes) to SPIR-V
// words. A compile error throws common::InputError with the compiler's "file:line: error: ..."
// (exit code 2).
std::vector<uint32_t> compileShader(const common::ShaderSource& source);

// The book's compileShaderIfChanged: the SPIR-V for a shader name ("chapter-06/triangle.frag"),
// compiled from its GLSL when the GLSL (or a file it includes) is newer than the build's .spv,
// else the build's .spv; also when the sources are not found (a copied bin/) or this build has
// no shaderc. Compiled code that does not fit the pipeline made for the build's shader throws
// common::InputError. Where the sources are found, the shader is watched for edits from then on
// (live reload, common/shaders/shader_compiler.hpp).
std::vector<uint32_t> compileShaderIfChanged(std::string_view name);
