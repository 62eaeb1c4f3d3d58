#include "scene/CameraView.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "scene/Scene.h"

namespace lit {

namespace {

constexpr float kMinFov = 1e-3f;     // radians; below this the projection is numerically useless
constexpr float kMaxFov = 3.1f;      // radians; just under π, where tan(fov/2) blows up
constexpr float kMinNear = 1e-4f;    // metres; a smaller near plane wastes nearly all depth precision
constexpr float kDefaultFov = 0.8f;  // radians, the framing camera's vertical field of view

float sanitizeAspect(float aspect) { return (std::isfinite(aspect) && aspect > 0.0f) ? aspect : 1.0f; }
float sanitizeFov(float fov) { return std::isfinite(fov) ? std::clamp(fov, kMinFov, kMaxFov) : kDefaultFov; }

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float len = glm::length(v);
    return (std::isfinite(len) && len > 1e-12f) ? v / len : fallback;
}

// The projection of a view: finite far plane when zfar > znear, otherwise an infinite one.
glm::mat4 perspectiveFor(float yfov, float aspect, float znear, float zfar) {
    if (zfar > znear && std::isfinite(zfar)) return glm::perspective(yfov, aspect, znear, zfar);
    return glm::infinitePerspective(yfov, aspect, znear);
}

}  // namespace

glm::vec3 CameraView::forward() const {
    // The view matrix's third row is the camera's +Z axis in world space; the camera looks down −Z.
    return -glm::vec3(view[0][2], view[1][2], view[2][2]);
}

CameraView makeCameraView(const glm::mat4& cameraWorld, float yfov, float aspect, float znear, float zfar) {
    // Orthonormalise the rotation (drop scale and any shear from the node hierarchy): a view
    // matrix must be rigid or lighting in view space goes wrong.
    const glm::vec3 z = safeNormalize(glm::vec3(cameraWorld[2]), glm::vec3(0.0f, 0.0f, 1.0f));
    glm::vec3 x = glm::vec3(cameraWorld[0]) - z * glm::dot(z, glm::vec3(cameraWorld[0]));
    x = safeNormalize(x, std::abs(z.y) < 0.99f
                             ? safeNormalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), z), {1.0f, 0.0f, 0.0f})
                             : glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::vec3 y = glm::cross(z, x);
    const glm::vec3 position = glm::vec3(cameraWorld[3]);

    glm::mat4 rigid(1.0f);
    rigid[0] = glm::vec4(x, 0.0f);
    rigid[1] = glm::vec4(y, 0.0f);
    rigid[2] = glm::vec4(z, 0.0f);
    rigid[3] = glm::vec4(position, 1.0f);

    CameraView v;
    v.position = position;
    v.yfov = sanitizeFov(yfov);
    v.znear = (std::isfinite(znear) && znear > kMinNear) ? znear : kMinNear;
    v.zfar = zfar;
    // Inverse of a rigid transform: transpose the rotation, rotate the negated translation.
    v.view = glm::mat4(glm::transpose(glm::mat3(rigid)));
    v.view[3] = glm::vec4(-(glm::mat3(v.view) * position), 1.0f);
    v.projection = perspectiveFor(v.yfov, sanitizeAspect(aspect), v.znear, v.zfar);
    return v;
}

CameraView frameBounds(const Aabb& bounds, float aspect, float yfov) {
    aspect = sanitizeAspect(aspect);
    yfov = sanitizeFov(yfov);
    if (bounds.empty()) {
        // Nothing to frame: a human-sized view of the origin.
        const glm::vec3 eye{0.0f, 1.0f, 3.0f};
        return makeCameraView(glm::inverse(glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f))), yfov,
                              aspect, 0.05f, 100.0f);
    }
    const glm::vec3 center = bounds.center();
    // The bounding sphere fits when its angular radius is within the narrower half field of view.
    const float radius = std::max(bounds.radius(), 1e-3f);
    const float halfVertical = 0.5f * yfov;
    const float halfHorizontal = std::atan(std::tan(halfVertical) * aspect);
    const float halfFov = std::min(halfVertical, halfHorizontal);
    const float distance = radius / std::sin(halfFov);
    // From the +Z side, about 17° above the horizon so floors read as floors.
    const glm::vec3 towardsEye = glm::normalize(glm::vec3(0.0f, 0.3f, 1.0f));
    const glm::vec3 eye = center + towardsEye * distance;
    const glm::mat4 world = glm::inverse(glm::lookAt(eye, center, glm::vec3(0.0f, 1.0f, 0.0f)));
    // The sphere spans [distance − radius, distance + radius] along the view axis; keep a margin.
    const float znear = std::max(0.5f * (distance - radius), 1e-3f * radius);
    const float zfar = 1.05f * (distance + radius);
    return makeCameraView(world, yfov, aspect, znear, zfar);
}

