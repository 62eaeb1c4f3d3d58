#pragma once
// What a front end asks the renderer to draw over the viewport (selection outline, gizmo, light
// and camera markers, debug lines) and what it reads back from a pixel (picking). Plain data: the
// editor fills it, Renderer::setOverlay hands it to OverlayPass, Renderer::surfaceAt returns it.

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace lit {

// A world-space line segment with a linear RGBA colour (alpha blends it over the image).
struct OverlayLine {
    glm::vec3 a{0.0f}, b{0.0f};  // end points, world space (m)
    glm::vec4 color{1.0f};       // linear RGB, alpha = opacity
    bool operator==(const OverlayLine&) const = default;
};

// What a click hit: a node and the primitive of its mesh (index into Mesh::primitives).
struct PickedPrimitive {
    int node = -1;
    int primitive = 0;
    bool operator==(const PickedPrimitive&) const = default;
};

struct ViewportOverlay {
    // Nodes whose visible pixels get an outline (2 px, outside them), as Blender outlines a
    // selection: the active node in light orange, the other selected nodes in a darker orange.
    // A node's children draw with their own IDs, so a selected group lists its descendants too
    // (the editor does: editor/ViewportOverlay.cpp). Scene node indices; a node in both lists
    // is drawn as active.
    std::vector<int> activeOutline;
    std::vector<int> selectedOutline;
    // One primitive of a node picked (a part of a one-node scene): of that node only the
    // primitive is outlined, as active. nullopt: the nodes above whole.
    std::optional<PickedPrimitive> activePrimitive;
    // Depth-tested against the scene: the parts behind geometry are drawn faint, not hidden, so
    // markers inside walls stay findable.
    std::vector<OverlayLine> lines;
    // Never hidden (translate gizmo): drawn last, over everything.
    std::vector<OverlayLine> linesOnTop;

    bool empty() const { return activeOutline.empty() && selectedOutline.empty() && lines.empty() && linesOnTop.empty(); }
    // The editor redraws its viewport only when the overlay (among others) differs from the last
    // frame's (editor/ViewportRedraw.h).
    bool operator==(const ViewportOverlay&) const = default;
};

// The surface seen through one pixel of the last frame, read back from the G-buffer.
struct SurfaceSample {
    glm::vec3 position{0.0f};  // world (m), from the depth buffer and the frame's inverse view-projection
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // world, unit (as stored: facing the camera)
    float roughness = 0.0f;    // perceptual (glTF)
    float metalness = 0.0f;
    bool diffuse = true;       // base colour × (1 − metalness) > 0: the shader traces diffuse cones here
    int node = -1;             // scene node drawn there
    // Where it came from, so tracedCones() can repeat the cone-trace shader's per-pixel choices:
    glm::ivec2 glPixel{0};     // pixel in GL (bottom-up) coordinates: the shader's ivec2(gl_FragCoord.xy)
    float voxelSize = 0.0f;    // voxel size (m) of the frame's voxel volume; 0 when GI was off
    float volumeSide = 0.0f;   // side of that voxel volume (m); 0 when GI was off
};

}  // namespace lit
