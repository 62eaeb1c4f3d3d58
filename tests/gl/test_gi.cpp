// Global illumination on the Cornell box (voxel cone tracing, 64³, 128×128): physical
// invariants and effects that must appear with GI on and vanish with it off.
#include "GlTestSupport.h"
#include "gi/VoxelVolume.h"
#include "image/ImageIO.h"

namespace lit::test {
namespace {

class CornellGi : public GlFixture {
protected:
    RenderSettings giSettings(bool gi, View view = View::Final) const {
        RenderSettings s = smallSettings(128);
        s.gi.enabled = gi;
        s.gi.voxelResolution = 64;
        s.debug.view = view;
        // One bounce: these tests are about the cone tracer and its terms; a second bounce traces
        // six cones per occupied voxel (seconds per voxelization on llvmpipe, and these tests
        // re-voxelize for every image). Bounces: test_gi_accuracy.cpp.
        s.gi.bounces = 1;
        return s;
    }
    // Renders one view; the voxel volume is built on the first frame of each render() call.
    HdrImage renderView(const Scene& scene, bool gi, View view) { return render(scene, giSettings(gi, view)); }
    // Gives the node named `node` a metal of `roughness` (white, 0.95); false if there is no such node.
    static bool makeMetal(Scene& scene, const std::string& node, float roughness) {
        Material metal;
        metal.name = "metal";
        metal.baseColorFactor = glm::vec4(0.95f, 0.95f, 0.95f, 1.0f);
        metal.metallic = 1.0f;
        metal.roughness = roughness;
        scene.materials.push_back(metal);
        bool found = false;
        for (Node& n : scene.nodes)
            if (n.name == node && n.mesh >= 0) {
                for (Primitive& p : scene.meshes[std::size_t(n.mesh)].primitives)
                    p.material = int(scene.materials.size() - 1);
                found = true;
            }
        ++scene.materialRevision;
        return found;
    }
};

TEST_F(CornellGi, FourTermsSumToTheFinalImage) {
    const Scene scene = loadCornellBox();
    const HdrImage final = renderView(scene, true, View::Final);
    const HdrImage dd = renderView(scene, true, View::DirectDiffuse);
    const HdrImage id = renderView(scene, true, View::IndirectDiffuse);
    const HdrImage ds = renderView(scene, true, View::DirectSpecular);
    const HdrImage is = renderView(scene, true, View::IndirectSpecular);
    double worst = 0.0, total = 0.0, indirectTotal = 0.0;
    for (std::size_t i = 0; i < final.rgb.size(); ++i) {
        const double sum = double(dd.rgb[i]) + id.rgb[i] + ds.rgb[i] + is.rgb[i];
        worst = std::max(worst, std::abs(sum - final.rgb[i]) / std::max(1e-3, double(final.rgb[i])));
        total += final.rgb[i];
        indirectTotal += id.rgb[i] + is.rgb[i];
    }
    EXPECT_LT(worst, 1e-3) << "largest relative difference between Σ terms and final";
    EXPECT_GT(indirectTotal, 0.05 * total) << "the indirect terms must contribute (else the sum test is vacuous)";
}

TEST_F(CornellGi, CeilingIsLitOnlyWithGi) {
    const Scene scene = loadCornellBox();
    // Both GI modes, whichever is the default (docs/GI.md, "Modes"): the fast one (isotropic
    // voxels, wide unbounded cones) and the accurate one (anisotropic voxels, footprint-bounded
    // cones).
    RenderSettings settings = giSettings(true);
    settings.gi.mode = GiMode::Fast;
    RenderSettings accurateSettings = settings;
    accurateSettings.gi.mode = GiMode::Accurate;
    const HdrImage on = render(scene, settings), off = renderView(scene, false, View::Final);
    const HdrImage accurate = render(scene, accurateSettings);
    float withGi = 1e9f, withAccurateGi = 1e9f, withoutGi = 0.0f;
    for (const glm::vec3& p : {glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(-0.5f, 2.0f, 0.5f), glm::vec3(0.5f, 2.0f, -0.5f)}) {
        withGi = std::min(withGi, luminance(radianceAt(scene, settings, on, p)));
        withAccurateGi = std::min(withAccurateGi, luminance(radianceAt(scene, settings, accurate, p)));
        withoutGi = std::max(withoutGi, luminance(radianceAt(scene, settings, off, p)));
    }
    std::printf("ceiling radiance with GI (darkest of 3 points): %.4f, accurate GI %.4f\n", withGi, withAccurateGi);
    EXPECT_LT(withoutGi, 1e-3f) << "the downward spot does not reach the ceiling";
    // Fast mode. The ceiling sees the spot-lit floor (radiance ≈ 0.8-1.3) over a large solid
    // angle: a physical estimate is 0.1-0.2. With the mip chain stacking opacity (thin walls stay
    // opaque) 64³ gives 0.044; with plain-average mips the cones see through the walls and it is
    // 0.008. The remaining gap is the side cones' self-occlusion by the ceiling's own coarse
    // voxels, which the accurate mode fixes.
    EXPECT_GT(withGi, 0.03f) << "bounced light must reach the ceiling";
    EXPECT_LT(withGi, 0.3f) << "more than the lit floor can send";
    // Accurate mode, re-derived from the reference path tracer (docs/GI.md, "Accuracy against the
    // reference"): the ceiling's mean one-bounce radiance is 0.42 W/(sr·m²) (0.47 with two
    // bounces). The fast mode gives 0.044 (above); the accurate one 0.3-0.4. Bars: at least half of
    // the one-bounce mean at the darkest of the three points, at most 1.2 × the two-bounce mean.
    EXPECT_GT(withAccurateGi, 0.5f * 0.42f) << "accurate GI: bounced light must reach the ceiling";
    EXPECT_LT(withAccurateGi, 1.2f * 0.47f) << "accurate GI: more than the lit floor can send";
}

// Colour bleeding at points next to the red (x = −1) and green (x = +1) walls, with bars from the
// path-traced reference of the same view (ReferenceScene + PathTracer, 128 spp, Final view):
//                                    one bounce      two bounces
//   ceiling, R/G by red, G/R by green  0.997, 0.994    1.124, 1.063
//   back wall low down (GI off 1.000)  1.170, 1.133    1.231, 1.187
// With one bounce the ceiling does not bleed: it sees the coloured walls, but those are lit only
// where the downward spot reaches them, far below. Its colour comes with the second bounce (light
// → floor → wall → ceiling). Measured (64³, 128²), one bounce / two bounces:
//   fast:     ceiling 1.127, 1.187 / 1.547, 1.299   back wall 1.179, 1.177 / 1.349, 1.298
//   accurate: ceiling 1.015, 1.012 / 1.188, 1.119   back wall 1.270, 1.151 / 1.369, 1.258
// Every mode must bleed where the reference does (at least half its excess over 1). The accurate
// mode must also match the reference's ratios within ±20 % (the GI accuracy bar) and not bleed where
// the reference does not: the one-bounce ceiling within ±5 % of grey, since the smallest real
// bleed in this view is 6.3 %. The fast mode bleeds on the one-bounce ceiling by 13-19 %, and its
// two-bounce ceiling is 1.38× and 1.22× the reference's ratios: known errors of that mode
// (docs/GI.md, "Known limits"), not asserted. (Asking every mode for > 1.05 on the one-bounce
// ceiling would ask for the fast mode's error, not light.)
TEST_F(CornellGi, WhiteSurfacesNearColouredWallsBleedTheirColour) {
    const Scene scene = loadCornellBox();
    const auto ratio = [](const glm::vec3& c, int a, int b) { return c[a] / std::max(c[b], 1e-4f); };
    struct Ratios {
        float ceilingRed, ceilingGreen, backRed, backGreen;
    };
    const auto measure = [&](GiMode mode, int bounces) {
        RenderSettings settings = giSettings(true);
        settings.gi.mode = mode;
        settings.gi.bounces = bounces;
        const HdrImage image = render(scene, settings);
        const Ratios r{ratio(radianceAt(scene, settings, image, {-0.85f, 2.0f, 0.0f}), 0, 1),
                       ratio(radianceAt(scene, settings, image, {0.85f, 2.0f, 0.0f}), 1, 0),
                       ratio(radianceAt(scene, settings, image, {-0.9f, 0.9f, -1.0f}), 0, 1),
                       ratio(radianceAt(scene, settings, image, {0.9f, 0.9f, -1.0f}), 1, 0)};
        std::printf("%s, %d bounce(s): ceiling R/G %.3f, G/R %.3f; back wall R/G %.3f, G/R %.3f\n",
                    std::string(toString(mode)).c_str(), bounces, r.ceilingRed, r.ceilingGreen, r.backRed, r.backGreen);
        return r;
    };
    const Ratios oneBounceReference{0.997f, 0.994f, 1.170f, 1.133f};
    const Ratios twoBounceReference{1.124f, 1.063f, 1.231f, 1.187f};
    const auto bleedsAtLeastHalf = [](float vct, float reference) { return vct - 1.0f > 0.5f * (reference - 1.0f); };

    // GI off: the back-wall points are lit by the white spot alone.
    const RenderSettings offSettings = giSettings(false);
    const HdrImage off = render(scene, offSettings);
    EXPECT_NEAR(ratio(radianceAt(scene, offSettings, off, {-0.9f, 0.9f, -1.0f}), 0, 1), 1.0f, 0.01f);
    EXPECT_NEAR(ratio(radianceAt(scene, offSettings, off, {0.9f, 0.9f, -1.0f}), 1, 0), 1.0f, 0.01f);

    for (const GiMode mode : {GiMode::Fast, GiMode::Accurate}) {
        const std::string name(toString(mode));
        const Ratios one = measure(mode, 1), two = measure(mode, 2);
        EXPECT_TRUE(bleedsAtLeastHalf(one.backRed, oneBounceReference.backRed)) << name << ": back wall by the red wall";
        EXPECT_TRUE(bleedsAtLeastHalf(one.backGreen, oneBounceReference.backGreen)) << name << ": back wall by the green wall";
        EXPECT_TRUE(bleedsAtLeastHalf(two.ceilingRed, twoBounceReference.ceilingRed)) << name << ": ceiling by the red wall";
        EXPECT_TRUE(bleedsAtLeastHalf(two.ceilingGreen, twoBounceReference.ceilingGreen)) << name << ": ceiling by the green wall";
        if (mode != GiMode::Accurate) continue;
        EXPECT_NEAR(one.ceilingRed, 1.0f, 0.05f) << "no bleeding on the one-bounce ceiling";
        EXPECT_NEAR(one.ceilingGreen, 1.0f, 0.05f) << "no bleeding on the one-bounce ceiling";
        EXPECT_NEAR(one.backRed / oneBounceReference.backRed, 1.0f, 0.2f);
        EXPECT_NEAR(one.backGreen / oneBounceReference.backGreen, 1.0f, 0.2f);
        EXPECT_NEAR(two.ceilingRed / twoBounceReference.ceilingRed, 1.0f, 0.2f);
        EXPECT_NEAR(two.ceilingGreen / twoBounceReference.ceilingGreen, 1.0f, 0.2f);
        EXPECT_NEAR(two.backRed / twoBounceReference.backRed, 1.0f, 0.2f);
        EXPECT_NEAR(two.backGreen / twoBounceReference.backGreen, 1.0f, 0.2f);
    }
}

TEST_F(CornellGi, MirrorFloorReflectsTheRedWall) {
    Scene scene = loadCornellBox();
    ASSERT_TRUE(makeMetal(scene, "floor", 0.05f));
    const RenderSettings settings = giSettings(true);
    const HdrImage is = renderView(scene, true, View::IndirectSpecular);
    writePng(outputDir() / "mirror_floor_indirect_specular.png", settings.output.width, settings.output.height,
             renderer_->readOutputRgba8());
    // Front floor next to the red wall mirrors the red wall's directly lit lower part (the camera's
    // mirror image (0, −1, 3.4) sees the wall at about (−1, 0.09, 0.25)); likewise on the green side.
    const glm::vec3 left = radianceAt(scene, settings, is, {-0.92f, 0.0f, 0.5f}, 1);
    const glm::vec3 right = radianceAt(scene, settings, is, {0.92f, 0.0f, 0.5f}, 1);
    EXPECT_GT(left.r, 0.02f);
    EXPECT_GT(left.r, 3.0f * left.g) << "floor next to the red wall: " << left.r << "," << left.g << "," << left.b;
    EXPECT_GT(right.g, 1.5f * right.r) << "floor next to the green wall: " << right.r << "," << right.g;
    // With GI off there is no indirect specular at all.
    const HdrImage off = renderView(scene, false, View::IndirectSpecular);
    EXPECT_EQ(luminance(radianceAt(scene, settings, off, {-0.92f, 0.0f, 0.5f}, 1)), 0.0f);
}

// A rough metal wall's indirect specular is smooth with the default single cone per pixel around
// the mirror direction; two GGX samples per pixel, shifted per pixel, scatter from pixel to pixel
// (the speckle of a rough metal). How far each is from the reference here: docs/GI.md, "Known
// limits" (grazing metal).
TEST_F(CornellGi, OneSpecularConeLeavesNoSpeckleOnARoughMetal) {
    Scene scene = loadCornellBox();
    // Roughness 0.4: traced at reduced resolution, narrower than the diffuse cones.
    ASSERT_TRUE(makeMetal(scene, "left_wall_red", 0.4f));
    RenderSettings settings = giSettings(true, View::IndirectSpecular);
    ASSERT_EQ(settings.indirect.specularSamples, 1) << "the default";
    settings.output.width = settings.output.height = 256;  // the reflections' structure spans more pixels than the noise
    const HdrImage one = render(scene, settings);
    writePng(outputDir() / "rough_metal_wall_one_cone.png", one.width, one.height, renderer_->readOutputRgba8());
    settings.indirect.specularSamples = 2;
    const HdrImage two = render(scene, settings);
    writePng(outputDir() / "rough_metal_wall_two_samples.png", two.width, two.height, renderer_->readOutputRgba8());
    // Pixels of the wall only: the box between the points (−1, 0.5, 0) and (−1, 1.5, −0.6).
    const CameraView camera = cameraFor(scene, settings);
    const glm::ivec2 a = projectToPixel(camera, {-1.0f, 0.5f, 0.0f}, one.width, one.height);
    const glm::ivec2 b = projectToPixel(camera, {-1.0f, 1.5f, -0.6f}, one.width, one.height);
    const glm::ivec2 lo = glm::max(glm::min(a, b), 1), hi = glm::min(glm::max(a, b), glm::ivec2(one.width, one.height) - 2);
    ASSERT_GT((hi.x - lo.x) * (hi.y - lo.y), 200) << "the wall window covers too few pixels";
    // Speckle: Σ |pixel − mean of its four neighbours| / Σ pixel, on luminance.
    const auto speckle = [&](const HdrImage& image) {
        double difference = 0.0, total = 0.0;
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                const double c = luminance(image.at(x, y));
                const double around = 0.25 * (luminance(image.at(x - 1, y)) + luminance(image.at(x + 1, y)) +
                                              luminance(image.at(x, y - 1)) + luminance(image.at(x, y + 1)));
                difference += std::abs(c - around);
                total += c;
            }
        return total > 0.0 ? difference / total : 1.0;
    };
    const double speckleOne = speckle(one), speckleTwo = speckle(two);
    EXPECT_GT(luminance(windowMean(one, (lo.x + hi.x) / 2, (lo.y + hi.y) / 2, 4)), 0.0f) << "the wall reflects light";
    EXPECT_LT(speckleOne, 0.25 * speckleTwo) << "speckle: one cone " << speckleOne << ", two samples " << speckleTwo;
}

TEST_F(CornellGi, LightEditReinjectsWithoutRevoxelizing) {
    Scene scene = loadCornellBox();
    const RenderSettings settings = giSettings(true);
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);
    EXPECT_TRUE(renderer_->stats().voxelized);
    renderer_->render(scene, camera, settings);
    EXPECT_FALSE(renderer_->stats().voxelized) << "nothing changed: no GI work";
    EXPECT_FALSE(renderer_->stats().injected);
    scene.lights[0].color = glm::vec3(1.0f, 0.2f, 0.2f);
    ++scene.lightRevision;
    renderer_->render(scene, camera, settings);
    EXPECT_FALSE(renderer_->stats().voxelized) << "a light edit must not re-voxelize";
    EXPECT_TRUE(renderer_->stats().injected);
    scene.nodes[std::size_t(scene.nodes.size() > 5 ? 5 : 0)].translation.x += 0.1f;
    scene.updateWorldTransforms();
    ++scene.geometryRevision;
    renderer_->render(scene, camera, settings);
    EXPECT_TRUE(renderer_->stats().voxelized) << "a transform edit re-voxelizes";
    EXPECT_TRUE(renderer_->stats().injected);
    ASSERT_NE(renderer_->voxels(), nullptr);
    EXPECT_EQ(renderer_->voxels()->resolution(), 64);
}

TEST_F(CornellGi, BadVoxelResolutionIsClampedWithAWarning) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = giSettings(true);
    settings.gi.voxelResolution = 100;
    render(scene, settings);
    ASSERT_NE(renderer_->voxels(), nullptr);
    EXPECT_EQ(renderer_->voxels()->resolution(), 128);
    bool warned = false;
    for (const LogMessage& m : log_.recent())
        warned |= m.level == LogLevel::Warning && m.text.find("not a power of two") != std::string::npos;
    EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace lit::test
