// chapter-15 light pass: shadePixel(), the colour of one pixel -- lit, or the attachment --view
// asks for. Needs readGBuffer() and shadeLights() declared first (light_shading.glsl).

//> shade-pixel
// `s`: what the G-buffer holds at the pixel (readGBuffer); `pixel`: its integer coordinates;
// `sunLight`: how much of the sun reaches the pixel (1.0 without shadows; light_loop.glsl).
vec4 shadePixel(SurfaceSample s, ivec2 pixel, float sunLight) {
    if (show.view == 1) {
        vec3 world = s.position + scene.cameraPosition;
        return vec4(s.surface ? clamp((world - show.boundsMin.xyz) / (show.boundsMax.xyz - show.boundsMin.xyz), 0.0, 1.0)
                              : vec3(0.0), 1.0);
    } else if (show.view == 2) {
        return vec4(s.albedo, 1.0);
    } else if (show.view == 3) {
        return vec4(s.surface ? s.normal * 0.5 + 0.5 : vec3(0.0), 1.0);
    } else if (show.view == 4) {
        return vec4(s.pbr, 1.0);
    } else if (show.view == 5) {
        float distance = show.reversedZ != 0 ? eyeDistance(s.depth, show.far, show.near)
                                             : eyeDistance(s.depth, show.near, show.far);
        return vec4(vec3(distanceToGrey(distance, show.near, show.far)), 1.0);
    } else if (!s.surface) {
        return vec4(0.0, 0.0, 0.0, 1.0);  // nothing was drawn here: no surface to light
    } else {
        vec3 N = surfaceNormal(s.normal);
        vec3 V = viewDirection(s.position, vec3(0.0), N);  // the camera is the origin here
        // Ambient light, darkened by the surface's occlusion (glTF applies occlusion maps to
        // indirect light only: the lights are not).
        vec3 color = scene.ambientColor * scene.ambientIntensity * s.albedo * s.pbr.r;
        return vec4(color + shadeLights(pixel, s, N, V, sunLight), 1.0);
    }
}
//< shade-pixel
