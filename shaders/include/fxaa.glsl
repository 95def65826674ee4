// FXAA: fast approximate anti-aliasing as a post-process (after Timothy Lottes, NVIDIA 2009; this
// is the compact "FXAA 2 / console" form). It finds the local edge direction from the luma of
// the four diagonal neighbours and blurs along it, with bilinear taps; if the wider blur brings in
// luma outside the neighbourhood's range, it keeps the narrower one.
//> fxaa
const float FXAA_REDUCE_MIN = 1.0 / 128.0;
const float FXAA_REDUCE_MUL = 1.0 / 8.0;
const float FXAA_SPAN_MAX = 8.0;

// Luma of a linear colour, on a perceptual (roughly gamma 2) scale, where edges are judged.
float fxaaLuma(vec3 linearColor) {
    return sqrt(dot(linearColor, vec3(0.299, 0.587, 0.114)));
}

vec3 fxaa(sampler2D image, vec2 uv) {
    vec2 texel = 1.0 / vec2(textureSize(image, 0));
    float lumaNW = fxaaLuma(texture(image, uv + vec2(-1.0, -1.0) * texel).rgb);
    float lumaNE = fxaaLuma(texture(image, uv + vec2(1.0, -1.0) * texel).rgb);
    float lumaSW = fxaaLuma(texture(image, uv + vec2(-1.0, 1.0) * texel).rgb);
    float lumaSE = fxaaLuma(texture(image, uv + vec2(1.0, 1.0) * texel).rgb);
    vec3 center = texture(image, uv).rgb;
    float lumaM = fxaaLuma(center);
    float lumaMin = min(lumaM, min(min(lumaNW, lumaNE), min(lumaSW, lumaSE)));
    float lumaMax = max(lumaM, max(max(lumaNW, lumaNE), max(lumaSW, lumaSE)));

    vec2 direction = vec2(-((lumaNW + lumaNE) - (lumaSW + lumaSE)), (lumaNW + lumaSW) - (lumaNE + lumaSE));
    float reduce = max((lumaNW + lumaNE + lumaSW + lumaSE) * 0.25 * FXAA_REDUCE_MUL, FXAA_REDUCE_MIN);
    float scale = 1.0 / (min(abs(direction.x), abs(direction.y)) + reduce);
    direction = clamp(direction * scale, vec2(-FXAA_SPAN_MAX), vec2(FXAA_SPAN_MAX)) * texel;

    vec3 narrow = 0.5 * (texture(image, uv + direction * (1.0 / 3.0 - 0.5)).rgb +
                         texture(image, uv + direction * (2.0 / 3.0 - 0.5)).rgb);
    vec3 wide = narrow * 0.5 + 0.25 * (texture(image, uv - direction * 0.5).rgb +
                                       texture(image, uv + direction * 0.5).rgb);
    float lumaWide = fxaaLuma(wide);
    return (lumaWide < lumaMin || lumaWide > lumaMax) ? narrow : wide;
}
//< fxaa
