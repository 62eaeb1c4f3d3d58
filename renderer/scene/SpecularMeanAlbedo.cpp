// The GGX lobe's mean albedo table (scene/SpecularMeanAlbedo.h).

#include "scene/SpecularMeanAlbedo.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "reference/MicrofacetBrdf.h"
#include "scene/RadicalInverse.h"

namespace lit {

namespace {

// (A, B) at n·v = `NdotV`: with h drawn from the visible normals, f_s (n·l) / pdf(l) =
// F · G2(l, v) / G1(v), split into its F0 and F90 parts.
glm::vec2 directionalAlbedo(float NdotV, float roughness) {
    constexpr int kSamples = 1024;
    const float alpha = reference::alphaFromRoughness(roughness);
    const glm::vec3 v(std::sqrt(std::max(1.0f - NdotV * NdotV, 0.0f)), 0.0f, NdotV);
    const float g1 = reference::G1_SmithGGX(NdotV, alpha);
    glm::dvec2 sum(0.0);
    for (int k = 0; k < kSamples; ++k) {
        const glm::vec2 u((static_cast<float>(k) + 0.5f) / kSamples, radicalInverse(static_cast<std::uint32_t>(k)));
        const glm::vec3 h = reference::sampleGgxVisibleNormal(v, alpha, u);
        const float VdotH = glm::dot(v, h);
        const glm::vec3 l = 2.0f * VdotH * h - v;
        if (l.z <= 0.0f) continue;
        const float w = reference::G_SmithGGXCorrelated(l.z, NdotV, alpha) / g1;
        const float fc = std::pow(1.0f - std::clamp(VdotH, 0.0f, 1.0f), 5.0f);
        sum += glm::dvec2(w * (1.0f - fc), w * fc);
    }
    return glm::vec2(sum / static_cast<double>(kSamples));
}

}  // namespace

const std::array<glm::vec2, kSpecularMeanAlbedoSize>& specularMeanAlbedoTable() {
    static const std::array<glm::vec2, kSpecularMeanAlbedoSize> table = [] {
        constexpr int kViews = 64;
        std::array<glm::vec2, kSpecularMeanAlbedoSize> out{};
        for (int j = 0; j < kSpecularMeanAlbedoSize; ++j) {
            const float roughness = static_cast<float>(j) / (kSpecularMeanAlbedoSize - 1);
            glm::vec2 sum(0.0f);
            for (int i = 0; i < kViews; ++i) {
                const float mu = (static_cast<float>(i) + 0.5f) / kViews;
                sum += directionalAlbedo(mu, roughness) * mu;
            }
            out[static_cast<std::size_t>(j)] = 2.0f * sum / static_cast<float>(kViews);
        }
        return out;
    }();
    return table;
}

glm::vec2 specularMeanAlbedo(float roughness) {
    const auto& table = specularMeanAlbedoTable();
    const float s = std::clamp(roughness, 0.0f, 1.0f) * (kSpecularMeanAlbedoSize - 1);
    const int i0 = std::min(static_cast<int>(s), kSpecularMeanAlbedoSize - 2);
    const float f = s - static_cast<float>(i0);
    return glm::mix(table[static_cast<std::size_t>(i0)], table[static_cast<std::size_t>(i0) + 1], f);
}

}  // namespace lit
