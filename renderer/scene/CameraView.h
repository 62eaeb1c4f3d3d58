#pragma once
// Camera math: the matrices a frame is rendered with, built from a glTF camera + node, from a
// free-flying editor camera, or framed around scene bounds. Conventions: right-handed, +Y up,
// the camera looks down −Z, OpenGL clip space with depth in [0,1] mapped from z_ndc ∈ [−1,1].

#include "scene/Aabb.h"

#include <glm/glm.hpp>

namespace lit {

struct Scene;

struct CameraView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 position{0.0f};
    float yfov = 0.8f;   // radians
    float znear = 0.05f;  // metres
    float zfar = 100.0f;  // metres

    glm::mat4 viewProjection() const { return projection * view; }
    glm::vec3 forward() const;  // world-space viewing direction (−Z of the camera)
    bool operator==(const CameraView&) const = default;
};

// A perspective view from a camera's world matrix (rotation and translation; scale ignored).
CameraView makeCameraView(const glm::mat4& cameraWorld, float yfov, float aspect, float znear, float zfar);

// A view that looks at `bounds` from the +Z side (slightly above) so the whole box fits the
// vertical and horizontal field of view.
CameraView frameBounds(const Aabb& bounds, float aspect, float yfov = 0.8f);

// The camera chosen for a frame: the scene's camera `index`, or a framing camera when index < 0
// or the scene has none. Near/far are fitted to the scene bounds when the camera leaves zfar open.
CameraView sceneCameraView(const Scene& scene, int cameraIndex, float aspect);

// Near and far planes (metres) for a camera at `position` that may look anywhere: far reaches
// the farthest corner of `bounds`; near is half the distance to the box when the camera is
// outside it, and far / 10⁴ (at least 1 mm) inside it, so a camera inside a building never
// clips walls in front of it while depth keeps ~13 bits of range. Empty bounds: (0.05, 1000).
glm::vec2 depthRangeFor(const glm::vec3& position, const Aabb& bounds);

// Fly camera used by the editor: position plus yaw/pitch in radians (yaw 0 looks down −Z).
struct FlyCamera {
    glm::vec3 position{0.0f, 1.0f, 3.0f};
    float yaw = 0.0f;
    float pitch = 0.0f;
    float yfov = 0.8f;
    float speed = 2.0f;  // metres per second

    glm::vec3 forward() const;
    glm::vec3 right() const;
    CameraView view(float aspect, float znear, float zfar) const;
    // Sets position/yaw/pitch to match a view matrix (for starting from a scene camera).
    void setFromView(const CameraView& v);
};

// Orthographic light-space projection for a directional light travelling along `direction`
// that encloses `bounds` tightly: the light-space box of the bounds' eight corners (plus a
// 0.1 % margin) becomes the [-1,1]³ clip cube, so no geometry is clipped in x, y or depth and
// few texels are wasted outside it.
glm::mat4 fitDirectionalShadow(const glm::vec3& direction, const Aabb& bounds);

// The light-space view of those maps (and of the camera's cascades, ShadowCascades.h): looking
// along `direction` from the centre of `bounds` (the origin when empty).
glm::mat4 directionalLightView(const glm::vec3& direction, const Aabb& bounds);

}  // namespace lit
