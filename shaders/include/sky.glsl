// The sky: what the background shows and what cones that leave the voxel volume (or reach the
// trace distance) receive. The GLSL twin of renderer/scene/Sky.cpp's skyRadiance; the GL test
// tests/gl/test_sky.cpp evaluates both for the same directions and requires them to agree.
// Radiance in W/(sr·m²); the parameters come from FrameUniforms (RenderSettings sky fields).
#include "frame.glsl"

layout(binding = LIT_TEX_SKY) uniform sampler2D skyImage;

const float kSkyPi = 3.14159265358979;

// Equirectangular lookup: u = 0.5 + atan(x, −z)/2π (−Z, where cameras look, in the middle),
// v = acos(y)/π (row 0 straight up). `lod` > 0 blurs for wide cones (the image is mipmapped).
vec3 skyImageRadiance(vec3 d, float lod) {
    vec2 uv = vec2(0.5 + atan(d.x, -d.z) / (2.0 * kSkyPi), acos(clamp(d.y, -1.0, 1.0)) / kSkyPi);
    return textureLod(skyImage, uv, lod).rgb;
}

vec3 skyRadianceLod(vec3 direction, float lod) {
    int mode = int(frame.skyZenith.w);
    if (mode == LIT_SKY_NONE) return vec3(0.0);
    vec3 d = normalize(direction);
    vec3 radiance;
    if (mode == LIT_SKY_UNIFORM) {
        radiance = frame.skyZenith.rgb;
    } else if (mode == LIT_SKY_GRADIENT) {
        radiance = d.y >= 0.0 ? mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, sqrt(d.y))
                              : mix(frame.skyHorizon.rgb, frame.skyGround.rgb, min(1.0, -d.y * LIT_SKY_GROUND_BLEND));
    } else {
        radiance = skyImageRadiance(d, lod);
    }
    return radiance * frame.skyHorizon.w;
}

vec3 skyRadiance(vec3 direction) { return skyRadianceLod(direction, 0.0); }

// What a cone of full apex angle `aperture` (rad) sees of the sky along `direction`: the image
// is read at the mip level whose texels are about as wide as the cone (2π/width rad per texel).
vec3 skyConeRadiance(vec3 direction, float aperture) {
    float lod = 0.0;
    if (int(frame.skyZenith.w) == LIT_SKY_HDR)
        lod = log2(max(1.0, aperture * float(textureSize(skyImage, 0).x) / (2.0 * kSkyPi)));
    return skyRadianceLod(direction, lod);
}
