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

void addGizmo(const Document& doc, const CameraView& view, glm::vec2 viewport, const OverlayOptions& options,
              ViewportOverlay& overlay) {
    const glm::vec3 origin = nodeWorldPosition(doc.scene, doc.selectedNode);
    const glm::mat3 axes = gizmoAxes(options.gizmoMode, options.gizmoSpace,
                                     doc.scene.nodes[static_cast<std::size_t>(doc.selectedNode)].world);
    // The handle under the mouse turns yellow, so the user sees what a drag will change.
    append(overlay.linesOnTop, gizmoLines(options.gizmoMode, view, viewport, origin, axes, options.hoveredGizmoAxis));
}

// `node` and its descendants (their pixels carry their own node IDs), appended to `out`.
void appendSubtree(const Scene& scene, int node, std::vector<int>& out) {
    if (node < 0 || node >= static_cast<int>(scene.nodes.size())) return;
    std::vector<int> stack{node};
    for (std::size_t visited = 0; !stack.empty() && visited <= scene.nodes.size(); ++visited) {
        const int n = stack.back();
        stack.pop_back();
        out.push_back(n);
        for (const int child : scene.nodes[static_cast<std::size_t>(n)].children)
            if (child >= 0 && child < static_cast<int>(scene.nodes.size())) stack.push_back(child);
    }
}

bool subtreeHasMesh(const Scene& scene, int node) {
    std::vector<int> nodes;
    appendSubtree(scene, node, nodes);
    return std::any_of(nodes.begin(), nodes.end(), [&](int n) { return scene.nodes[static_cast<std::size_t>(n)].mesh >= 0; });
}

// The selection outlined as Blender does: the active node with its descendants in light orange,
// the other selected nodes with theirs in darker orange.
void addSelectionOutline(const Document& doc, ViewportOverlay& overlay) {
    appendSubtree(doc.scene, doc.selectedNode, overlay.activeOutline);
    if (doc.primitivePicked && doc.selectedNode >= 0)
        overlay.activePrimitive = PickedPrimitive{doc.selectedNode, doc.selectedPrimitive};
    for (const int node : doc.selection())
        if (node != doc.selectedNode) appendSubtree(doc.scene, node, overlay.selectedOutline);
}

// Selected nodes other than the active one that draw nothing (empties, lights and cameras with
// no mesh below them) have no pixels to outline: their bounds as boxes.
void addSelectionBoxes(const Document& doc, ViewportOverlay& overlay) {
    constexpr glm::vec4 kSelectedBoxColor{1.0f, 0.55f, 0.1f, 0.9f};
    for (const int node : doc.selection()) {
        if (node == doc.selectedNode || subtreeHasMesh(doc.scene, node)) continue;
        const Aabb box = nodeWorldBounds(doc.scene, node);
        for (int i = 0; i < 8; ++i)
            for (int bit : {1, 2, 4}) {
                if (i & bit) continue;
                auto corner = [&box](int c) {
                    return glm::vec3(c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y, c & 4 ? box.max.z : box.min.z);
                };
                overlay.linesOnTop.push_back({corner(i), corner(i | bit), kSelectedBoxColor});
            }
    }
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
        if (!cone.marched) color.a *= kUnmarchedConeAlpha;
        if (cone.footprintPerHeight > 0.0f && surface.voxelSize > 0.0f) {
            // A footprint-bounded cone (the accurate mode's stratified set) reads voxels no wider
            // than a third of its height above the surface: near the surface it is a pencil, not
            // the 60° cone its aperture says. Drawn as its axis and, at each sample of its march,
            // a circle as wide as the voxels that sample reads. With anisotropic voxels a sample
            // from level 1 on blends the X, Y and Z directional faces by direction² (cone.glsl,
            // sampleRadiance): those circles show the blend as colour (red X, green Y, blue Z, as
            // the gizmo's axes); finer samples, which mix in the isotropic level 0, keep the cone's.
            overlay.linesOnTop.push_back({cone.apex, cone.apex + cone.direction * length, color});
            const glm::vec3 faces = cone.direction * cone.direction;
            const glm::vec4 faceColor(faces / std::max({faces.x, faces.y, faces.z, 1e-6f}), color.a);
            for (const ConeSample& sample :
                 coneSamples(cone, surface.voxelSize, surface.volumeSide, doc.settings.gi.coneStepScale, length)) {
                const bool blendsFaces =
                    doc.settings.gi.anisotropicVoxels() && sample.diameter >= 2.0f * surface.voxelSize;
                append(overlay.linesOnTop, circleLines(cone.apex + cone.direction * sample.tMid, cone.direction,
                                                       0.5f * sample.diameter, blendsFaces ? faceColor : color,
                                                       kConeSampleCircleSegments));
            }
            continue;
        }
        append(overlay.linesOnTop, coneLines(cone.apex, cone.direction, cone.aperture, length, color));
    }
}

}  // namespace

Aabb nodeWorldBounds(const Scene& scene, int index) {
    Aabb bounds;
    if (index < 0 || index >= static_cast<int>(scene.nodes.size())) return bounds;
    std::vector<int> stack{index};
    for (std::size_t visited = 0; !stack.empty() && visited <= scene.nodes.size(); ++visited) {
        const Node& node = scene.nodes[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        if (node.mesh >= 0 && node.mesh < static_cast<int>(scene.meshes.size()))
            for (const Primitive& p : scene.meshes[static_cast<std::size_t>(node.mesh)].primitives)
                bounds.extend(p.bounds.transformed(node.world));
        for (const int child : node.children) stack.push_back(child);
    }
    if (bounds.empty()) {
        const glm::vec3 origin = nodeWorldPosition(scene, index);
        bounds.extend(origin - glm::vec3(0.1f));
        bounds.extend(origin + glm::vec3(0.1f));
    }
    return bounds;
}

glm::vec3 nodeWorldPosition(const Scene& scene, int index) {
    if (index < 0 || index >= static_cast<int>(scene.nodes.size())) return glm::vec3(0.0f);
    return glm::vec3(scene.nodes[static_cast<std::size_t>(index)].world[3]);
}

ViewportOverlay buildViewportOverlay(const Document& doc, const CameraView& view, glm::vec2 viewport,
                                     const OverlayOptions& options) {
    ViewportOverlay overlay;
    const bool selected = doc.selectedNode >= 0 && doc.selectedNode < static_cast<int>(doc.scene.nodes.size());
    if (options.markers) addMarkers(doc, view, viewport, overlay);
    if (options.cameraPath) addCameraPath(doc, view, viewport, overlay);
    if (options.gizmo && selected) addGizmo(doc, view, viewport, options, overlay);
    if (options.selectionOutline) {
        addSelectionOutline(doc, overlay);
        addSelectionBoxes(doc, overlay);
    }
    if (options.coneSurface) addCones(doc, options, overlay);
    return overlay;
}

}  // namespace lit::editor
