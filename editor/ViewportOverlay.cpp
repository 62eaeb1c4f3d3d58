#include "ViewportOverlay.h"

#include <algorithm>

#include "TranslateGizmo.h"
#include "scene/OverlayShapes.h"

namespace lit::editor {

namespace {

constexpr glm::vec4 kCameraMarkerColor{0.85f, 0.85f, 0.9f, 0.9f};
constexpr glm::vec4 kPathColor{0.3f, 0.8f, 1.0f, 1.0f};
constexpr glm::vec4 kKeyColor{0.7f, 0.9f, 1.0f, 0.9f};
constexpr glm::vec4 kSelectedKeyColor{1.0f, 0.65f, 0.15f, 1.0f};
constexpr glm::vec4 kDiffuseConeColor{0.4f, 1.0f, 0.5f, 0.9f};
constexpr glm::vec4 kSpecularConeColor{1.0f, 0.5f, 0.9f, 0.9f};

void append(std::vector<OverlayLine>& to, const std::vector<OverlayLine>& lines) {
    to.insert(to.end(), lines.begin(), lines.end());
}

// Marker size for things at `position`: a fixed fraction of the screen, so markers neither
// vanish far away nor fill the view close up.
float screenSize(const CameraView& view, glm::vec2 viewport, glm::vec3 position, float fraction) {
    return worldPerPixel(view, viewport, position) * viewport.y * fraction;
}

void addMarkers(const Document& doc, const CameraView& view, glm::vec2 viewport, ViewportOverlay& overlay) {
    const Scene& scene = doc.scene;
    for (const Node& node : scene.nodes) {
        const glm::vec3 position(node.world[3]);
        if (node.light >= 0 && node.light < static_cast<int>(scene.lights.size()))
            append(overlay.lines, lightMarkerLines(scene.lights[static_cast<std::size_t>(node.light)], node.world,
                                                   screenSize(view, viewport, position, 0.08f)));
        if (node.camera >= 0 && node.camera < static_cast<int>(scene.cameras.size())) {
            const Camera& camera = scene.cameras[static_cast<std::size_t>(node.camera)];
            const float aspect = camera.aspectRatio > 0.0f ? camera.aspectRatio : viewport.x / std::max(viewport.y, 1.0f);
            append(overlay.lines, cameraFrustumLines(node.world, camera.yfov, aspect,
                                                     screenSize(view, viewport, position, 0.08f), kCameraMarkerColor));
        }
    }
}

void addGizmo(const Document& doc, const CameraView& view, glm::vec2 viewport, int hoveredAxis,
              ViewportOverlay& overlay) {
    const glm::vec3 origin = nodeWorldPosition(doc.scene, doc.selectedNode);
    std::vector<OverlayLine> lines = translateGizmoLines(origin, TranslateGizmo::axisLength(view, viewport, origin));
    // The axis under the mouse turns yellow, so the user sees what a drag will move.
    if (hoveredAxis >= 0 && hoveredAxis < 3) {
        const glm::vec4 axisColor = hoveredAxis == 0 ? kGizmoColorX : hoveredAxis == 1 ? kGizmoColorY : kGizmoColorZ;
        for (OverlayLine& line : lines)
            if (line.color == axisColor) line.color = glm::vec4(1.0f, 0.95f, 0.2f, 1.0f);
    }
    append(overlay.linesOnTop, lines);
}

void addCameraPath(const Document& doc, const CameraView& view, glm::vec2 viewport, ViewportOverlay& overlay) {
    const CameraPath& path = doc.cameraPath;
    if (path.empty()) return;
    const std::vector<CameraKey>& keys = path.keys();
    if (keys.size() > 1 && path.duration() > 0.0f) {
        const int samples = kPathCurveSamplesPerKey * static_cast<int>(keys.size());
        std::optional<CameraPose> previous;
        for (int i = 0; i <= samples; ++i) {
            // The last sample is at endTime: a loop wraps it back to the start, so the closing
            // segment is drawn too.
            const double t = path.startTime() + path.duration() * static_cast<double>(i) / samples;
            const std::optional<CameraPose> pose = path.evaluate(t);
            if (pose && previous) overlay.lines.push_back({previous->position, pose->position, kPathColor});
            previous = pose;
        }
    }
    const float aspect = viewport.x / std::max(viewport.y, 1.0f);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const CameraPose pose{keys[i].position, keys[i].rotation, keys[i].yfov};
        const bool selected = static_cast<int>(i) == doc.selectedKey;
        append(overlay.lines, cameraFrustumLines(pose.world(), pose.yfov, aspect,
                                                 screenSize(view, viewport, pose.position, selected ? 0.1f : 0.06f),
                                                 selected ? kSelectedKeyColor : kKeyColor));
    }
}

void addCones(const Document& doc, const OverlayOptions& options, ViewportOverlay& overlay) {
    const SurfaceSample& surface = *options.coneSurface;
    for (const TracedCone& cone : tracedCones(surface, options.coneCameraPosition, doc.settings)) {
        // Drawn at a quarter of the volume's side rather than their full march length (often the
        // whole volume), which would fill the view with lines; without GI there is no volume to
        // size them by, so they are a metre long.
        const float length = surface.volumeSide > 0.0f ? std::min(cone.length, 0.25f * surface.volumeSide) : 1.0f;
        // Specular samples on rough surfaces take their light from the diffuse cones instead of
        // marching (docs/GI.md): drawn faint, so the view shows what is really traced.
        glm::vec4 color = cone.specular ? kSpecularConeColor : kDiffuseConeColor;
        if (!cone.marched) color.a *= 0.3f;
        append(overlay.linesOnTop, coneLines(cone.apex, cone.direction, cone.aperture, length, color));
    }
}

}  // namespace

glm::vec3 nodeWorldPosition(const Scene& scene, int index) {
    if (index < 0 || index >= static_cast<int>(scene.nodes.size())) return glm::vec3(0.0f);
    return glm::vec3(scene.nodes[static_cast<std::size_t>(index)].world[3]);
}

ViewportOverlay buildViewportOverlay(const Document& doc, const CameraView& view, glm::vec2 viewport,
                                     const OverlayOptions& options) {
    ViewportOverlay overlay;
    const bool selected = doc.selectedNode >= 0 && doc.selectedNode < static_cast<int>(doc.scene.nodes.size());
    if (selected && options.selectionOutline) overlay.highlightNode = doc.selectedNode;
    if (options.markers) addMarkers(doc, view, viewport, overlay);
    if (options.cameraPath) addCameraPath(doc, view, viewport, overlay);
    if (options.gizmo && selected) addGizmo(doc, view, viewport, options.hoveredGizmoAxis, overlay);
    if (options.coneSurface) addCones(doc, options, overlay);
    return overlay;
}

}  // namespace lit::editor
