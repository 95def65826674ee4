// --view depth: a depth value of a perspective projection with depth range 0..1 shown as grey.
// Depth goes back to eye distance, then to a logarithmic scale: near is white, the far plane
// (the clear value) black. Used by the light passes of chapters 10, 14 and 15.
//> depth-view
float depthToGrey(float depth, float near, float far) {
    float distance = near * far / (far - depth * (far - near));
    return 1.0 - log(distance / near) / log(far / near);
}
//< depth-view
