#pragma once
// Editor-only state that the panels edit besides the Scene and the RenderSettings: which
// panels are shown and how the viewport is presented. None of it reaches the renderer.

#include <string_view>

namespace lit::editor {

struct PanelVisibility {
    bool hierarchy = true;
    bool inspector = true;
    bool stats = true;
    bool renderSettings = true;
    bool camera = true;
    bool log = true;
    bool timeline = true;
};

// The flag of the panel called `name` as scripts and the View menu name it (hierarchy,
// inspector, settings, stats, camera, log, timeline), or nullptr for an unknown name.
inline bool* panelFlag(PanelVisibility& visible, std::string_view name) {
    if (name == "hierarchy") return &visible.hierarchy;
    if (name == "inspector") return &visible.inspector;
    if (name == "settings") return &visible.renderSettings;
    if (name == "stats") return &visible.stats;
    if (name == "camera") return &visible.camera;
    if (name == "log") return &visible.log;
    if (name == "timeline") return &visible.timeline;
    return nullptr;
}

struct ViewportSettings {
    // Render resolution as a fraction of the window's framebuffer; the output is stretched
    // (bilinear) to the window. Below 1 keeps the editor responsive on slow GPUs and llvmpipe,
    // where cone tracing costs scale with the pixel count.
    float renderScale = 1.0f;
    // Light and camera markers, the camera path curve and the translate gizmo.
    bool markers = true;
    // "Cone directions" debug view: a click in the viewport shows the cones the cone-trace pass
    // traces from that pixel (instead of selecting the object there).
    bool coneDirections = false;
};

}  // namespace lit::editor
