#include <gtest/gtest.h>

#include "FlyController.h"
#include "SceneEdits.h"
#include "ViewportOverlay.h"

namespace {

using namespace lit;
using namespace lit::editor;

// Window pixel (top-left origin) of a world point seen by `camera` in a window of `size`.
glm::vec2 toWindow(const FlyCamera& camera, glm::vec2 size, glm::vec3 point) {
    const CameraView view = camera.view(size.x / size.y, 0.05f, 100.0f);
    const glm::vec4 clip = view.viewProjection() * glm::vec4(point, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y};
}

bool inside(glm::vec2 p, glm::vec4 area) {
    return p.x >= area.x && p.y >= area.y && p.x <= area.x + area.z && p.y <= area.y + area.w;
}

// F with the editor's panels around the viewport (the 1280×720 layout: hierarchy and inspector
// on the left, settings and camera on the right, log and timeline along the bottom): the
// selected box, and its gizmo at the node's origin with its 90 px arms, end up in the free area,
// not in the window's centre behind the timeline.
TEST(FrameInArea, TheSelectionAndItsGizmoLandInTheVisibleViewport) {
    const glm::vec2 window(1280.0f, 720.0f);
    const glm::vec4 area(298.0f, 27.0f, 610.0f, 496.0f);  // x, y, width, height
    Document doc;
    const int box = addNode(doc, NodeKind::Box, {3.0f, 0.5f, -4.0f});
    FlyCamera camera;
    camera.position = {0.0f, 1.5f, 6.0f};
    camera.yaw = 0.4f;
    camera.pitch = -0.2f;
    camera.yfov = 0.8f;
    const float distance = frameBoundsInArea(camera, nodeWorldBounds(doc.scene, box), window, area);
    EXPECT_GT(distance, 0.0f);

    const glm::vec2 gizmo = toWindow(camera, window, nodeWorldPosition(doc.scene, box));
    EXPECT_NEAR(gizmo.x, area.x + 0.5f * area.z, 0.5f);
    EXPECT_NEAR(gizmo.y, area.y + 0.5f * area.w, 0.5f);
    constexpr float kGizmoArm = 90.0f;  // px (TransformGizmo)
    EXPECT_TRUE(inside(gizmo - kGizmoArm, area) && inside(gizmo + kGizmoArm, area));
    const Aabb bounds = nodeWorldBounds(doc.scene, box);
    float top = window.y, bottom = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                          (corner & 4) ? bounds.max.z : bounds.min.z);
        const glm::vec2 pixel = toWindow(camera, window, p);
        EXPECT_TRUE(inside(pixel, area)) << "corner " << corner << " at " << pixel.x << ", " << pixel.y;
        top = std::min(top, pixel.y);
        bottom = std::max(bottom, pixel.y);
    }
    // It fills a good part of the area (the sphere around the box spans 80 % of its height).
    EXPECT_GT(bottom - top, 0.4f * area.w);

    // No area yet (the first frame): the whole window, as frameBounds.
    FlyCamera whole = camera;
    frameBoundsInArea(whole, bounds, window, glm::vec4(0.0f));
    const glm::vec2 centred = toWindow(whole, window, bounds.center());
    EXPECT_NEAR(centred.x, 640.0f, 0.5f);
    EXPECT_NEAR(centred.y, 360.0f, 0.5f);
}

}  // namespace
