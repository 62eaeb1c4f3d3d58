#version 450 core
// Tone mapping: exposure, then the ACES filmic curve fitted by Narkowicz 2015 ("ACES Filmic Tone
// Mapping Curve"), written to an sRGB target (the hardware applies the sRGB transfer function).
#include "frame.glsl"
#include "tonemap.glsl"

in vec2 vUv;
layout(location = 0) out vec4 outColor;

layout(binding = LIT_TEX_HDR_INPUT) uniform sampler2D hdrImage;
uniform int uDataView;  // 1: the input holds display values (albedo, normals...): no tone mapping

void main() {
    vec3 hdr = texelFetch(hdrImage, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 color = uDataView != 0 ? clamp(hdr, 0.0, 1.0) : acesFilmic(max(hdr, 0.0) * frame.exposure.x);
    outColor = vec4(color, 1.0);
}
