#version 450 core
// Auto exposure, step 1 (AutoExposurePass): a histogram of log2 luminance of the HDR image.
// Each work group counts its 16×16 pixels in shared memory, then adds its counts to the global
// histogram (one atomic per bin and group instead of one per pixel).
#include "shared.h"

layout(local_size_x = LIT_EXPOSURE_GROUP_SIZE, local_size_y = LIT_EXPOSURE_GROUP_SIZE) in;

layout(binding = LIT_TEX_HDR_INPUT) uniform sampler2D hdrImage;
layout(std430, binding = LIT_SSBO_LUMINANCE_HISTOGRAM) buffer Histogram { uint bins[]; };

shared uint localBins[LIT_EXPOSURE_BINS];

// Bin of a luminance: 0 for black (below 2^LIT_EXPOSURE_LOG2_MIN), else 1..BINS−1 over the range.
uint binOf(float luminance) {
    if (luminance < exp2(LIT_EXPOSURE_LOG2_MIN)) return 0u;
    float t = (log2(luminance) - LIT_EXPOSURE_LOG2_MIN) / (LIT_EXPOSURE_LOG2_MAX - LIT_EXPOSURE_LOG2_MIN);
    return uint(clamp(t * float(LIT_EXPOSURE_BINS - 1), 0.0, float(LIT_EXPOSURE_BINS - 2))) + 1u;
}

void main() {
    uint local = gl_LocalInvocationIndex;
    if (local < uint(LIT_EXPOSURE_BINS)) localBins[local] = 0u;
    barrier();
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(pixel, textureSize(hdrImage, 0)))) {
        vec3 rgb = max(texelFetch(hdrImage, pixel, 0).rgb, vec3(0.0));
        float luminance = dot(rgb, vec3(0.2126, 0.7152, 0.0722));  // Rec. 709 / sRGB primaries
        atomicAdd(localBins[binOf(luminance)], 1u);
    }
    barrier();
    if (local < uint(LIT_EXPOSURE_BINS) && localBins[local] > 0u) atomicAdd(bins[local], localBins[local]);
}
