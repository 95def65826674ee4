// chapter-15 light pass: the shading of one G-buffer pixel by the scene's lights, put together
// from its parts -- the lights, scene info and push constants (light_inputs.glsl), the G-buffer
// (gbuffer_read.glsl), the loop over the lights (light_loop.glsl) and the pixel's colour
// (shade_pixel.glsl). light.frag runs it for each pixel of a full-screen triangle.
#include "light_inputs.glsl"
#include "gbuffer_read.glsl"
#include "light_loop.glsl"
#include "shade_pixel.glsl"
