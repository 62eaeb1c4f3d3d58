#pragma once
// KHR_lights_punctual falloff on the CPU, mirroring shaders/include/lights.glsl (sampleLight,
// rangeAttenuation, spotAttenuation) term for term. Units (docs/UNITS.md): intensity is candela
// for point and spot lights and lux for directional lights, used as W/sr and W/m².
// The light table itself comes from passes/LightSetup (buildLightSetup), the same one the GL
// passes upload, so both renderers see the same lights, positions, directions and spot factors.

#include <shared.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lit::reference {

// The spec's recommended range window times inverse square (lights.glsl rangeAttenuation).
inline float rangeAttenuation(float distance, float range) {
    const float invSquare = 1.0f / std::max(distance * distance, 1e-4f);
    if (range <= 0.0f) return invSquare;
    const float ratio = distance / range;
    const float window = std::clamp(1.0f - ratio * ratio * ratio * ratio, 0.0f, 1.0f);
    return window * invSquare;
}

// The spec's spot falloff: saturate(cos·scale + offset)² (lights.glsl spotAttenuation).
inline float spotAttenuation(const gpu::GpuLight& light, const glm::vec3& toLight) {
    const float cd = glm::dot(glm::vec3(light.directionType), -toLight);
    const float a = std::clamp(cd * light.spotShadow.x + light.spotShadow.y, 0.0f, 1.0f);
    return a * a;
}

struct PunctualSample {
    glm::vec3 l{0.0f};         // unit vector from the surface to the light
    glm::vec3 irradiance{0.0f};  // E⊥ = intensity × attenuation × colour (W/m² at normal incidence)
    float distance = 0.0f;     // metres (infinity for directional lights)
};

inline PunctualSample samplePunctualLight(const gpu::GpuLight& light, const glm::vec3& position) {
    PunctualSample s;
    const int type = static_cast<int>(light.directionType.w);
    const glm::vec3 colour = glm::vec3(light.colorIntensity) * light.colorIntensity.a;
    if (type == LIT_LIGHT_DIRECTIONAL) {
        s.l = -glm::vec3(light.directionType);
        s.distance = INFINITY;
        s.irradiance = colour;
        return s;
    }
    const glm::vec3 d = glm::vec3(light.positionRange) - position;
    s.distance = glm::length(d);
    s.l = d / std::max(s.distance, 1e-6f);
    float attenuation = rangeAttenuation(s.distance, light.positionRange.w);
    if (type == LIT_LIGHT_SPOT) attenuation *= spotAttenuation(light, s.l);
    s.irradiance = colour * attenuation;
    return s;
}

}  // namespace lit::reference
