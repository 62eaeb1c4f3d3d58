#pragma once
// The Difference view's false colour: the signed relative error of an image (the VCT) against the
// reference, per pixel, on luminance, e = (L_test − L_ref) / max(L_ref, floor), shown on a
// diverging ramp: blue = too dark (e ≤ −max), white = right (e = 0), red = too bright (e ≥ +max).
// `floor` keeps black reference pixels from dividing by zero: a fraction of the image's mean.

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lit::reference {

// A linear value in [0, 1] (clamped) as an 8-bit sRGB code: the sRGB transfer function (IEC 61966-2-1).
inline std::uint8_t encodeSrgb8(float linear) {
    const float v = std::clamp(linear, 0.0f, 1.0f);
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

// Display colours (3 floats per pixel in [0, 1], as relativeErrorColours gives them) as sRGB-encoded
// RGBA8, alpha 255: what a PNG or an sRGB texture of the Difference view holds.
inline std::vector<std::uint8_t> displayColoursToRgba8(const std::vector<float>& colours) {
    std::vector<std::uint8_t> rgba(colours.size() / 3 * 4, 255);
    for (std::size_t p = 0; p < colours.size() / 3; ++p)
        for (std::size_t c = 0; c < 3; ++c) rgba[4 * p + c] = encodeSrgb8(colours[3 * p + c]);
    return rgba;
}

// The ramp at t ∈ [−1, 1] (t = e / max): blue (0.10, 0.25, 0.95) → white → red (0.95, 0.15, 0.10).
inline glm::vec3 differenceRampColour(float t) {
    t = std::clamp(t, -1.0f, 1.0f);
    const glm::vec3 white(1.0f), blue(0.10f, 0.25f, 0.95f), red(0.95f, 0.15f, 0.10f);
    return t < 0.0f ? glm::mix(white, blue, -t) : glm::mix(white, red, t);
}

// Display colours (sRGB-ready values in [0,1], 3 per pixel) of the signed relative error of
// `test` against `truth` (linear RGB, 3 floats per pixel, same size). Pixels where both are black
// (background) stay black. `maxError` is the error shown at either end of the ramp (1 = 100 %).
inline std::vector<float> relativeErrorColours(const std::vector<float>& test, const std::vector<float>& truth,
                                               float maxError) {
    const auto luminance = [](const std::vector<float>& rgb, std::size_t p) {
        return 0.2126f * rgb[3 * p] + 0.7152f * rgb[3 * p + 1] + 0.0722f * rgb[3 * p + 2];
    };
    const std::size_t pixels = std::min(test.size(), truth.size()) / 3;
    double mean = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) mean += luminance(truth, p);
    mean = pixels ? mean / static_cast<double>(pixels) : 0.0;
    const float floor = std::max(1e-6f, 0.01f * static_cast<float>(mean));  // 1 % of the mean
    std::vector<float> out(pixels * 3, 0.0f);
    for (std::size_t p = 0; p < pixels; ++p) {
        const float t = luminance(test, p), r = luminance(truth, p);
        if (t <= 0.0f && r <= 0.0f) continue;
        const glm::vec3 c = differenceRampColour((t - r) / std::max(r, floor) / std::max(maxError, 1e-6f));
        out[3 * p] = c.r;
        out[3 * p + 1] = c.g;
        out[3 * p + 2] = c.b;
    }
    return out;
}

// Figures of an image against its reference (linear RGB, 3 floats per pixel, same size), on
// luminance (Rec. 709 weights) over all pixels: what `lit-render --compare` prints.
struct ImageComparison {
    double testMean = 0.0;       // mean luminance of the image compared
    double referenceMean = 0.0;  // mean luminance of the reference
    // Root mean square of the per-pixel luminance difference, relative to the reference's mean
    // (0.1 = 10 %); 0 when the reference is black.
    double relativeRmse = 0.0;
    double meanRatio() const { return referenceMean > 0.0 ? testMean / referenceMean : 0.0; }
};

inline ImageComparison compareImages(const std::vector<float>& test, const std::vector<float>& truth) {
    const auto luminance = [](const std::vector<float>& rgb, std::size_t p) {
        return 0.2126 * rgb[3 * p] + 0.7152 * rgb[3 * p + 1] + 0.0722 * rgb[3 * p + 2];
    };
    const std::size_t pixels = std::min(test.size(), truth.size()) / 3;
    ImageComparison result;
    if (pixels == 0) return result;
    double squares = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
        const double t = luminance(test, p), r = luminance(truth, p);
        result.testMean += t;
        result.referenceMean += r;
        squares += (t - r) * (t - r);
    }
    const double n = static_cast<double>(pixels);
    result.testMean /= n;
    result.referenceMean /= n;
    result.relativeRmse = result.referenceMean > 0.0 ? std::sqrt(squares / n) / result.referenceMean : 0.0;
    return result;
}

}  // namespace lit::reference
