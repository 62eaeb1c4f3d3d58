#include "FlyController.h"

#include <algorithm>
#include <cmath>

namespace lit::editor {

void applyFlyInput(FlyCamera& camera, const FlyInput& input, float dtSeconds, const FlyControlSettings& settings) {
    // Look first, so the motion of this frame follows the direction the user now sees.
    // FlyCamera: positive yaw turns left, positive pitch looks up.
    camera.yaw -= input.lookPixels.x * settings.radiansPerPixel;
    camera.pitch -= input.lookPixels.y * settings.radiansPerPixel;
    camera.pitch = std::clamp(camera.pitch, -settings.maxPitch, settings.maxPitch);
    // Keep yaw in (−π, π] so it does not grow without bound (and lose float precision).
    constexpr float kPi = 3.14159265358979f;
    camera.yaw = std::remainder(camera.yaw, 2.0f * kPi);
    if (camera.yaw <= -kPi) camera.yaw += 2.0f * kPi;

    if (input.wheelSteps != 0.0f)
        camera.speed = std::clamp(camera.speed * std::pow(settings.speedStepFactor, input.wheelSteps),
                                  settings.minSpeed, settings.maxSpeed);

    glm::vec3 direction =
        camera.right() * input.move.x + glm::vec3(0.0f, 1.0f, 0.0f) * input.move.y + camera.forward() * input.move.z;
    const float length = glm::length(direction);
    if (length < 1e-6f || dtSeconds <= 0.0f) return;
    // Diagonal motion is not faster than straight motion.
    if (length > 1.0f) direction /= length;
    const float speed = camera.speed * (input.fast ? settings.fastMultiplier : 1.0f);
    camera.position += direction * speed * dtSeconds;
}

void lookAt(FlyCamera& camera, glm::vec3 target, const FlyControlSettings& settings) {
    const glm::vec3 offset = target - camera.position;
    if (glm::length(offset) < 1e-6f) return;
    const glm::vec3 d = glm::normalize(offset);
    // Inverse of FlyCamera::forward(): (−sin yaw · cos pitch, sin pitch, −cos yaw · cos pitch).
    camera.pitch = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)), -settings.maxPitch, settings.maxPitch);
    camera.yaw = std::atan2(-d.x, -d.z);
}

void orbitAround(FlyCamera& camera, glm::vec3 pivot, glm::vec2 pixels, const FlyControlSettings& settings) {
    const float distance = glm::length(camera.position - pivot);
    if (distance < 1e-6f) return;
    lookAt(camera, pivot, settings);
    // The scene turns with the mouse as if grabbed (Blender, Godot): dragging right takes the
    // camera round to the left, dragging down lifts it to look down on the pivot.
    camera.yaw -= pixels.x * settings.radiansPerPixel;
    camera.pitch = std::clamp(camera.pitch - pixels.y * settings.radiansPerPixel, -settings.maxPitch, settings.maxPitch);
    camera.position = pivot - camera.forward() * distance;
}

float frameBounds(FlyCamera& camera, const Aabb& bounds) {
    if (bounds.empty()) return 0.0f;
    const glm::vec3 centre = bounds.center();
    // A point or a flat object still gets some room around it (10 cm).
    const float radius = std::max(0.5f * glm::length(bounds.size()), 0.05f);
    const float distance = radius / std::sin(0.4f * camera.yfov);  // the sphere spans 80 % of the FOV
    camera.position = centre - camera.forward() * distance;
    return distance;
}

float frameBoundsInArea(FlyCamera& camera, const Aabb& bounds, glm::vec2 window, glm::vec4 area) {
    if (bounds.empty()) return 0.0f;
    if (window.x <= 0.0f || window.y <= 0.0f || area.z <= 1.0f || area.w <= 1.0f) return frameBounds(camera, bounds);
    const float radius = std::max(0.5f * glm::length(bounds.size()), 0.05f);
    // Tangents of the half field of view: the window spans ±tanX, ±tanY at unit depth.
    const float tanY = std::tan(0.5f * camera.yfov);
    const float tanX = tanY * window.x / window.y;
    // The area's centre and half extent at unit depth (screen y grows downwards, view y up).
    const glm::vec2 centre((area.x + 0.5f * area.z) / window.x * 2.0f - 1.0f,
                           1.0f - (area.y + 0.5f * area.w) / window.y * 2.0f);
    const float halfExtent = 0.8f * std::min(area.z / window.x * tanX, area.w / window.y * tanY);
    // A sphere at depth z spans r / √(z² − r²) in tangent units: solve for 80 % of the area.
    const float depth = radius * std::sqrt(1.0f + 1.0f / (halfExtent * halfExtent));
    const glm::vec3 forward = camera.forward(), right = camera.right();
    const glm::vec3 up = glm::cross(right, forward);
    const glm::vec3 toCentre = forward + right * (centre.x * tanX) + up * (centre.y * tanY);
    camera.position = bounds.center() - toCentre * depth;
    return depth;
}

float flySpeedForBounds(const Aabb& bounds) {
    if (bounds.empty()) return 2.0f;
    const float side = glm::length(bounds.size());
    return std::clamp(side / 4.0f, 0.1f, 100.0f);
}

}  // namespace lit::editor
