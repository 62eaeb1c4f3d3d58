#version 450 core
// Tone mapping: exposure, then the ACES filmic curve fitted by Narkowicz 2015 ("ACES Filmic Tone
// Mapping Curve"), written to an sRGB target (the hardware applies the sRGB transfer function).
#include "frame.glsl"
#include "tonemap.glsl"

in vec2 vUv;
layout(location = 0) out vec4 outColor;

layout(binding = LIT_TEX_HDR_INPUT) uniform sampler2D hdrImage;
uniform int uDataView;  // 1: the input holds display values (albedo, normals...): no tone mapping
uniform int uAutoExposure;  // 1: the metered exposure of AutoExposurePass, else frame.exposure.x (2^exposureEv)
layout(std430, binding = LIT_SSBO_EXPOSURE) readonly buffer Exposure { vec4 meteredExposure; };  // x multiplier

void main() {
    vec3 hdr = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0).rgb;
    float exposure = uAutoExposure != 0 ? meteredExposure.x : frame.exposure.x;
    vec3 color = uDataView != 0 ? clamp(hdr, 0.0, 1.0) : acesFilmic(max(hdr, 0.0) * exposure);
    outColor = vec4(color, 1.0);
}
