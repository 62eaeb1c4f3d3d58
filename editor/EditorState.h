#pragma once
// Editor-only state that the panels edit besides the Scene and the RenderSettings: which
// panels are shown and how the viewport is presented. None of it reaches the renderer.

#include <glm/glm.hpp>
#include <string>
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
    bool legend = true;         // the debug view's legend in the viewport's corner
    bool statsDetails = false;  // the performance overlay's graph and per-pass table (else two lines)
    bool operator==(const PanelVisibility&) const = default;
};

// The names panelFlag knows, in the order of the View menu.
inline constexpr const char* kPanelNames[] = {"hierarchy", "inspector", "settings", "stats",
                                              "stats-details", "camera", "log", "timeline", "legend"};

// The flag of the panel called `name` as scripts and the View menu name it (hierarchy,
// inspector, settings, stats, stats-details, camera, log, timeline, legend), or nullptr for an
// unknown name.
inline bool* panelFlag(PanelVisibility& visible, std::string_view name) {
    if (name == "hierarchy") return &visible.hierarchy;
    if (name == "inspector") return &visible.inspector;
    if (name == "settings") return &visible.renderSettings;
    if (name == "stats") return &visible.stats;
    if (name == "camera") return &visible.camera;
    if (name == "log") return &visible.log;
    if (name == "timeline") return &visible.timeline;
    if (name == "legend") return &visible.legend;
    if (name == "stats-details") return &visible.statsDetails;
    return nullptr;
}

// Where the last frame drew the viewport's own UI, ImGui units (x, y, width, height; zero when
// not drawn), and what the legend said (DebugViewLegend.h legendText): the script's "layout"
// command logs it, so tests check the legend's text and place without reading pixels.
struct ViewportUiReport {
    glm::vec4 area{0.0f};    // the free viewport area between the docked panels
    glm::vec4 legend{0.0f};  // the debug view's legend box
    glm::vec4 stats{0.0f};   // the performance overlay
    std::string legendText;
};

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
    // While the camera moves or a value is dragged, the viewport lowers its render scale to hold
    // this frame rate (frames per second; 0 = never), and renders at full scale when still.
    float interactiveFpsTarget = 10.0f;
    // Render the 3D image only when something it shows changed or work is still in flight, and
    // show the last one again otherwise (ViewportRedraw.h); off renders every frame (for timing
    // the renderer in the editor).
    bool redrawOnDemand = true;
    // The GI work a frame may do (GiBudget): occupied voxels the update after an edit traces per
    // frame (0 = all in the edit's frame), then voxels the refinement traces per frame (0 = none).
    // Spread so that a light edit keeps the editor answering; the light converges to the same
    // image as lit-render's still.
    int giUpdateVoxelsPerFrame = 16384;
    int giRefineVoxelsPerFrame = 8192;
    // GPU time the spread GI work (the update's shares, the refinement) may take per frame, ms;
    // the two counts above are then the most a frame traces, and the GI paces itself by what the
    // work cost in the frames before (gi/GiPacer.h). 0: the counts alone.
    float giMillisecondsPerFrame = 25.0f;
    // ... and while an update after an edit runs and nothing is touched (no input or motion in the
    // frame, the interactive scale's grace over), ms: the edit's light is final sooner (the voxel
    // counts grow with it), and the UI still answers within about this plus its own frame (40 ms:
    // 20 frames a second on llvmpipe at 1280×720, as while refining). Not the refinement's frames.
    // At most giMillisecondsPerFrame's effect when smaller; 0 = the same.
    float giIdleMillisecondsPerFrame = 40.0f;
};

}  // namespace lit::editor
