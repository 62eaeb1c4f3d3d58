// Reduced-resolution and temporally accumulated indirect lighting (docs/GI.md, "Reduced
// resolution and temporal accumulation"): what the low-resolution trace (indirect_trace.frag.glsl)
// and the resolve (indirect_resolve.frag.glsl) share. Needs frame.glsl, gbuffer.glsl, cone.glsl.
//
// Both terms are traced *demodulated*: L_ID / (albedo_d · intensity · AO) = irradiance/π and
// L_IS / (E · intensity · AO) = ⟨L⟩, the lobe-averaged radiance. These vary slowly across a
// surface, so a few traced pixels can stand for their neighbours, and the resolve multiplies the
// per-pixel material back in: textures and albedo edges stay at full resolution.
//
// The cone sets can be turned about the normal by `rotation` (radians) each frame; the five side
// cones of the diffuse set repeat every 72°, so LIT_DIFFUSE_ROTATION_STEPS steps of 72°/steps
// make the accumulated result see that many times more directions. With rotation 0 these give
// exactly cone.glsl's traceDiffuse / traceSpecular (÷ E).

uniform int uScale;       // indirect scale s: one traced pixel per s × s block
uniform ivec2 uJitter;    // which pixel of its block (0..s−1 each) a low-resolution texel traces
uniform float uRotation;  // rad: this frame's turn of the cone sets about the normal

// The full-resolution pixel that low-resolution texel `low` traces.
ivec2 tracedPixel(ivec2 low) {
    return min(low * uScale + uJitter, ivec2(frame.viewport.xy) - 1);
}

mat3 rotatedTangentFrame(vec3 n, float rotation) {
    float c = cos(rotation), s = sin(rotation);
    return tangentFrame(n) * mat3(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);
}

// traceDiffuse of cone.glsl in the frame `basis` (irradiance/π; cones[] gets each cone's C_i).
vec3 traceDiffuseInFrame(vec3 origin, mat3 basis, float aperture, float maxDistance,
                         out vec3 cones[kDiffuseConeCount]) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < kDiffuseConeCount; ++i) {
        cones[i] = traceCone(origin, basis * kDiffuseConeDirections[i], aperture, maxDistance).rgb;
        sum += kDiffuseConeWeights[i] * cones[i];
    }
    return sum;
}

// traceSpecular of cone.glsl without the directional albedo E (the lobe-averaged radiance ⟨L⟩),
// with the diffuse cones `cones` traced in `basis` when `reuseDiffuse`.
vec3 traceSpecularLobe(vec3 origin, vec3 n, mat3 basis, vec3 v, float roughness, int count, vec2 pixel, int frameIndex,
                       float maxDistance, bool reuseDiffuse, vec3 cones[kDiffuseConeCount]) {
    float alpha = alphaFromRoughness(roughness);
    float aperture = specularConeAperture(alpha, count);
    vec3 weightedRadiance = vec3(0.0);
    float weightSum = 0.0;
    for (int k = 0; k < count; ++k) {
        vec3 h = basis * sampleGgxHalfVector(specularSample(k, count, pixel, frameIndex), alpha);
        vec3 l;
        float w = ggxSampleWeight(n, v, h, alpha, l);
        if (w <= 0.0) continue;
        vec3 radiance = reuseDiffuse ? radianceFromDiffuseCones(normalize(l * basis), cones)
                                     : traceCone(origin, l, aperture, maxDistance).rgb;
        weightedRadiance += w * radiance;
        weightSum += w;
    }
    if (weightSum <= 0.0) {
        vec3 mirror = reflect(-v, n);
        weightedRadiance = reuseDiffuse ? radianceFromDiffuseCones(normalize(mirror * basis), cones)
                                        : traceCone(origin, mirror, aperture, maxDistance).rgb;
        weightSum = 1.0;
    }
    return weightedRadiance / weightSum;
}
