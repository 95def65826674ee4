// --view depth: a depth value shown as grey. eyeDistance() inverts a perspective projection with
// depth range 0..1 whose near and far planes are `near` and `far` (for reversed-Z, pass them
// swapped: depth 1 at the near plane); distanceToGrey() maps the distance to a logarithmic grey
// scale, near white, far (and the cleared background) black. Used by chapters 10, 14 and 15.
//> depth-view
float eyeDistance(float depth, float near, float far) {
    return near * far / (far - depth * (far - near));
}

float distanceToGrey(float distance, float near, float far) {
    return clamp(1.0 - log(distance / near) / log(far / near), 0.0, 1.0);
}

float depthToGrey(float depth, float near, float far) {
    return distanceToGrey(eyeDistance(depth, near, far), near, far);
}
//< depth-view
