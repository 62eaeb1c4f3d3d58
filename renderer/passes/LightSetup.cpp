#include "passes/LightSetup.h"

#include "Log.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"
#include "scene/Sky.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace lit {

glm::vec2 spotAngleScaleOffset(float innerConeAngle, float outerConeAngle) {
    const float cosOuter = std::cos(outerConeAngle);
    const float cosInner = std::cos(innerConeAngle);
    const float scale = 1.0f / std::max(0.001f, cosInner - cosOuter);
    return {scale, -cosOuter * scale};
}

void cubeFaceViewProjections(const glm::vec3& p, float nearPlane, float farPlane, glm::mat4 out[6]) {
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, nearPlane, farPlane);
    const glm::vec3 targets[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    for (int f = 0; f < 6; ++f) out[f] = projection * glm::lookAt(p, p + targets[f], ups[f]);
}

namespace {

// Near/far planes that enclose the scene as seen from `position` (metres).
glm::vec2 depthRangeFrom(const glm::vec3& position, const Aabb& bounds, float range) {
    float farthest = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner = bounds.corner(i);
        farthest = std::max(farthest, glm::length(corner - position));
    }
    float farPlane = farthest * 1.01f + 0.01f;
    if (range > 0.0f) farPlane = std::min(farPlane, range);
    // Near plane: small enough for geometry close to the light, large enough to keep depth
    // precision (1/1000 of the far plane keeps 24+ bits of useful depth in a 32F buffer).
    const float nearPlane = std::max(0.01f, farPlane * 0.001f);
    return {nearPlane, std::max(farPlane, nearPlane * 2.0f)};
}

}  // namespace

LightSetup buildLightSetup(const Scene& scene, const Aabb& sceneBounds, const RenderSettings& settings, Log& log) {
    LightSetup setup;
    const Aabb bounds = sceneBounds.empty() ? Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)} : sceneBounds;
    bool warnedCount = false, warnedShadows = false;
    const auto addLight = [&](const Light& light, const glm::vec3& position, const glm::vec3& direction) {
        const int type = light.type == LightType::Directional ? LIT_LIGHT_DIRECTIONAL
                         : light.type == LightType::Spot      ? LIT_LIGHT_SPOT
                                                              : LIT_LIGHT_POINT;
        gpu::GpuLight g{};
        g.positionRange = glm::vec4(position, std::max(light.range, 0.0f));
        g.directionType = glm::vec4(direction, static_cast<float>(type));
        g.colorIntensity = glm::vec4(light.color, light.intensity);
        const glm::vec2 spot = spotAngleScaleOffset(light.innerConeAngle, light.outerConeAngle);
        g.spotShadow = glm::vec4(spot, -1.0f, -1.0f);
        g.shadowParams = glm::vec4(0.0f, 1.0f, settings.shadows.depthBias, settings.shadows.slopeBias);
        g.shadowViewProjection = glm::mat4(1.0f);

        const int lightIndex = static_cast<int>(setup.lights.size());
        if (settings.shadows.enabled && light.castsShadow) {
            ShadowView view;
            view.light = lightIndex;
            view.position = position;
            if (type == LIT_LIGHT_POINT) {
                if (setup.shadowsCube.size() < LIT_MAX_SHADOW_CUBE) {
                    const glm::vec2 nf = depthRangeFrom(position, bounds, light.range);
                    view.cube = true;
                    view.layer = static_cast<int>(setup.shadowsCube.size());
                    view.nearPlane = nf.x;
                    view.farPlane = nf.y;
                    cubeFaceViewProjections(position, nf.x, nf.y, view.viewProjection);
                    g.spotShadow.z = static_cast<float>(view.layer);
                    g.shadowParams.x = nf.x;
                    g.shadowParams.y = nf.y;
                    setup.shadowsCube.push_back(view);
                } else {
                    warnedShadows = true;
                }
            } else if (setup.shadows2d.size() < LIT_MAX_SHADOW_2D) {
                view.layer = static_cast<int>(setup.shadows2d.size());
                if (type == LIT_LIGHT_DIRECTIONAL) {
                    view.viewProjection[0] = fitDirectionalShadow(direction, bounds);
                    if (settings.shadows.cascades > 0 && setup.cascaded.size() < LIT_MAX_CASCADED_LIGHTS) {
                        g.spotShadow.w = static_cast<float>(setup.cascaded.size());
                        setup.cascaded.push_back(lightIndex);
                    }
                } else {
                    const glm::vec2 nf = depthRangeFrom(position, bounds, light.range);
                    view.nearPlane = nf.x;
                    view.farPlane = nf.y;
                    // The frustum covers the outer cone plus a margin for PCF; capped below 180°.
                    const float fov = std::min(2.0f * light.outerConeAngle + glm::radians(4.0f), glm::radians(170.0f));
                    const glm::vec3 up = std::abs(direction.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
                    view.viewProjection[0] = glm::perspective(fov, 1.0f, nf.x, nf.y) *
                                             glm::lookAt(position, position + direction, up);
                    g.shadowParams.x = nf.x;
                    g.shadowParams.y = nf.y;
                }
                g.spotShadow.z = static_cast<float>(view.layer);
                g.shadowViewProjection = view.viewProjection[0];
                setup.shadows2d.push_back(view);
            } else {
                warnedShadows = true;
            }
        }
        setup.lights.push_back(g);
    };
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const Node& node = scene.nodes[n];
        if (node.light < 0) continue;
        if (setup.lights.size() >= LIT_MAX_LIGHTS) {
            if (!warnedCount) log.warning("more than " + std::to_string(LIT_MAX_LIGHTS) + " lights; the rest are ignored");
            warnedCount = true;
            break;
        }
        const Light& light = scene.lights[static_cast<std::size_t>(node.light)];
        addLight(light, glm::vec3(node.world[3]),
                 glm::normalize(glm::vec3(node.world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f))));
    }
    // A scene without lights gets a sun at an angle (scene/Sky.h), as bright as settings say.
    if (hasDefaultSun(scene, settings)) {
        Light sun;
        sun.name = "default sun";
        sun.type = LightType::Directional;
        sun.intensity = settings.sky.sunIrradiance;
        addLight(sun, glm::vec3(0.0f), defaultSunDirection(settings));
    }
    if (warnedShadows) log.warning("too many shadow-casting lights; some lights render without shadows");
    return setup;
}

}  // namespace lit
