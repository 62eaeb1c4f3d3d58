#include "ViewportRedraw.h"

#include <algorithm>
#include <cmath>

#include "passes/TemporalAntialiasPass.h"

namespace lit::editor {

namespace {

// The render settings with `sizeOf`'s render size: what changed besides the size.
RenderSettings withSizeOf(RenderSettings settings, const RenderSettings& sizeOf) {
    settings.output.width = sizeOf.output.width;
    settings.output.height = sizeOf.output.height;
    return settings;
}

bool sameScene(const FrameInputs& a, const FrameInputs& b) {
    return a.geometryRevision == b.geometryRevision && a.materialRevision == b.materialRevision &&
           a.lightRevision == b.lightRevision && a.sceneUploads == b.sceneUploads;
}

// Renders that settle what accumulates over frames, or that change only what is drawn over the
// tone-mapped image: neither starts the settling again.
bool keepsSettling(RedrawReason reason) {
    return reason == RedrawReason::Temporal || reason == RedrawReason::Exposure || reason == RedrawReason::Overlay ||
           reason == RedrawReason::Screenshot;
}

}  // namespace

std::string_view redrawReasonName(RedrawReason reason) {
    switch (reason) {
        case RedrawReason::None:
            return "none";
        case RedrawReason::First:
            return "first frame";
        case RedrawReason::Always:
            return "every frame";
        case RedrawReason::Size:
            return "render size";
        case RedrawReason::Camera:
            return "camera";
        case RedrawReason::Scene:
            return "scene";
        case RedrawReason::Settings:
            return "settings";
        case RedrawReason::Overlay:
            return "overlay";
        case RedrawReason::GiUpdate:
            return "GI update";
        case RedrawReason::GiRefine:
            return "GI refining";
        case RedrawReason::Playback:
            return "playback";
        case RedrawReason::Screenshot:
            return "screenshot";
        case RedrawReason::Shaders:
            return "shaders";
        case RedrawReason::Temporal:
            return "temporal accumulation";
        case RedrawReason::Exposure:
            return "auto exposure";
    }
    return "";
}

bool ViewportRedraw::editedSinceRender(const FrameInputs& inputs) const {
    if (!last_) return true;
    return inputs.camera != last_->camera || !sameScene(inputs, *last_) ||
           withSizeOf(inputs.settings, last_->settings) != last_->settings;
}

RedrawReason ViewportRedraw::decide(const FrameInputs& inputs, const PendingWork& pending, bool onDemand) const {
    if (!last_) return RedrawReason::First;
    if (!onDemand) return RedrawReason::Always;
    if (inputs.settings.output.width != last_->settings.output.width ||
        inputs.settings.output.height != last_->settings.output.height)
        return RedrawReason::Size;
    if (inputs.camera != last_->camera) return RedrawReason::Camera;
    if (!sameScene(inputs, *last_)) return RedrawReason::Scene;
    if (inputs.settings != last_->settings) return RedrawReason::Settings;
    if (inputs.overlay != last_->overlay) return RedrawReason::Overlay;
    if (pending.giUpdating) return RedrawReason::GiUpdate;
    if (pending.giRefining) return RedrawReason::GiRefine;
    if (pending.playing) return RedrawReason::Playback;
    if (pending.screenshot) return RedrawReason::Screenshot;
    if (pending.shadersReloaded) return RedrawReason::Shaders;
    if (temporalFramesLeft_ > 0) return RedrawReason::Temporal;
    if (exposureSecondsLeft_ > 0.0) return RedrawReason::Exposure;
    return RedrawReason::None;
}

double giSecondsLeft(double elapsedSeconds, float done) {
    if (done >= 1.0f) return 0.0;
    if (done < 0.05f || elapsedSeconds < 0.0) return std::numeric_limits<double>::infinity();
    return elapsedSeconds * (1.0 - done) / done;
}

FrameWork ViewportRedraw::work(RedrawReason reason, double now, double renderSeconds, double updateSecondsLeft) const {
    if (reason == RedrawReason::None) return FrameWork::Show;
    if (reason != RedrawReason::GiUpdate && reason != RedrawReason::GiRefine) return FrameWork::Render;
    if (giLightChanged_) return FrameWork::Render;
    const double render = std::max(renderSeconds, 0.0);
    const double renders = reason == RedrawReason::GiRefine ? kRefineImageRenders : kUpdateImageRenders;
    const double since = now - lastRenderAt_;
    if (since < renders * render) return FrameWork::GiOnly;
    const bool endsSoon = reason == RedrawReason::GiUpdate && updateSecondsLeft < render;
    if (endsSoon && since < kUpdateImageHold * renders * render) return FrameWork::GiOnly;
    return FrameWork::Render;
}

void ViewportRedraw::rendered(FrameInputs inputs, RedrawReason reason, double now) {
    giLightChanged_ = false;
    const RenderSettings& settings = inputs.settings;
    const bool temporal = settings.indirect.temporalAccumulation && settings.gi.enabled;
    const bool antialiased = TemporalAntialiasPass::applies(settings);
    // Frames after this one until both histories are full (anti-aliasing's starts again in the
    // frame after the GI's light last changed, which may be this one).
    const int settleFrames = std::max(temporal ? settings.indirect.temporalMaxFrames - 1 : 0,
                                      antialiased ? TemporalAntialiasPass::frames(settings) : 0);
    const bool exposure = settings.output.autoExposure;
    if (!keepsSettling(reason) || !last_) {
        // This frame shows something new: the history holds one frame of it, and the exposure
        // has all of its way to go (counted from the next frame, conservatively).
        temporalFramesLeft_ = settleFrames;
        const double speed = settings.output.autoExposureSpeed;
        exposureSecondsLeft_ = exposure && speed > 0.0 ? -std::log(kExposureRest) / speed : 0.0;
    } else {
        temporalFramesLeft_ = settleFrames > 0 ? std::max(temporalFramesLeft_ - 1, 0) : 0;
        // The renderer adapts by the time since its last metered frame, at most kMaxExposureStep.
        exposureSecondsLeft_ =
            exposure ? std::max(exposureSecondsLeft_ - std::min(now - lastRenderAt_, kMaxExposureStep), 0.0) : 0.0;
    }
    last_ = std::move(inputs);
    lastRenderAt_ = now;
}

}  // namespace lit::editor
