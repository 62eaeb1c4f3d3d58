#pragma once
// The viewport's render scale while the user interacts (ViewportSettings::interactiveFpsTarget):
// while the camera moves or a value is dragged, the scale drops so the frame time meets the
// target; when still, the viewport renders at its full (chosen) scale.
//
// Why it is a class of its own: a scale that restarts every motion from full size and can at most
// halve per frame begins each motion with frames at ½ and ¼ scale (0.5–0.75 s and 0.2 s at
// 1280×720 on llvmpipe) before it reaches ~0.2; and a scale re-chosen every frame in small steps
// flips between neighbouring steps on noise, each flip reallocating the renderer's targets.
// This controller
//  - remembers the scale of the last motion and starts the next one there;
//  - before any motion, jumps to the scale a still frame's time predicts (cost ∝ pixels ∝ scale²);
//  - ignores the frame time of a frame that was not rendered at the interactive scale (the still
//    frame before a motion says nothing about the interactive scale's cost);
//  - keeps the scale while the mean frame time at that scale is within a dead band around the
//    target, so noise on a loaded machine does not flip it (and reallocate the targets);
//  - holds the scale for a short grace period after the interaction stops, so a mouse-look that
//    pauses for a moment does not render one full-size frame (150 ms and more at 1280×720 on
//    llvmpipe) and stutter;
//  - counts only frames that rendered: with redraw on demand (ViewportRedraw.h) a frame that
//    showed the last image again says nothing about the cost of a render.
// Pure logic, no GL or ImGui: tests/editor/test_interactive_scale.cpp.

#include <algorithm>
#include <cmath>

namespace lit::editor {

class InteractiveScale {
public:
    static constexpr float kMinScale = 0.1f;
    static constexpr float kStep = 0.05f;  // scales are multiples of this: fewer distinct target sizes
    // Dead band: frame times within [target / kBand, target · kBand] keep the scale. 1.3 is about
    // one 0.05 step at scale ~0.2 in frame time ((0.25/0.2)² = 1.56 split both ways).
    static constexpr double kBand = 1.3;

    // Seconds the scale is held after the interaction stops: longer than the gaps between the
    // mouse events of a hand that keeps moving, short enough that the full-size image follows a
    // deliberate stop at once.
    static constexpr double kGraceSeconds = 0.3;

    struct Frame {
        float full = 1.0f;         // the viewport's chosen scale (0.1..1)
        bool interacting = false;  // the camera moved or a value is being dragged this frame
        float targetFps = 0.0f;    // ViewportSettings::interactiveFpsTarget; ≤ 0: off
        double now = 0.0;          // s, a steady clock: times the grace period
        // How long the last frame that rendered took (update, render, present), s; and whether it
        // is the previous frame (a frame that showed the last image again is not counted).
        double lastRenderSeconds = 0.0;
        bool previousRendered = true;
    };

    // The scale for the next frame.
    float next(const Frame& frame) {
        const float full = std::clamp(frame.full, kMinScale, 1.0f);
        const bool lastWasInteractive = lastInteractive_;
        if (frame.targetFps <= 0.0f) {
            lastInteractive_ = false;
            holdUntil_ = -1.0;
            return full;
        }
        if (!frame.interacting) {
            lastInteractive_ = false;
            // The first still frame after a motion starts the grace period; the scale of the
            // motion holds until it ends (a motion that resumes meanwhile starts from it).
            if (lastWasInteractive) holdUntil_ = frame.now + kGraceSeconds;
            if (holding(frame.now)) return std::min(scale_, full);
            holdUntil_ = -1.0;
            return full;
        }
        holdUntil_ = -1.0;
        lastInteractive_ = true;
        const double targetSeconds = 1.0 / frame.targetFps;
        const double lastFrameSeconds = frame.lastRenderSeconds;
        const double ratio = std::sqrt(targetSeconds / std::max(lastFrameSeconds, 1e-3));  // side scale factor
        if (!lastWasInteractive) {
            // The previous frame was still (full scale, or the held scale): start where the last
            // motion ended, or where the last still frame's cost predicts.
            if (remembered_ <= 0.0f) remembered_ = quantize(full * static_cast<float>(std::min(ratio, 1.0)), full);
            scale_ = std::min(remembered_, full);
            framesAtScale_ = 0;
            measuredAtScale_ = 0;
            meanSeconds_ = 0.0;
            return scale_;
        }
        // A frame that did not render (a value held without a change) tells nothing new.
        if (!frame.previousRendered) return std::min(scale_, full);
        // The frame time of one frame scatters by ±50 % on a loaded machine: decide on a running
        // mean of the frames rendered at this scale (the first one after a change still pays for
        // the new targets, so it is not counted), except when one frame is far too slow.
        ++framesAtScale_;
        if (framesAtScale_ >= 2) {
            ++measuredAtScale_;
            meanSeconds_ = measuredAtScale_ == 1 ? lastFrameSeconds : meanSeconds_ + kMeanWeight * (lastFrameSeconds - meanSeconds_);
        }
        const double mean = measuredAtScale_ > 0 ? meanSeconds_ : lastFrameSeconds;
        const bool farTooSlow = lastFrameSeconds > 2.0 * targetSeconds;
        const bool decided = measuredAtScale_ >= kFramesToDecide;
        if (farTooSlow || (decided && (mean > targetSeconds * kBand || mean < targetSeconds / kBand))) {
            const double seconds = farTooSlow ? lastFrameSeconds : mean;
            const double wanted = std::sqrt(targetSeconds / seconds);
            // At most ÷2 or ×1.25 per change so it settles instead of oscillating.
            setScale(quantize(scale_ * static_cast<float>(std::clamp(wanted, 0.5, 1.25)), full));
        }
        if (scale_ > full) setScale(full);
        remembered_ = scale_;
        return scale_;
    }

    float current() const { return scale_; }
    // The interactive scale still holds after the interaction stopped (the grace period).
    bool holding(double now) const { return holdUntil_ >= 0.0 && now < holdUntil_; }
    // Seconds until the grace period ends (0 when none runs): the editor wakes up then to render
    // the full-size image.
    double graceLeft(double now) const { return holding(now) ? holdUntil_ - now : 0.0; }

private:
    static float quantize(float scale, float full) {
        return std::clamp(std::round(scale / kStep) * kStep, kMinScale, full);
    }

    static constexpr int kFramesToDecide = 3;    // frames measured at a scale before it may rise or fall
    static constexpr double kMeanWeight = 0.3;   // of the newest frame in the running mean (~3 frames)

    void setScale(float scale) {
        if (scale != scale_) {
            framesAtScale_ = 0;
            measuredAtScale_ = 0;
            meanSeconds_ = 0.0;
        }
        scale_ = scale;
    }

    float scale_ = 1.0f;
    int framesAtScale_ = 0;      // frames rendered at scale_ since it was set
    int measuredAtScale_ = 0;    // of those, the ones whose time counts (all but the first)
    double meanSeconds_ = 0.0;
    float remembered_ = 0.0f;  // the scale the last motion ended at (0: none yet)
    bool lastInteractive_ = false;
    double holdUntil_ = -1.0;  // s (Frame::now) when the grace period ends; < 0: none
};

}  // namespace lit::editor
