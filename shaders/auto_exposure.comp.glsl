#version 450 core
// Auto exposure, step 2 (AutoExposurePass): from the log-luminance histogram, the exposure that
// maps the scene's mean log luminance to the key value, approached from the previous exposure.
// One work group of LIT_EXPOSURE_BINS threads; clears the histogram for the next frame.
#include "shared.h"

layout(local_size_x = LIT_EXPOSURE_BINS) in;

layout(std430, binding = LIT_SSBO_LUMINANCE_HISTOGRAM) buffer Histogram { uint bins[]; };
layout(std430, binding = LIT_SSBO_EXPOSURE) buffer Exposure { vec4 exposure; };  // x 2^y, y stops, z mean log2 L, w metered

uniform float uKey;             // luminance the mean maps to (0.18: middle grey)
uniform float uCompensationEv;  // stops added to the metered exposure
uniform float uMinEv, uMaxEv;   // clamp of the exposure (stops)
uniform float uBlend;           // share of the way to the target taken this frame (1 = at once)

shared uint counts[LIT_EXPOSURE_BINS];

void main() {
    uint bin = gl_LocalInvocationIndex;
    counts[bin] = bins[bin];
    bins[bin] = 0u;
    barrier();
    if (bin != 0u) return;

    uint metered = 0u;
    for (int i = 1; i < LIT_EXPOSURE_BINS; ++i) metered += counts[i];
    if (metered == 0u) return;  // a black image: keep the exposure it had
    // Mean of bin centres between the low and high quantiles of the metered (non-black) pixels.
    float low = LIT_EXPOSURE_LOW_PERCENT * float(metered), high = LIT_EXPOSURE_HIGH_PERCENT * float(metered);
    float binWidth = (LIT_EXPOSURE_LOG2_MAX - LIT_EXPOSURE_LOG2_MIN) / float(LIT_EXPOSURE_BINS - 1);
    float below = 0.0, sum = 0.0, weight = 0.0;
    for (int i = 1; i < LIT_EXPOSURE_BINS; ++i) {
        float n = float(counts[i]);
        // The part of this bin's pixels that lies between the quantiles.
        float inside = clamp(below + n, low, high) - clamp(below, low, high);
        float centre = LIT_EXPOSURE_LOG2_MIN + (float(i - 1) + 0.5) * binWidth;
        sum += inside * centre;
        weight += inside;
        below += n;
    }
    float meanLog2 = weight > 0.0 ? sum / weight : 0.0;
    float target = clamp(log2(uKey) - meanLog2 + uCompensationEv, uMinEv, uMaxEv);
    float ev = mix(exposure.w > 0.0 ? exposure.y : target, target, uBlend);
    exposure = vec4(exp2(ev), ev, meanLog2, 1.0);
}
