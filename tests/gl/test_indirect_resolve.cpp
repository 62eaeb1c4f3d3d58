// Reduced-resolution indirect lighting and its temporal accumulation (ConeTracePass::
// executeReduced + IndirectResolvePass), through the Renderer on the Cornell box seen from
// inside (every pixel a wall or box, as in the full-frame benchmark).
// Cost: about 28 s in all on llvmpipe (2 cores), 96² to 128² pixels, 64³ voxels.
#include "GlTestSupport.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <functional>

namespace lit::test {
namespace {

class IndirectResolve : public GlFixture {
protected:
    // Frames after which ConeTracePass::samplingFor repeats at scale 2: lcm(jitter 4, rotation 8,
    // cone-subset phases 5).
    static constexpr int kSamplingPeriod = 40;

    // The camera of assets/cornell_inside.still.path.json: inside the box at z = 0.95, 70° fov.
    static CameraView insideCamera(float aspect, glm::vec3 position = {0.0f, 1.0f, 0.95f}, float yaw = 0.0f) {
        const glm::mat4 world = glm::rotate(glm::translate(glm::mat4(1.0f), position), yaw, glm::vec3(0, 1, 0));
        return makeCameraView(world, glm::radians(70.0f), aspect, 0.05f, 20.0f);
    }

    static RenderSettings giSettings(int size, int scale, bool temporal) {
        RenderSettings s = smallSettings(size);
        s.gi.enabled = true;
        s.indirect.scale = scale;
        s.indirect.temporalAccumulation = temporal;
        return s;
    }

    HdrImage renderFrames(const Scene& scene, const CameraView& camera, const RenderSettings& settings, int frames) {
        for (int i = 0; i < frames; ++i) renderer_->render(scene, camera, settings);
        return HdrImage{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    }

    // Cone subsets against the whole sets (temporalConeSubsets off), L_ID of the Cornell box seen
    // from inside, 96², scale 2, temporal accumulation, in `mode`: one frame and a sampling period
    // of each, each on a fresh renderer. `moreSubsetFrames` renders on after the subsets' period,
    // before the renderer is replaced.
    struct SubsetRuns {
        HdrImage subsetFirst, subsetConverged, wholeFirst, wholeConverged;
        // After the sampling period: the subsets' L_ID against the whole sets' (RMSE relative to the
        // mean), and their mean's relative offset.
        double convergedRmse() const { return relativeRmse(subsetConverged, wholeConverged); }
        double convergedBias() const { return meanLuminance(subsetConverged) / meanLuminance(wholeConverged) - 1.0; }
    };
    SubsetRuns renderSubsetsAndWholeSets(const Scene& scene, const CameraView& camera, GiMode mode,
                                         const std::function<void(RenderSettings)>& moreSubsetFrames) {
        RenderSettings subsets = giSettings(96, 2, true);
        subsets.gi.mode = mode;
        subsets.debug.view = View::IndirectDiffuse;
        EXPECT_TRUE(subsets.indirect.temporalConeSubsets) << "the default";
        RenderSettings whole = subsets;
        whole.indirect.temporalConeSubsets = false;
        SubsetRuns runs;
        renderer_->setScene(scene);
        runs.subsetFirst = renderFrames(scene, camera, subsets, 1);
        runs.subsetConverged = renderFrames(scene, camera, subsets, kSamplingPeriod - 1);
        moreSubsetFrames(subsets);
        renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
        renderer_->setScene(scene);
        runs.wholeFirst = renderFrames(scene, camera, whole, 1);
        runs.wholeConverged = renderFrames(scene, camera, whole, kSamplingPeriod - 1);
        return runs;
    }

    static double meanLuminance(const HdrImage& image) {
        double sum = 0.0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) sum += luminance(image.at(x, y));
        return sum / (double(image.width) * image.height);
    }

