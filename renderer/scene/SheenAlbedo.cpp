// The sheen lobe and its albedo table (scene/SheenAlbedo.h).

#include "scene/SheenAlbedo.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lit {

float sheenAlpha(float roughness) {
    const float r = std::clamp(roughness, 0.07f, 1.0f);
    return r * r;
}

float sheenDistribution(float NdotH, float alpha) {
    const float invAlpha = 1.0f / alpha;
    const float sin2 = std::max(1.0f - NdotH * NdotH, 0.0f);
    return (2.0f + invAlpha) * std::pow(sin2, 0.5f * invAlpha) / (2.0f * std::numbers::pi_v<float>);
}

float sheenVisibility(float NdotL, float NdotV) {
    return 1.0f / std::max(4.0f * (NdotL + NdotV - NdotL * NdotV), 1e-6f);
}

namespace {

// ∫ D_s V_s (n·l) dl over the hemisphere for a view at n·v = `NdotV`: midpoint rule in the polar
// angle of l and, by the lobe's mirror symmetry about the view plane, in half the azimuth.
float integrate(float NdotV, float roughness) {
    constexpr int kTheta = 96, kPhi = 48;
    const float alpha = sheenAlpha(roughness);
    const float sinV = std::sqrt(std::max(1.0f - NdotV * NdotV, 0.0f));
    const float dTheta = 0.5f * std::numbers::pi_v<float> / kTheta, dPhi = std::numbers::pi_v<float> / kPhi;
    double sum = 0.0;
    for (int t = 0; t < kTheta; ++t) {
        const float theta = (static_cast<float>(t) + 0.5f) * dTheta;
        const float NdotL = std::cos(theta), sinL = std::sin(theta);
        for (int p = 0; p < kPhi; ++p) {
            const float phi = (static_cast<float>(p) + 0.5f) * dPhi;
            // v = (sinV, 0, NdotV), l = (sinL cos φ, sinL sin φ, NdotL); h = normalize(v + l).
            const float hx = sinV + sinL * std::cos(phi), hy = sinL * std::sin(phi), hz = NdotV + NdotL;
            const float length = std::sqrt(hx * hx + hy * hy + hz * hz);
            if (length <= 0.0f) continue;
            sum += sheenDistribution(hz / length, alpha) * sheenVisibility(NdotL, NdotV) * NdotL * sinL;
        }
    }
    return static_cast<float>(2.0 * sum * dTheta * dPhi);
}

}  // namespace

const std::array<float, kSheenAlbedoSize * kSheenAlbedoSize>& sheenAlbedoTable() {
    static const std::array<float, kSheenAlbedoSize * kSheenAlbedoSize> table = [] {
        std::array<float, kSheenAlbedoSize * kSheenAlbedoSize> out{};
        for (int j = 0; j < kSheenAlbedoSize; ++j)
            for (int i = 0; i < kSheenAlbedoSize; ++i)
                out[static_cast<std::size_t>(j * kSheenAlbedoSize + i)] =
                    integrate((static_cast<float>(i) + 0.5f) / kSheenAlbedoSize,
                              (static_cast<float>(j) + 0.5f) / kSheenAlbedoSize);
        return out;
    }();
    return table;
}

float sheenAlbedo(float NdotV, float roughness) {
    const auto& table = sheenAlbedoTable();
    // Texel centres at (i + ½)/size: GL's linear filter with clamp to edge.
    const auto coordinate = [](float x, int& i0, int& i1, float& f) {
        const float s = std::clamp(x, 0.0f, 1.0f) * kSheenAlbedoSize - 0.5f;
        const float lo = std::floor(s);
        f = s - lo;
        i0 = std::clamp(static_cast<int>(lo), 0, kSheenAlbedoSize - 1);
        i1 = std::clamp(static_cast<int>(lo) + 1, 0, kSheenAlbedoSize - 1);
    };
    int x0, x1, y0, y1;
    float fx, fy;
    coordinate(NdotV, x0, x1, fx);
    coordinate(roughness, y0, y1, fy);
    const auto at = [&](int x, int y) { return table[static_cast<std::size_t>(y * kSheenAlbedoSize + x)]; };
    const float top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * fx;
    const float bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * fx;
    return top + (bottom - top) * fy;
}

float sheenMeanAlbedo(float roughness) {
    constexpr int kSteps = 64;
    float sum = 0.0f;
    for (int i = 0; i < kSteps; ++i) {
        const float mu = (static_cast<float>(i) + 0.5f) / kSteps;
        sum += sheenAlbedo(mu, roughness) * mu;
    }
    return 2.0f * sum / kSteps;
}

}  // namespace lit
