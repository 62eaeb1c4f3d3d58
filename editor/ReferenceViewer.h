#pragma once
// The editor's Reference and Difference views: the reference path tracer
// (reference::ProgressiveReference) runs on a background thread while the view is on, accumulating
// samples while the camera and the scene stay still and starting over on any edit. Reference shows
// the path-traced image of the current term view (final or one of the four terms), tone-mapped
// like the rasterizer's; Difference shows the rasterizer's image against it as a false-colour
// relative error with a colour bar. Both replace the viewport image; the rasterizer keeps running
// underneath (Difference needs its image).

#include "gl/Objects.h"
#include "reference/ProgressiveReference.h"

#include <imgui.h>

namespace lit {

class Renderer;
struct Scene;
struct CameraView;
struct RenderSettings;

enum class ReferenceMode { Off, Reference, Difference };

class ReferenceViewer {
public:
    // Refreshing the image costs a pass over it on the CPU (and, for Difference, an HDR
    // read-back): a few times a second is enough to watch it converge. Seconds.
    static constexpr double kRefreshSeconds = 0.25;

    // After the rasterizer's frame: feeds the current state to the tracer and refreshes the
    // displayed image (a few times a second). Turns the tracer off when the mode is Off.
    void update(const Scene& scene, const CameraView& camera, const RenderSettings& settings, Renderer& renderer);
    // The image to show instead of the renderer's output, or nullptr (mode Off, no image yet).
    const gl::Texture* output() const;
    // The tracer is still adding samples the shown image lacks: the editor keeps refreshing it
    // (every kRefreshSeconds) although its own frame does not change.
    bool accumulating() const;
    ReferenceMode mode() const { return mode_; }
    // A small window: mode, samples per pixel, samples/s, the colour bar and its range. Placed
    // with its top right corner at `topRight` (the free viewport area's corner, clear of the
    // panels) on first use, or always when `placeCondition` is ImGuiCond_Always (after a resize).
    void drawWindow(ImVec2 topRight, ImGuiCond placeCondition);

private:
    ReferenceMode mode_ = ReferenceMode::Off;
    reference::ProgressiveReference tracer_{4096};
    gl::Texture texture_;      // SRGB8_ALPHA8 holding display bytes, blitted like the renderer's output
    bool haveImage_ = false;
    double lastUpload_ = -1.0;  // seconds (steady clock)
    int uploadedSamples_ = -1;
    float maxError_ = 0.5f;     // relative error at the ends of the Difference ramp
    bool unsupportedView_ = false;
    // The bounces the reference traces (the GI's, reference::kAllBounces for every bounce, 0 with GI off).
    int referenceBounces_ = 0;
};

}  // namespace lit
