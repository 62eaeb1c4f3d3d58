#pragma once
// Redraw on demand: whether this frame renders the viewport's 3D image (Renderer::render) or
// shows the last one again under the UI, which is still drawn every frame. A converged frame of
// the Cornell box at 1280×720 costs 150 ms and more on llvmpipe; rendering it again when nothing
// changed made every click wait for it (and a double click never registered).
//
// The frame renders when what it is rendered from differs from the last rendered frame's
// (FrameInputs: camera, render settings with the render size, the scene's revisions and uploads,
// the overlay) or when work is still in flight with the same inputs (PendingWork: the GI update
// and refinement, playback, a viewport screenshot, reloaded shaders). After each such frame a
// few more settle what accumulates over frames: temporal accumulation and anti-aliasing until
// their histories are full (IndirectSettings::temporalMaxFrames, OutputSettings::
// antialiasingFrames frames) and auto exposure until it has adapted (to 1 % of the step, a time
// that follows from OutputSettings::autoExposureSpeed).
//
// A frame that would render only for the GI work in flight (GiUpdate, GiRefine) advances the GI
// alone (Renderer::advanceGi) and shows the last image again, unless the image is due: an update
// completed since the last render (the light shown changed), or the time since the last render
// began reached kUpdateImageRenders (kRefineImageRenders while refining) times that render's
// duration, so rendering takes at most a quarter of the time while an update runs and a tenth
// while the refinement does (its light changes little from one image to the next). A render at
// 1280×720 costs 170-350 ms on llvmpipe while the GI's share of a frame is 25 ms
// (ViewportSettings::giMillisecondsPerFrame): an image in every such frame would make each of
// them cost a render, so the UI answers in the frames between. On a GPU, where a render costs a
// few ms, every frame renders.
// Window-free (lit_editor_core): tests/editor/test_viewport_redraw.cpp.

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

#include "Overlay.h"
#include "RenderSettings.h"
#include "scene/CameraView.h"

namespace lit::editor {

// What a viewport frame is rendered from. Two frames with equal inputs render the same image
// unless work is pending.
struct FrameInputs {
    CameraView camera;
    RenderSettings settings;  // as rendered: the render size, the shadow-map view's light
    // The Scene's revision counters (every edit, undo and redo bumps the ones it needs) and
    // SceneUpload::uploads() (a new document, a structural edit).
    std::uint64_t geometryRevision = 0, materialRevision = 0, lightRevision = 0;
    std::uint64_t sceneUploads = 0;
    ViewportOverlay overlay;  // drawn into the renderer's output image
    bool operator==(const FrameInputs&) const = default;
};

// Work that needs more frames although the inputs stay the same.
struct PendingWork {
    bool giUpdating = false;  // the last frame's FrameStats::giUpdateDone < 1
    bool giRefining = false;  // its FrameStats::giRefining, and this frame's budget lets refinement run
    bool playing = false;     // camera path playback
    bool screenshot = false;  // a viewport screenshot is taken this frame (a clean render)
    bool shadersReloaded = false;
};

// What a frame does with the 3D image.
enum class FrameWork : std::uint8_t {
    Show,    // shows the last image again
    GiOnly,  // advances the GI (Renderer::advanceGi) and shows the last image again
    Render,  // renders the image (Renderer::render, with the GI work)
};

// Why a frame renders; None: the last image is shown again.
enum class RedrawReason : std::uint8_t {
    None,
    First,   // no frame rendered yet
    Always,  // redraw on demand is off (ViewportSettings::redrawOnDemand)
    Size,    // render size (window, panels of a 2D view, render scale)
    Camera,
    Scene,     // an edit, undo or redo, another document
    Settings,  // render settings, the view
    Overlay,   // selection, gizmo, markers, path, cones
    GiUpdate,
    GiRefine,
    Playback,
    Screenshot,
    Shaders,
    Temporal,  // temporal accumulation or anti-aliasing filling its history
    Exposure,  // auto exposure adapting
};

std::string_view redrawReasonName(RedrawReason reason);

// The seconds a GI update is expected to need to complete, from the seconds it has taken and the
// share done (FrameStats::giUpdateDone) at the pace so far; infinity before a twentieth is done
// (too early to tell).
double giSecondsLeft(double elapsedSeconds, float done);

class ViewportRedraw {
public:
    // Auto exposure's longest adaptation step per frame, s (Renderer.cpp, composite: a pause does
    // not count as adaptation time).
    static constexpr double kMaxExposureStep = 0.25;
    // Auto exposure settles when the rest of a step is below this share of it: exp(-speed t).
    static constexpr double kExposureRest = 0.01;

    // Whether the camera, the scene or the render settings of `inputs` differ from the last
    // rendered frame's (the render size and the overlay aside): a value dragged counts as
    // interaction for the interactive render scale only while it changes one of them, so a
    // click that changes nothing, or only the selection, does not lower the scale.
    bool editedSinceRender(const FrameInputs& inputs) const;

    // The time since the last render began, in its durations, after which a frame that works on
    // the GI renders the image again: the image's share of the time is at most 1 / this.
    static constexpr double kUpdateImageRenders = 4.0;
    static constexpr double kRefineImageRenders = 10.0;
    // An update expected to complete within one render (giSecondsLeft) holds back its progress
    // image, so that the image of its whole light comes a render sooner; for at most this many
    // times kUpdateImageRenders renders since the last one (the estimate may be wrong).
    static constexpr double kUpdateImageHold = 2.0;

    // This frame's decision; `onDemand` false renders every frame.
    RedrawReason decide(const FrameInputs& inputs, const PendingWork& pending, bool onDemand) const;
    // What the frame does for `reason` at `now` (s), the last render having taken `renderSeconds`,
    // with the GI update under way expected to need `updateSecondsLeft` more (giSecondsLeft).
    FrameWork work(RedrawReason reason, double now, double renderSeconds,
                   double updateSecondsLeft = std::numeric_limits<double>::infinity()) const;
    // The frame advanced the GI alone; `updateCompleted`: an update completed in it
    // (FrameStats::giUpdateCompleted), so the next frame that works on the GI renders.
    void advancedGi(bool updateCompleted) { giLightChanged_ = giLightChanged_ || updateCompleted; }
    // The frame rendered from `inputs` for `reason` (not None) at `now` (s on a steady clock:
    // auto exposure's adaptation time).
    void rendered(FrameInputs inputs, RedrawReason reason, double now);

    // Rendered frames still to come for temporal accumulation and anti-aliasing, and auto
    // exposure's adaptation time left.
    int temporalFramesLeft() const { return temporalFramesLeft_; }
    double exposureSecondsLeft() const { return exposureSecondsLeft_; }

private:
    std::optional<FrameInputs> last_;  // the last rendered frame's
    double lastRenderAt_ = 0.0;        // s, when it rendered
    bool giLightChanged_ = false;      // an update completed in a GI-only frame since then
    int temporalFramesLeft_ = 0;
    double exposureSecondsLeft_ = 0.0;  // adaptation time, s
};

}  // namespace lit::editor
