// The tone curve: the ACES filmic fit by Narkowicz 2015 ("ACES Filmic Tone Mapping Curve").
// Shared by the tone mapper and the voxel debug views, which tone-map radiance themselves.

vec3 acesFilmic(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}
