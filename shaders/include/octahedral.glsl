// Octahedral normal encoding (Cigolle, Donow, Evangelakos, Mara, McGuire, Meyer, "A Survey of
// Efficient Representations for Independent Unit Vectors", JCGT 2014): a unit vector projected
// onto the octahedron |x| + |y| + |z| = 1, the lower half folded over the upper, gives two
// numbers in [-1, 1]. In 2 x 16-bit UNORM the mean angular error is about 0.0014 degrees.
#ifndef OCTAHEDRAL_GLSL
#define OCTAHEDRAL_GLSL

//> octahedral
vec2 signNotZero(vec2 v) {
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

// Unit vector -> [0, 1]^2 (for a UNORM attachment).
vec2 encodeOctahedral(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    if (n.z < 0.0) p = (1.0 - abs(p.yx)) * signNotZero(p);
    return p * 0.5 + 0.5;
}

// [0, 1]^2 -> unit vector.
vec3 decodeOctahedral(vec2 e) {
    vec2 p = e * 2.0 - 1.0;
    vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * signNotZero(n.xy);
    return normalize(n);
}
//< octahedral

#endif