CameraView sceneCameraView(const Scene& scene, int cameraIndex, float aspect) {
    const Aabb bounds = scene.worldBounds();
    const bool haveCamera = cameraIndex >= 0 && static_cast<std::size_t>(cameraIndex) < scene.cameras.size();
    const int node = haveCamera ? scene.nodeOfCamera(cameraIndex) : -1;
    if (node < 0) return frameBounds(bounds, aspect, kDefaultFov);

    const Camera& camera = scene.cameras[static_cast<std::size_t>(cameraIndex)];
    const glm::mat4& world = scene.nodes[static_cast<std::size_t>(node)].world;
    // The output's aspect wins over the camera's: rendering with another aspect would stretch
    // the image. The camera's own value is used only when the caller has none.
    if (!(aspect > 0.0f) || !std::isfinite(aspect)) aspect = camera.aspectRatio > 0.0f ? camera.aspectRatio : 1.0f;

    float znear = camera.znear > 0.0f ? camera.znear : 0.05f;
    float zfar = camera.zfar;
    if (!(zfar > znear)) {
        if (bounds.empty()) {
            zfar = std::max(1000.0f, 2.0f * znear);
        } else {
            // Fit to the scene's bounding sphere as seen from the camera.
            const float radius = std::max(bounds.radius(), 1e-3f);
            const float distance = glm::length(bounds.center() - glm::vec3(world[3]));
            // Depth precision is set by near: raise it as far as the scene allows. Inside the
            // sphere geometry can be anywhere, so only a fraction of the radius is safe.
            znear = std::max(znear, 1e-3f * radius);
            if (distance > radius) znear = std::max(znear, 0.5f * (distance - radius));
            zfar = std::max(1.01f * (distance + radius), 2.0f * znear);
        }
    }
    return makeCameraView(world, camera.yfov, aspect, znear, zfar);
}

glm::vec2 depthRangeFor(const glm::vec3& position, const Aabb& bounds) {
    if (bounds.empty() || !std::isfinite(position.x + position.y + position.z)) return {0.05f, 1000.0f};
    float farthest = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner = bounds.corner(i);
        farthest = std::max(farthest, glm::length(corner - position));
    }
    const float zfar = std::max(1.01f * farthest, 0.1f);
    const glm::vec3 outside = glm::max(glm::max(bounds.min - position, position - bounds.max), glm::vec3(0.0f));
    const float distanceToBox = glm::length(outside);
    const float znear = std::max({0.5f * distanceToBox, 1e-4f * zfar, 1e-3f});
    return {znear, std::max(zfar, 2.0f * znear)};
}

glm::vec3 FlyCamera::forward() const {
    // Rotate −Z by pitch about +X, then by yaw about +Y (right-handed: positive yaw turns left).
    const float cp = std::cos(pitch);
    return {-std::sin(yaw) * cp, std::sin(pitch), -std::cos(yaw) * cp};
}

glm::vec3 FlyCamera::right() const { return {std::cos(yaw), 0.0f, -std::sin(yaw)}; }

CameraView FlyCamera::view(float aspect, float znear, float zfar) const {
    // Built from yaw and pitch rotations rather than lookAt, so looking straight up or down
    // (pitch ±π/2) stays well defined.
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), position) *
                            glm::rotate(glm::mat4(1.0f), yaw, glm::vec3(0.0f, 1.0f, 0.0f)) *
                            glm::rotate(glm::mat4(1.0f), pitch, glm::vec3(1.0f, 0.0f, 0.0f));
    return makeCameraView(world, yfov, aspect, znear, zfar);
}

void FlyCamera::setFromView(const CameraView& v) {
    // Roll cannot be represented by yaw/pitch and is dropped.
    position = v.position;
    const glm::vec3 f = safeNormalize(v.forward(), glm::vec3(0.0f, 0.0f, -1.0f));
    pitch = std::asin(std::clamp(f.y, -1.0f, 1.0f));
    const float horizontal = std::sqrt(f.x * f.x + f.z * f.z);
    if (horizontal > 1e-6f) yaw = std::atan2(-f.x, -f.z);
    yfov = v.yfov;
}

glm::mat4 directionalLightView(const glm::vec3& direction, const Aabb& bounds) {
    const glm::vec3 dir = safeNormalize(direction, glm::vec3(0.0f, -1.0f, 0.0f));
    // Any up vector not parallel to the light works; the map's in-plane rotation does not matter.
    const glm::vec3 up = std::abs(dir.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    // Eye at the centre: light-space coordinates stay small, so tiny boxes keep their precision.
    const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    return glm::lookAt(center, center + dir, up);
}

glm::mat4 fitDirectionalShadow(const glm::vec3& direction, const Aabb& bounds) {
    const glm::mat4 lightView = directionalLightView(direction, bounds);
    if (bounds.empty()) return glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -1.0f, 1.0f) * lightView;

    // Tight fit: the light-space box of the eight corners. It is smaller than the bounding
    // sphere's square (by up to 3× in area for a cube), so shadow texels are not wasted.
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(std::numeric_limits<float>::lowest());
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner = bounds.corner(i);
        const glm::vec3 p = glm::vec3(lightView * glm::vec4(corner, 1.0f));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // A small margin so corners land strictly inside despite rounding, and flat boxes (a ground
    // plane seen edge-on) still give a non-degenerate projection.
    const float scale = std::max(bounds.radius(), 1e-3f);
    const glm::vec3 margin = 1e-3f * (hi - lo) + glm::vec3(1e-5f * scale);
    lo -= margin;
    hi += margin;
    // View space looks down −Z: near and far distances are the negated z extremes.
    return glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z, -lo.z) * lightView;
}

}  // namespace lit
