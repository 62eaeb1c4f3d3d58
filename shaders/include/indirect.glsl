// Reduced-resolution and temporally accumulated indirect lighting (docs/GI.md, "Reduced
// resolution and temporal accumulation"): what the low-resolution trace (indirect_trace.frag.glsl)
// and the resolve (indirect_resolve.frag.glsl) share. Needs frame.glsl, gbuffer.glsl, cone.glsl.
#include "bfloat.glsl"
#include "octahedral.glsl"
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

// The turn the cone sets take this frame. Footprint-bounded cones (LIT_CONE_FOOTPRINT, the
// accurate mode) see along their axes only, so their result depends on the set's rotation:
// turning it every frame made a still camera's L_ID change 9.6 % from frame to frame and the
// cornell_inside path flicker 5.4 % (320×180, 128³); with the set fixed, 0.4 % (docs/GI.md,
// "Approaches that did not work").
// They keep rotation 0, the set a still without temporal accumulation traces.
float coneSetRotation() {
#if LIT_CONE_FOOTPRINT
    return 0.0;
#else
    return uRotation;
#endif
}

// The full-resolution pixel that low-resolution texel `low` traces.
ivec2 tracedPixel(ivec2 low) {
    return min(low * uScale + uJitter, ivec2(frame.viewport.xy) - 1);
}

// The low-resolution targets, one texel per traced pixel, packed so the resolve reads a
// neighbour with two fetches (on llvmpipe the resolve's cost is its texel fetches):
//   packed (RGBA32UI): bfloat2(D.rg), bfloat2(D.b, 1 = D traced), bfloat2(S.rg), bfloat2(S.b, 1 +
//            roughness = S traced) (bfloat.glsl: cheaper than halves for the resolve; the
//            roughness to 1/128, the same for neighbours of one material, whose weights it scales alike)
//   guide  (RGBA32UI): the traced pixel's world position (float bits, m), octahedral normal (snorm16 ×2)
// D = irradiance/π, S = lobe-averaged radiance ⟨L⟩ (0 where not traced).
uvec4 packIndirect(vec4 diffuse, vec4 specular) {
    return uvec4(packBfloat2(diffuse.rg), packBfloat2(diffuse.ba), packBfloat2(specular.rg), packBfloat2(specular.ba));
}
void unpackIndirect(uvec4 bits, out vec4 diffuse, out vec4 specular) {
    diffuse = vec4(unpackBfloat2(bits.x), unpackBfloat2(bits.y));
    specular = vec4(unpackBfloat2(bits.z), unpackBfloat2(bits.w));
}

uvec4 packGuide(vec3 position, vec3 normal) {
    return uvec4(floatBitsToUint(position), packSnorm2x16(octEncode(normal)));
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
        cones[i] = traceDiffuseCone(origin, basis, i, aperture, maxDistance);
        sum += kDiffuseConeWeights[i] * cones[i];
    }
    return sum;
}

// traceSpecularLobe (the lobe-averaged radiance without the directional albedo) is in cone.glsl.
