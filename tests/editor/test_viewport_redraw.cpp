// ViewportRedraw: the editor renders its 3D frame only when something it shows changed or work
// is still in flight; otherwise the last image is shown again.
#include <gtest/gtest.h>

#include <cmath>

#include "ViewportRedraw.h"

namespace lit::editor {
namespace {

FrameInputs someInputs() {
    FrameInputs inputs;
    inputs.settings.output.width = 640;
    inputs.settings.output.height = 360;
    inputs.camera.position = {0.0f, 1.0f, 3.0f};
    inputs.settings.output.antialiasing = false;  // its settling frames: AntialiasingRendersUntilItsHistoryIsFull
    return inputs;
}

// A redraw that has rendered `inputs` once.
ViewportRedraw renderedOnce(const FrameInputs& inputs, double now = 10.0) {
    ViewportRedraw redraw;
    EXPECT_EQ(redraw.decide(inputs, {}, true), RedrawReason::First);
    redraw.rendered(inputs, RedrawReason::First, now);
    return redraw;
}

TEST(ViewportRedraw, TheSameInputsRenderNothing) {
    const FrameInputs inputs = someInputs();
    const ViewportRedraw redraw = renderedOnce(inputs);
    EXPECT_EQ(redraw.decide(inputs, {}, true), RedrawReason::None);
    EXPECT_FALSE(redraw.editedSinceRender(inputs));
    // Redraw on demand off: every frame.
    EXPECT_EQ(redraw.decide(inputs, {}, false), RedrawReason::Always);
}

TEST(ViewportRedraw, EachInputThatChangedRenders) {
    const FrameInputs inputs = someInputs();
    const ViewportRedraw redraw = renderedOnce(inputs);
    auto changed = [&](auto&& change) {
        FrameInputs next = inputs;
        change(next);
        return redraw.decide(next, {}, true);
    };
    EXPECT_EQ(changed([](FrameInputs& i) { i.settings.output.width = 320; }), RedrawReason::Size);
    EXPECT_EQ(changed([](FrameInputs& i) { i.camera.position.x += 0.01f; }), RedrawReason::Camera);
    EXPECT_EQ(changed([](FrameInputs& i) { ++i.geometryRevision; }), RedrawReason::Scene);
    EXPECT_EQ(changed([](FrameInputs& i) { ++i.materialRevision; }), RedrawReason::Scene);
    EXPECT_EQ(changed([](FrameInputs& i) { ++i.lightRevision; }), RedrawReason::Scene);
    EXPECT_EQ(changed([](FrameInputs& i) { ++i.sceneUploads; }), RedrawReason::Scene);
    EXPECT_EQ(changed([](FrameInputs& i) { i.settings.output.exposureEv += 1.0f; }), RedrawReason::Settings);
    EXPECT_EQ(changed([](FrameInputs& i) { i.settings.debug.view = View::Albedo; }), RedrawReason::Settings);
    EXPECT_EQ(changed([](FrameInputs& i) { i.overlay.activeOutline.push_back(3); }), RedrawReason::Overlay);
    EXPECT_EQ(changed([](FrameInputs& i) {
                  i.overlay.lines.push_back({{0, 0, 0}, {1, 0, 0}, {1, 1, 0, 1}});
              }),
              RedrawReason::Overlay);
}

TEST(ViewportRedraw, EditsButNotTheSizeOrTheOverlayCountAsInteraction) {
    const FrameInputs inputs = someInputs();
    const ViewportRedraw redraw = renderedOnce(inputs);
    FrameInputs next = inputs;
    next.settings.output.width = 100;       // the interactive scale's own doing
    next.overlay.selectedOutline = {1, 2};  // a click in the hierarchy
    EXPECT_FALSE(redraw.editedSinceRender(next));
    ++next.geometryRevision;  // a gizmo or slider drag
    EXPECT_TRUE(redraw.editedSinceRender(next));
    next = inputs;
    next.settings.gi.indirectIntensity = 2.0f;
    EXPECT_TRUE(redraw.editedSinceRender(next));
}

TEST(ViewportRedraw, PendingWorkRendersWithUnchangedInputs) {
    const FrameInputs inputs = someInputs();
    const ViewportRedraw redraw = renderedOnce(inputs);
    EXPECT_EQ(redraw.decide(inputs, {.giUpdating = true}, true), RedrawReason::GiUpdate);
    EXPECT_EQ(redraw.decide(inputs, {.giRefining = true}, true), RedrawReason::GiRefine);
    EXPECT_EQ(redraw.decide(inputs, {.playing = true}, true), RedrawReason::Playback);
    EXPECT_EQ(redraw.decide(inputs, {.screenshot = true}, true), RedrawReason::Screenshot);
    EXPECT_EQ(redraw.decide(inputs, {.shadersReloaded = true}, true), RedrawReason::Shaders);
}

TEST(ViewportRedraw, GiWorkRendersTheImageOnlyNowAndThen) {
    const FrameInputs inputs = someInputs();
    ViewportRedraw redraw = renderedOnce(inputs, 10.0);
    const double render = 0.3;  // s, the last render (llvmpipe at 1280×720)
    EXPECT_EQ(redraw.work(RedrawReason::None, 10.1, render), FrameWork::Show);
    EXPECT_EQ(redraw.work(RedrawReason::Camera, 10.1, render), FrameWork::Render);
    EXPECT_EQ(redraw.work(RedrawReason::Scene, 10.1, render), FrameWork::Render);
    // GI work alone until four renders' time has passed since the last render began (ten while
    // refining).
    EXPECT_EQ(redraw.work(RedrawReason::GiRefine, 10.1, render), FrameWork::GiOnly);
    EXPECT_EQ(redraw.work(RedrawReason::GiUpdate, 11.15, render), FrameWork::GiOnly);
    EXPECT_EQ(redraw.work(RedrawReason::GiUpdate, 11.21, render), FrameWork::Render);
    EXPECT_EQ(redraw.work(RedrawReason::GiRefine, 12.95, render), FrameWork::GiOnly);
    EXPECT_EQ(redraw.work(RedrawReason::GiRefine, 13.01, render), FrameWork::Render);
    // An update that completed in a GI-only frame changed the light shown: the next GI frame renders.
    redraw.advancedGi(false);
    EXPECT_EQ(redraw.work(RedrawReason::GiRefine, 10.2, render), FrameWork::GiOnly);
    redraw.advancedGi(true);
    redraw.advancedGi(false);
    EXPECT_EQ(redraw.work(RedrawReason::GiRefine, 10.2, render), FrameWork::Render);
    redraw.rendered(inputs, RedrawReason::GiRefine, 10.2);
    EXPECT_EQ(redraw.work(RedrawReason::GiRefine, 10.3, render), FrameWork::GiOnly);
    // Where a render costs a few ms (a GPU), every GI frame renders.
    EXPECT_EQ(redraw.work(RedrawReason::GiRefine, 10.251, 0.005), FrameWork::Render);
}

TEST(ViewportRedraw, AnUpdateAboutToCompleteHoldsBackItsProgressImage) {
    const FrameInputs inputs = someInputs();
    const ViewportRedraw redraw = renderedOnce(inputs, 10.0);
    const double render = 0.3;
    // Four renders' time since the last: the progress image is due, unless the update is expected
    // to complete within one render (its whole light then comes that much sooner) ...
    EXPECT_EQ(redraw.work(RedrawReason::GiUpdate, 11.25, render, 0.5), FrameWork::Render);
    EXPECT_EQ(redraw.work(RedrawReason::GiUpdate, 11.25, render, 0.2), FrameWork::GiOnly);
    // ... for at most twice that time, and the refinement's images are not held.
    EXPECT_EQ(redraw.work(RedrawReason::GiUpdate, 12.45, render, 0.2), FrameWork::Render);
    EXPECT_EQ(redraw.work(RedrawReason::GiRefine, 13.05, render, 0.0), FrameWork::Render);
}

TEST(ViewportRedraw, TheUpdatesTimeLeftFollowsItsPaceSoFar) {
    EXPECT_DOUBLE_EQ(giSecondsLeft(1.0, 0.5f), 1.0);
    EXPECT_NEAR(giSecondsLeft(1.5, 0.75f), 0.5, 1e-6);
    EXPECT_EQ(giSecondsLeft(3.0, 1.0f), 0.0);
    EXPECT_TRUE(std::isinf(giSecondsLeft(0.2, 0.01f))) << "too early to tell";
}

TEST(ViewportRedraw, TemporalAccumulationRendersUntilItsHistoryIsFull) {
    FrameInputs inputs = someInputs();
    inputs.settings.indirect.temporalAccumulation = true;
    inputs.settings.indirect.temporalMaxFrames = 4;
    ViewportRedraw redraw = renderedOnce(inputs);
    // The first frame holds one frame of history: three more fill it.
    double now = 10.0;
    for (int frame = 0; frame < 3; ++frame) {
        ASSERT_EQ(redraw.decide(inputs, {}, true), RedrawReason::Temporal) << frame;
        redraw.rendered(inputs, RedrawReason::Temporal, now += 0.1);
    }
    EXPECT_EQ(redraw.decide(inputs, {}, true), RedrawReason::None);
    // A selection change does not start it again; a camera motion does.
    FrameInputs selected = inputs;
    selected.overlay.activeOutline = {2};
    redraw.rendered(selected, redraw.decide(selected, {}, true), now += 0.1);
    EXPECT_EQ(redraw.decide(selected, {}, true), RedrawReason::None);
    FrameInputs moved = selected;
    moved.camera.position.z -= 0.5f;
    redraw.rendered(moved, redraw.decide(moved, {}, true), now += 0.1);
    EXPECT_EQ(redraw.temporalFramesLeft(), 3);
    // With GI off there is nothing to accumulate.
    FrameInputs noGi = moved;
    noGi.settings.gi.enabled = false;
    redraw.rendered(noGi, redraw.decide(noGi, {}, true), now += 0.1);
    EXPECT_EQ(redraw.decide(noGi, {}, true), RedrawReason::None);
}

TEST(ViewportRedraw, AntialiasingRendersUntilItsHistoryIsFull) {
    FrameInputs inputs = someInputs();
    inputs.settings.output.antialiasing = true;
    inputs.settings.output.antialiasingFrames = 6;
    ViewportRedraw redraw = renderedOnce(inputs);
    // Its history starts again in the frame after the GI's light last changed, which may have been
    // the one that rendered: six more frames fill it, with GI off too (edges need it as much).
    double now = 10.0;
    for (int frame = 0; frame < 6; ++frame) {
        ASSERT_EQ(redraw.decide(inputs, {}, true), RedrawReason::Temporal) << frame;
        redraw.rendered(inputs, RedrawReason::Temporal, now += 0.1);
    }
    EXPECT_EQ(redraw.decide(inputs, {}, true), RedrawReason::None);
    FrameInputs noGi = inputs;
    noGi.settings.gi.enabled = false;
    redraw.rendered(noGi, redraw.decide(noGi, {}, true), now += 0.1);
    EXPECT_EQ(redraw.temporalFramesLeft(), 6);
    // With temporal accumulation too, the longer of the two histories.
    FrameInputs both = inputs;
    both.settings.indirect.temporalAccumulation = true;
    both.settings.indirect.temporalMaxFrames = 16;
    redraw.rendered(both, redraw.decide(both, {}, true), now += 0.1);
    EXPECT_EQ(redraw.temporalFramesLeft(), 15);
    // The data views are not anti-aliased.
    FrameInputs albedo = inputs;
    albedo.settings.debug.view = View::Albedo;
    redraw.rendered(albedo, redraw.decide(albedo, {}, true), now += 0.1);
    EXPECT_EQ(redraw.decide(albedo, {}, true), RedrawReason::None);
}

TEST(ViewportRedraw, AutoExposureRendersUntilItHasAdapted) {
    FrameInputs inputs = someInputs();
    inputs.settings.output.autoExposure = true;
    inputs.settings.output.autoExposureSpeed = 3.0f;  // 1/s
    ViewportRedraw redraw = renderedOnce(inputs, 0.0);
    // To 1 % of the step: ln(100) / 3 = 1.54 s of adaptation, at 0.1 s a frame 16 frames.
    const double seconds = std::log(100.0) / 3.0;
    EXPECT_NEAR(redraw.exposureSecondsLeft(), seconds, 1e-9);
    int frames = 0;
    double now = 0.0;
    while (redraw.decide(inputs, {}, true) == RedrawReason::Exposure && frames < 100) {
        redraw.rendered(inputs, RedrawReason::Exposure, now += 0.1);
        ++frames;
    }
    EXPECT_EQ(frames, 16);
    // A pause counts at most ViewportRedraw::kMaxExposureStep, as in the renderer.
    redraw.rendered(inputs, RedrawReason::Settings, now += 0.1);
    redraw.rendered(inputs, RedrawReason::Exposure, now += 30.0);
    EXPECT_NEAR(redraw.exposureSecondsLeft(), seconds - ViewportRedraw::kMaxExposureStep, 1e-9);
    // Speed 0 adapts at once: the frame that changed is enough.
    inputs.settings.output.autoExposureSpeed = 0.0f;
    redraw.rendered(inputs, RedrawReason::Settings, now += 0.1);
    EXPECT_EQ(redraw.decide(inputs, {}, true), RedrawReason::None);
}

}  // namespace
}  // namespace lit::editor