    // RMSE of the per-channel difference over all pixels, relative to b's mean luminance.
    static double relativeRmse(const HdrImage& a, const HdrImage& b) {
        double sum = 0.0;
        for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += double(a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
        return std::sqrt(sum / double(a.rgb.size())) / meanLuminance(b);
    }

    // Mean absolute per-channel difference, relative to b's mean luminance.
    static double relativeMeanChange(const HdrImage& a, const HdrImage& b) {
        double sum = 0.0;
        for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(double(a.rgb[i]) - b.rgb[i]);
        return sum / double(a.rgb.size()) / meanLuminance(b);
    }
};

// Half and quarter resolution tracing (one frame, no accumulation) against the per-pixel trace:
// the quality target is 2 % RMSE relative to the mean on the final image.
TEST_F(IndirectResolve, ReducedResolutionMatchesFullResolutionOnCornellBox) {
    const Scene scene = loadCornellBox();
    renderer_->setScene(scene);
    const CameraView camera = insideCamera(1.0f);
    const HdrImage full = renderFrames(scene, camera, giSettings(128, 1, false), 1);
    const HdrImage half = renderFrames(scene, camera, giSettings(128, 2, false), 1);
    const HdrImage quarter = renderFrames(scene, camera, giSettings(128, 4, false), 1);
    RenderSettings indirectView = giSettings(128, 1, false);
    indirectView.debug.view = View::IndirectDiffuse;
    const HdrImage fullIndirect = renderFrames(scene, camera, indirectView, 1);
    indirectView.indirect.scale = 2;
    const HdrImage halfIndirect = renderFrames(scene, camera, indirectView, 1);
    const double halfRmse = relativeRmse(half, full), quarterRmse = relativeRmse(quarter, full);
    const double termRmse = relativeRmse(halfIndirect, fullIndirect);
    std::printf("final image RMSE vs full resolution: 1/2 %.3f %%, 1/4 %.3f %%; L_ID alone at 1/2: %.3f %% of its mean\n",
                100 * halfRmse, 100 * quarterRmse, 100 * termRmse);
    EXPECT_LE(halfRmse, 0.02);     // the quality target
    EXPECT_LE(quarterRmse, 0.02);  // same target; the default is 1/2
    // The indirect term on its own is smooth on the Cornell box: the upsampled term must be close,
    // not only the final image where direct light dominates.
    EXPECT_LE(termRmse, 0.05);
}

// A depth edge with very different indirect light on either side: the tall box in front of the
// back wall. Pixels next to the silhouette must get their own surface's light at quarter
// resolution (the most blocks per edge), not a blend of both sides.
TEST_F(IndirectResolve, UpsamplingKeepsDepthEdges) {
    const Scene scene = loadCornellBox();
    renderer_->setScene(scene);
    const CameraView camera = insideCamera(1.0f);
    RenderSettings settings = giSettings(128, 1, false);
    settings.debug.view = View::IndirectDiffuse;
    const HdrImage full = renderFrames(scene, camera, settings, 1);
    const std::vector<float> depth = renderer_->readDepth();
    settings.indirect.scale = 4;
    const HdrImage quarter = renderFrames(scene, camera, settings, 1);

    // Edge pixels: a 4-neighbour whose view distance differs by more than 10 %.
    const glm::mat4 inverse = glm::inverse(camera.projection * camera.view);
    const auto distance = [&](int x, int y) {
        const float d = depth[static_cast<std::size_t>(y) * 128 + x];
        const glm::vec4 w = inverse * glm::vec4((x + 0.5f) / 64.0f - 1.0f, (y + 0.5f) / 64.0f - 1.0f, d * 2.0f - 1.0f, 1.0f);
        return glm::length(glm::vec3(w) / w.w - camera.position);
    };
    double edgeError = 0.0, edgeReference = 0.0, worstEdge = 0.0, innerError = 0.0, innerReference = 0.0;
    int edges = 0;
    for (int y = 1; y < 127; ++y)
        for (int x = 1; x < 127; ++x) {
            const float here = distance(x, y);
            bool edge = false;
            for (const glm::ivec2 o : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)})
                edge |= std::abs(distance(x + o.x, y + o.y) - here) > 0.1f * here;
            if (!edge) {
                innerError += std::abs(double(luminance(quarter.at(x, y))) - luminance(full.at(x, y)));
                innerReference += luminance(full.at(x, y));
                continue;
            }
            const double e = std::abs(double(luminance(quarter.at(x, y))) - luminance(full.at(x, y)));
            edgeError += e;
            edgeReference += luminance(full.at(x, y));
            worstEdge = std::max(worstEdge, e / std::max(double(luminance(full.at(x, y))), 1e-6));
            ++edges;
        }
    ASSERT_GT(edges, 100) << "the view should show the tall box's silhouette against the back wall";
    const double relative = edgeError / edgeReference;
    std::printf("%d edge pixels: mean |quarter − full| %.2f %% of their mean L_ID, worst pixel %.1f %%; other pixels "
                "%.2f %%\n", edges, 100 * relative, 100 * worstEdge, 100 * innerError / innerReference);
    // Measured on this view at 1/4 (llvmpipe): 4.95 % at edge pixels (1.05 % elsewhere: at 1/4
    // the traced pixel may be 3 pixels away, where contact shadows change fast). A plain bilinear
    // upsample (the same shader without the plane and normal weights) measured 18.6 %: it puts
    // the back wall's light on the box's edge pixels and vice versa. 8 % lies between the two.
    EXPECT_LE(relative, 0.08);
}

// Temporal accumulation with a still camera settles: the change from one frame to the next falls
// to a small fraction of the first frames' change (the cone sets turn every frame).
TEST_F(IndirectResolve, StillCameraConverges) {
    const Scene scene = loadCornellBox();
    renderer_->setScene(scene);
    const CameraView camera = insideCamera(1.0f);
    RenderSettings settings = giSettings(96, 2, true);
    settings.debug.view = View::IndirectDiffuse;
    std::vector<HdrImage> frames;
    for (int i = 0; i < 40; ++i) frames.push_back(renderFrames(scene, camera, settings, 1));
    const double early = relativeMeanChange(frames[1], frames[0]);
    const double late = relativeMeanChange(frames[39], frames[38]);
    std::printf("frame-to-frame change of L_ID: frames 0→1 %.3f %%, 38→39 %.3f %%\n", 100 * early, 100 * late);
    EXPECT_GT(early, 0.002) << "the cone sets should turn between frames";
    // With 16 frames of history a frame moves the result by about 1/16 of one frame's deviation.
    EXPECT_LE(late, 0.25 * early);
    EXPECT_LE(late, 0.01);  // the flicker target, 1 % of the mean

    // The converged image is still the per-pixel trace's image within the quality target.
    RenderSettings reference = settings;
    reference.indirect.scale = 1;
    reference.indirect.temporalAccumulation = false;
    settings.debug.view = View::Final;
    reference.debug.view = View::Final;
    HdrImage converged;
    for (int i = 0; i < 16; ++i) converged = renderFrames(scene, camera, settings, 1);
    const HdrImage full = renderFrames(scene, camera, reference, 1);
    const double rmse = relativeRmse(converged, full);
    std::printf("converged final image (1/2, 16+ frames) vs per-pixel trace: RMSE %.3f %%\n", 100 * rmse);
    EXPECT_LE(rmse, 0.02);
}

// Cone subsets (IndirectSettings::temporalConeSubsets, on by default with temporal accumulation):
// every low-resolution texel marches the normal cone and two of the five side cones per frame, and
// the accumulation averages the pairs. One frame must differ from the whole set's (else the subsets
// are not in use); after a whole sampling period the accumulated L_ID must match the whole set's
// accumulated L_ID (both converge to the same estimate), and the final image the per-pixel trace.
TEST_F(IndirectResolve, ConeSubsetsConvergeToTheWholeConeSet) {
    const Scene scene = loadCornellBox();
    const CameraView camera = insideCamera(1.0f);
    // The fast mode's fixed cone set: the accurate mode's subsets (pairs of the stratified sets) are
    // AccurateConeSubsetsConvergeToTheWholeSets, without this test's final-image check, which the
    // accurate mode's reduced-resolution gap would fail with or without subsets (docs/GI.md, "Known
    // limits": the accurate mode at reduced resolution).
    HdrImage subsetFinal;
    RenderSettings reference;  // the per-pixel trace of the same settings, without accumulation
    const SubsetRuns runs = renderSubsetsAndWholeSets(scene, camera, GiMode::Fast, [&](RenderSettings subsets) {
        subsets.debug.view = View::Final;
        subsetFinal = renderFrames(scene, camera, subsets, kSamplingPeriod);
        reference = subsets;
    });
    reference.indirect.temporalConeSubsets = false;
    reference.indirect.scale = 1;
    reference.indirect.temporalAccumulation = false;
    reference.debug.view = View::Final;
    const HdrImage perPixel = renderFrames(scene, camera, reference, 1);

    const double first = relativeMeanChange(runs.subsetFirst, runs.wholeFirst);
    const double converged = runs.convergedRmse();
    const double bias = runs.convergedBias();
    const double final = relativeRmse(subsetFinal, perPixel);
    std::printf("cone subsets vs the whole set, L_ID: first frame mean change %.3f %%, after %d frames RMSE %.3f %%, "
                "mean %+.3f %%; final image vs per-pixel trace RMSE %.3f %%\n",
                100 * first, kSamplingPeriod, 100 * converged, 100 * bias, 100 * final);
    // Measured (96², 64³): one frame 5.9 % apart; after 40 frames L_ID RMSE 2.0 % (the history's
    // residual noise: 16 frames average ~5 pairs' worth of variation), mean −0.03 %, final image
    // 1.4 % from the per-pixel trace. A wrongly weighted subset (the three cones averaged equally
    // instead of W_0·C_0 + (1 − W_0)·½(C_k + C_{k+2})) measured 7.7 %, mean −1.0 %, final 3.6 %:
    // the bars below lie between the two.
    EXPECT_GT(first, 0.01) << "one frame of subsets should differ from the whole set";
    EXPECT_LE(converged, 0.04);
    EXPECT_LE(std::abs(bias), 0.005);
    EXPECT_LE(final, 0.02);  // the quality target
}

// Cone subsets in the accurate mode: each texel traces the normal cone and side cones k, k + 2 of
// its stratified set (cone_strata.glsl), k turning with the frame. The accurate mode's sets do not
// turn, so with a still camera every five frames of a texel trace its whole set, and the
// accumulated L_ID must converge to the accumulated L_ID of the whole sets (temporalConeSubsets
// off), from a first frame that differs from it (else the subsets are not in use). 64³, 96².
TEST_F(IndirectResolve, AccurateConeSubsetsConvergeToTheWholeSets) {
    const Scene scene = loadCornellBox();
    const CameraView camera = insideCamera(1.0f);
    HdrImage subsetNext;
    const SubsetRuns runs = renderSubsetsAndWholeSets(scene, camera, GiMode::Accurate, [&](RenderSettings subsets) {
        subsetNext = renderFrames(scene, camera, subsets, 1);
    });

    const double first = relativeRmse(runs.subsetFirst, runs.wholeFirst);
    const double converged = runs.convergedRmse();
    const double bias = runs.convergedBias();
    const double late = relativeMeanChange(subsetNext, runs.subsetConverged);
    std::printf("accurate mode, cone subsets vs the whole sets, L_ID: first frame RMSE %.3f %%, after %d frames RMSE "
                "%.3f %%, mean %+.3f %%; frame-to-frame change after them %.3f %%\n",
                100 * first, kSamplingPeriod, 100 * converged, 100 * bias, 100 * late);
    // Measured (96², 64³, llvmpipe): one frame 16.4 % apart; after 40 frames L_ID RMSE 1.84 %, mean
    // −0.18 %, then 0.73 % change per frame. Variants that must fail: the phase fixed (k = (x + 2y)
    // mod 5, the pairs never turn) 15.3 %; the three cones averaged equally 8.6 %, mean −1.6 %; the
    // history clamped to the neighbours' box widened by 10 % as in the fast mode
    // (IndirectResolvePass::clampMargin) 8.1 %, 4.2 % change per frame.
    EXPECT_GT(first, 0.01) << "one frame of subsets should differ from the whole sets";
    EXPECT_LE(converged, 0.02);  // the quality target
    EXPECT_LE(std::abs(bias), 0.005);
    EXPECT_LE(late, 0.01);  // the flicker target, 1 % of the mean
}

// World point of pixel (x, y) of a depth image rendered with `camera` (square image of `size`).
glm::vec3 worldAt(const CameraView& camera, const std::vector<float>& depth, int size, int x, int y) {
    const glm::mat4 inverse = glm::inverse(camera.projection * camera.view);
    const float d = depth[static_cast<std::size_t>(y) * size + x];
    const glm::vec4 w = inverse * glm::vec4((x + 0.5f) / size * 2.0f - 1.0f, (y + 0.5f) / size * 2.0f - 1.0f,
                                            d * 2.0f - 1.0f, 1.0f);
    return glm::vec3(w) / w.w;
}

// The camera moves sideways past the tall box: back-wall pixels it uncovers had no history
// (the box was there), so their result must be exactly a fresh frame's, not the box's history.
TEST_F(IndirectResolve, DisocclusionRejectsHistory) {
    const Scene scene = loadCornellBox();
    const int size = 96;
    RenderSettings settings = giSettings(size, 2, true);
    settings.debug.view = View::IndirectDiffuse;
    const CameraView a = insideCamera(1.0f, {-0.25f, 1.0f, 0.95f}), b = insideCamera(1.0f, {0.25f, 1.0f, 0.95f});
    renderer_->setScene(scene);
    // Frames 0..39 at A: frame 40 at B samples as frame 0 does (the sampling repeats every 40 frames:
    // jitter 4, rotation 8, cone subsets 5; ConeTracePass::samplingFor).
    renderFrames(scene, a, settings, kSamplingPeriod);
    const std::vector<float> depthA = renderer_->readDepth();
    const HdrImage withHistory = renderFrames(scene, b, settings, 1);
    const std::vector<float> depthB = renderer_->readDepth();
    renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
    renderer_->setScene(scene);
    const HdrImage fresh = renderFrames(scene, b, settings, 1);

    int disoccluded = 0;
    double worst = 0.0;
    const glm::mat4 toA = a.projection * a.view;
    for (int y = 2; y < size - 2; ++y)
        for (int x = 2; x < size - 2; ++x) {
            const glm::vec3 p = worldAt(b, depthB, size, x, y);
            const glm::vec4 clip = toA * glm::vec4(p, 1.0f);
            const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
            const int ax = int(uv.x * size), ay = int(uv.y * size);
            if (ax < 2 || ay < 2 || ax >= size - 2 || ay >= size - 2) continue;
            // Disoccluded: A saw something else at least 20 cm closer there, in a 5×5 window
            // (so pixels next to the silhouette, where the resolve's nearest lookup may land on
            // either side, do not count).
            bool hidden = true;
            for (int dy = -2; dy <= 2 && hidden; ++dy)
                for (int dx = -2; dx <= 2 && hidden; ++dx)
                    hidden = glm::length(worldAt(a, depthA, size, ax + dx, ay + dy) - p) > 0.2f;
            if (!hidden) continue;
            ++disoccluded;
            const double l = luminance(fresh.at(x, y));
            worst = std::max(worst, std::abs(double(luminance(withHistory.at(x, y))) - l) / std::max(l, 1e-6));
        }
    std::printf("%d disoccluded pixels, worst difference from a fresh frame %.4f %%\n", disoccluded, 100 * worst);
    ASSERT_GT(disoccluded, 20) << "moving past the tall box should uncover some of the back wall";
    EXPECT_LE(worst, 1e-3);  // the same shader on the same inputs: equal up to 16F rounding
}

// The editor's interactive render scale: while the camera moves the frame renders at a smaller
// size, and when it stops the full size comes back. The full size's history (and the camera it was
// written with) is kept across that switch, so the first still frame blends it in instead of
// starting from one frame of cone subsets: it must be much closer to the converged image than a
// first frame without history is.
TEST_F(IndirectResolve, HistoryIsKeptAcrossARenderSizeSwitch) {
    const Scene scene = loadCornellBox();
    const int full = 96, small = 48;
    RenderSettings settings = giSettings(full, 2, true);
    // The fast mode: the test's premise is that one frame is far from converged (one pair of cone
    // subsets, rotated sets: 10.7 %), so history shows. The accurate mode's first frame already
    // averages all 16 stratified sets through the strata filter (4.2 % from the converged image,
    // the rest is the jitter of the traced pixel), and a 5 cm move's nearest-pixel reprojection of
    // the kept history measured 5.5 %: not a test of whether history is kept. An accurate-
    // mode equivalent needs a first frame that is far from converged (per-frame set subsets) or a
    // history-identity check (e.g. a frame count read back from the history's alpha).
    settings.gi.mode = GiMode::Fast;
    settings.debug.view = View::IndirectDiffuse;
    RenderSettings moving = giSettings(small, 2, true);
    moving.gi.mode = GiMode::Fast;
    moving.debug.view = View::IndirectDiffuse;
    const CameraView a = insideCamera(1.0f), b = insideCamera(1.0f, {0.05f, 1.0f, 0.95f});
    renderer_->setScene(scene);
    renderFrames(scene, a, settings, 24);   // still at A, full size
    renderFrames(scene, b, moving, 3);      // the move to B, small size
    const HdrImage back = renderFrames(scene, b, settings, 1);  // stopped at B: full size again
    renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
    renderer_->setScene(scene);
    const HdrImage fresh = renderFrames(scene, b, settings, 1);
    const HdrImage converged = renderFrames(scene, b, settings, 31);
    const double backError = relativeRmse(back, converged), freshError = relativeRmse(fresh, converged);
    std::printf("first full-size frame after a switch, L_ID RMSE from the converged image: %.3f %% (a first frame "
                "without history: %.3f %%)\n", 100 * backError, 100 * freshError);
    // Measured (96², 64³, cone subsets): 3.9 % with the kept history, 10.7 % for a first frame
    // without it. Failing variants: the history dropped at every size change 10.4 %;
    // kept but reprojected with the last frame's camera (the small frame's) instead of its own 8.6 %.
    EXPECT_LE(backError, 0.5 * freshError);
}

// A light edit re-injects the volume: the accumulated indirect light is stale and dropped, so the
// next frame equals a fresh first frame of the edited scene.
TEST_F(IndirectResolve, SceneEditRejectsHistory) {
    Scene scene = loadCornellBox();
    const int size = 96;
    RenderSettings settings = giSettings(size, 2, true);
    settings.debug.view = View::IndirectDiffuse;
    const CameraView camera = insideCamera(1.0f);
    renderer_->setScene(scene);
    const HdrImage before = renderFrames(scene, camera, settings, kSamplingPeriod);  // next frame samples as frame 0
    ASSERT_FALSE(scene.lights.empty());
    scene.lights[0].intensity *= 4.0f;
    ++scene.lightRevision;
    const HdrImage edited = renderFrames(scene, camera, settings, 1);
    renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
    renderer_->setScene(scene);
    const HdrImage fresh = renderFrames(scene, camera, settings, 1);
    const double stale = relativeMeanChange(edited, fresh), change = relativeMeanChange(before, fresh);
    std::printf("after a light edit: difference from a fresh frame %.4f %% (the edit changed L_ID by %.1f %%)\n",
                100 * stale, 100 * change);
    EXPECT_GT(change, 0.3);    // the edit is visible (4× the light)
    EXPECT_LE(stale, 1e-4);    // and no history of the old light is left
}

}  // namespace
}  // namespace lit::test
