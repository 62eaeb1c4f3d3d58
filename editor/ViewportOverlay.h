#pragma once
// What the editor draws over the viewport each frame, gathered from the document and the
// editor's state: markers for lights and cameras, the selection outline and its translate
// gizmo, the camera path as a curve with small frusta at its keys, and the cones of the
// "cone directions" debug view. Window-free (lit_editor_core): the renderer draws the result.

#include <glm/glm.hpp>
#include <optional>

#include "Document.h"
#include "Overlay.h"
#include "TransformGizmo.h"
#include "scene/CameraView.h"

namespace lit::editor {

struct OverlayOptions {
    bool markers = true;      // light and camera markers
    bool gizmo = true;        // the translate gizmo on the selected node
    bool cameraPath = true;   // the path curve and key frusta
    bool selectionOutline = true;  // outline the selected node
    int hoveredGizmoAxis = -1;  // drawn yellow (0 X, 1 Y, 2 Z, TransformGizmo::kUniformHandle)
    GizmoMode gizmoMode = GizmoMode::Translate;
    GizmoSpace gizmoSpace = GizmoSpace::World;
    // Cone directions view: the surface picked for it, and the camera it was seen from.
    std::optional<SurfaceSample> coneSurface;
    glm::vec3 coneCameraPosition{0.0f};
};

// The cone directions view's colours (the legend explains them with the same values): diffuse
// cones green, specular cones pink, and a specular cone that is not marched (a rough surface
// takes its light from the diffuse cones) at this fraction of its opacity.
inline constexpr glm::vec4 kDiffuseConeColor{0.4f, 1.0f, 0.5f, 0.9f};
inline constexpr glm::vec4 kSpecularConeColor{1.0f, 0.5f, 0.9f, 0.9f};
inline constexpr float kUnmarchedConeAlpha = 0.3f;

// Segments of the circles drawn at the samples of footprint-bounded cones (cone directions view,
// accurate mode): ~30 samples per cone within the drawn quarter volume at 128³, so fewer than the
// shapes' 32 keep the overlay at a few thousand lines.
inline constexpr int kConeSampleCircleSegments = 12;

// Samples per path segment for the curve: smooth at editor sizes, cheap to rebuild each frame.
inline constexpr int kPathCurveSamplesPerKey = 24;

ViewportOverlay buildViewportOverlay(const Document& doc, const CameraView& view, glm::vec2 viewport,
                                     const OverlayOptions& options);

// World bounds of node `index` and its subtree's meshes; a node without any: a 20 cm box at its
// origin (lights, cameras, empties still have a place to frame).
Aabb nodeWorldBounds(const Scene& scene, int index);

// The world position of node `index` (its world matrix's translation), for the gizmo.
glm::vec3 nodeWorldPosition(const Scene& scene, int index);

}  // namespace lit::editor
