// Scenes from other tools look right without manual settings:
//  - Blender-exported scenes (tests/data/blender, made by tools/blender/make_scenes.py) render
//    within 25 % of the mean brightness of Blender's own Cycles render of them;
//  - a scene without lights gets a default sun and a sky, whose light reaches surfaces through
//    the voxel cones (and is blocked by geometry);
//  - auto exposure meters the image: 4× the light is 2 stops less exposure, the same picture;
//  - Sponza (when the shared scenes are present) is lit from inside the atrium.
#include "GlTestSupport.h"

#include "image/ImageIO.h"
#include "scene/SceneBuilder.h"
#include "scene/Sky.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace lit::test {
namespace {

float meanLuminance(const HdrImage& image) { return luminance(image.mean(0.0f, 0.0f, 1.0f, 1.0f)); }

class BlenderScenes : public GlFixture, public ::testing::WithParamInterface<const char*> {};

// Lit's defaults (EV 0, no auto exposure, sky auto = none for a lit scene, GI on) against the
// mean of Cycles' linear render (256 samples, black world; cycles_reference.json says how it was
// made). Both are means of linear radiance over all pixels of the same camera at 128×128, so no
// view transform enters. The 25 % bound on the full image is the requirement for scenes from
// other tools (Cycles
// traces every bounce, Lit one cone-traced bounce). The direct light alone (Lit without GI,
// Cycles with no bounces) isolates the light units from the GI: 10 % covers the differences in
// shading models (Principled BSDF vs Lit's GGX + Lambert) and Cycles' noise (< 1 % at 256
// samples). Measured ratios are printed and listed in docs/UNITS.md.
TEST_P(BlenderScenes, MeanBrightnessWithin25PercentOfCycles) {
    const std::filesystem::path folder = sourceDir() / "tests" / "data" / "blender";
    std::ifstream in(folder / "cycles_reference.json");
    ASSERT_TRUE(in) << "missing " << (folder / "cycles_reference.json").string();
    const nlohmann::json reference = nlohmann::json::parse(in);
    const nlohmann::json& cycles = reference.at("scenes").at(GetParam());

    const Scene scene = loadGltf(folder / (std::string(GetParam()) + ".gltf"), log_);
    ASSERT_EQ(scene.lights.size(), 1u);
    ASSERT_EQ(scene.cameras.size(), 1u);
    RenderSettings settings;  // defaults: nothing set by hand
    settings.output.width = 128;
    settings.output.height = 128;
    const double lit = meanLuminance(render(scene, settings));
    settings.gi.enabled = false;
    const double litDirect = meanLuminance(render(scene, settings));
    const double ratio = lit / cycles.at("meanLuminance").get<double>();
    const double directRatio = litDirect / cycles.at("directMeanLuminance").get<double>();
    std::printf("%s: Lit %.4f / Cycles %.4f = %.3f; direct light only: Lit %.4f / Cycles %.4f = %.3f\n", GetParam(), lit,
                cycles.at("meanLuminance").get<double>(), ratio, litDirect,
                cycles.at("directMeanLuminance").get<double>(), directRatio);
    EXPECT_GT(directRatio, 0.9);
    EXPECT_LT(directRatio, 1.1);
    // The point scene is 1.28x Cycles in the fast GI mode (its cone-traced indirect diffuse 0.262
    // where the reference's one bounce gives 0.069: docs/UNITS.md, "Brightness against Blender's
    // Cycles"); in the cached mode, the default, it is 0.91 (spot 0.86, sun 0.88), so all three are
    // asserted.
    EXPECT_GT(ratio, 0.75);
    EXPECT_LT(ratio, 1.25);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BlenderScenes, ::testing::Values("point", "spot", "sun"),
                         [](const auto& info) { return std::string(info.param); });

class SceneDefaults : public GlFixture {
protected:
    // A 6 m floor and a 1 m box on it, no lights, seen from `eye`; optionally a 2 m × 2 m roof
    // 1 m above the floor around (2, 0, 2) that shades the floor below it from the sky.
    // GI on, the sun off and a uniform sky of radiance 1: the indirect diffuse view.
    static RenderSettings uniformSkySettings() {
        RenderSettings settings = smallSettings();
        settings.gi.enabled = true;
        settings.sky.sunIrradiance = 0.0f;
        settings.sky.mode = SkyMode::Uniform;
        settings.sky.zenith = {1.0f, 1.0f, 1.0f};
        settings.debug.view = View::IndirectDiffuse;
        return settings;
    }
    static Scene bareScene(bool roof, glm::vec3 eye, glm::vec3 target) {
        Scene scene;
        const int grey = addMaterial(scene, glm::vec3(0.5f), 1.0f, 0.0f, "grey");
        addMeshNode(scene, makePlaneMesh("floor", 6.0f, grey, 6), glm::vec3(0.0f));
        addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), grey), glm::vec3(-1.5f, 0.5f, -1.5f));
        if (roof) addMeshNode(scene, makeBoxMesh("roof", glm::vec3(2.0f, 0.1f, 2.0f), grey), glm::vec3(2.0f, 1.0f, 2.0f));
        Camera camera;
        camera.yfov = 1.0f;
        addCameraNode(scene, camera, eye, target);
        return scene;
    }
};

TEST_F(SceneDefaults, BareSceneGetsASunAtAnAngleAndASky) {
    // Seen from the side the default sun's shadows fall towards, so they are in view.
    const Scene scene = bareScene(false, {-5.0f, 6.0f, -5.0f}, {0.0f, 0.0f, 0.0f});
    RenderSettings settings = smallSettings();
    settings.gi.enabled = true;
    const HdrImage image = render(scene, settings);
    // Sun: 4 W/m² at 60° elevation on albedo 0.5: L = 0.5/π · 4 · sin 60° ≈ 0.55, plus the sky's
    // ≈ 0.5/π · 0.8 ≈ 0.13.
    const float floor = luminance(radianceAt(scene, settings, image, {1.0f, 0.0f, 1.5f}));
    EXPECT_GT(floor, 0.4f);
    EXPECT_LT(floor, 1.0f);
    // The sun is not straight down: the box's shadow lies beside it, on the side the light
    // travels to (0.8 m from its centre; the shadow of a 1 m box at 60° reaches 0.58 m past its edge).
    const glm::vec3 sunDirection = defaultSunDirection(settings);
    ASSERT_LT(std::abs(sunDirection.y), 0.95f);
    const glm::vec3 behind =
        glm::vec3(-1.5f, 0.0f, -1.5f) + glm::normalize(glm::vec3(sunDirection.x, 0.0f, sunDirection.z)) * 0.8f;
    const float shadow = luminance(radianceAt(scene, settings, image, behind, 1));
    std::printf("bare scene: open floor %.3f, in the box's shadow %.3f\n", floor, shadow);
    EXPECT_LT(shadow, 0.5f * floor);
    // The background is the sky model: the top row looks 12° below the horizon, past the floor.
    const CameraView view = cameraFor(scene, settings);
    const int x = settings.output.width / 2, y = settings.output.height - 1;
    const glm::vec4 far =
        glm::inverse(view.viewProjection()) * glm::vec4((x + 0.5f) / settings.output.width * 2.0f - 1.0f,
                                                        (y + 0.5f) / settings.output.height * 2.0f - 1.0f, 1.0f, 1.0f);
    const glm::vec3 expected = skyRadiance(resolveSky(scene, settings, nullptr), glm::vec3(far) / far.w - view.position);
    EXPECT_LT(glm::length(image.at(x, y) - expected), 0.01f * glm::length(expected) + 1e-4f);
}

// A uniform sky of radiance L over an open floor gives irradiance π·L, so the floor's indirect
// diffuse radiance should be ρ·L = 0.5 (ρ = 0.5); with the sun off this is all the light there is.
// How much of it a roof takes away is SkyUnderARoofMatchesTheClosedForm's (below): this camera, low
// and far, averages metres of floor in a pixel, the open floor beyond the roof too. A band of less
// than 0.6 × the open floor's under the roof read 0.279 with rays started √3 voxels off the voxel
// centre (the closed form's one-bounce 0.210 is 0.42 of ρ·L) and reads 0.320 with the rays that
// start on the floor, the open floor in the window with more of the sky that the roof truly leaves.
TEST_F(SceneDefaults, SkyLightReachesAnOpenFloorThroughTheVoxels) {
    RenderSettings settings = uniformSkySettings();
    settings.gi.voxelResolution = 64;
    const glm::vec3 eye(2.0f, 0.4f, 7.0f), target(2.0f, 0.0f, 2.0f);
    const Scene open = bareScene(false, eye, target);
    const float openFloor = luminance(radianceAt(open, settings, render(open, settings), target));
    std::printf("sky light on the open floor: %.3f (rho L = 0.5)\n", openFloor);
    // Fails if sky light stops arriving (0) or is counted twice (1).
    EXPECT_NEAR(openFloor, 0.5f, 0.05f);
}

// View factor from a point to a rectangle in a parallel plane at height h, the rectangle's corner
// straight above the point, sides a and b (the cosine-weighted share of the hemisphere it covers).
double parallelRectangleViewFactor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * 3.14159265358979);
}

// A closed form for the voxel rays' geometry (resolution independence): one bounce of a
// uniform sky (radiance L = 1, no sun) on a floor of albedo ρ = 0.5 under a 2 m × 2 m roof 0.95 m
// above it. The roof holds no light (one bounce: only what the sky gives directly), so the floor
// below its centre reflects ρ·L·(1 − F), F = the roof's view factor (0.579), and the open floor ρ·L.
// Voxel rays started √3 voxels off the voxel centre (17 cm at 64³ here, where a voxel is 10 cm),
// from where the roof covers more of the sky, and ended where they entered a voxel, so the roof
// looked up to a voxel wider: the floor read 0.60 and 0.83 of the closed form at 64³ and 128³. They
// start half a voxel off the floor's plane and end on the roof's surface (bounce.comp.glsl;
// docs/GI.md, "Rays that end on the surface"): 0.905 and 0.955. Bar ±10 %, the resolution-
// independence bar, at both. What is left at 64³ is mostly the start, still
// 5 cm above the floor: from there the roof's view factor is 0.605, the floor's share of the sky 6 %
// less (0.25 voxel off reads 0.950 and 0.972, but the sealed room leaks 0.84 % at 128³, not 0.73 %).
TEST_F(SceneDefaults, SkyUnderARoofMatchesTheClosedForm) {
    RenderSettings settings = uniformSkySettings();
    settings.gi.bounces = 1;
    // The camera under the roof, looking down at the floor below its centre: from the side, a pixel
    // at grazing incidence spans metres of floor, the open floor beyond the roof's edge too.
    const glm::vec3 eye(2.0f, 0.5f, 2.6f), target(2.0f, 0.0f, 2.0f);
    const Scene covered = bareScene(true, eye, target);
    const double roofShare = 4.0 * parallelRectangleViewFactor(1.0, 1.0, 0.95);
    const double expected = 0.5 * (1.0 - roofShare);
    for (const int voxels : {64, 128}) {
        settings.gi.voxelResolution = voxels;
        const float underRoof = luminance(radianceAt(covered, settings, render(covered, settings), target));
        std::printf("%d³: floor under the roof %.3f, closed form %.3f (roof's view factor %.3f): %.3f\n", voxels,
                    underRoof, expected, roofShare, underRoof / expected);
        EXPECT_NEAR(underRoof / expected, 1.0, 0.10) << voxels << "³";
    }
}

// Auto exposure meters the image, not the light: four times the light is two stops less
// exposure and (within the histogram's half-stop bins) the same tone-mapped picture.
TEST_F(SceneDefaults, AutoExposureFollowsTheLight) {
    Scene scene = loadCornellBox();
    RenderSettings settings = smallSettings(64);
    settings.output.autoExposure = true;
    settings.output.autoExposureSpeed = 0.0f;  // instant, so one frame settles
    render(scene, settings);
    const float ev = renderer_->exposureEv(settings);
    const std::vector<std::uint8_t> before = renderer_->readOutputRgba8();
    scene.lights[0].intensity *= 4.0f;
    ++scene.lightRevision;
    render(scene, settings);
    const float brighterEv = renderer_->exposureEv(settings);
    const std::vector<std::uint8_t> after = renderer_->readOutputRgba8();
    std::printf("auto exposure: %.3f EV, with 4x the light %.3f EV\n", ev, brighterEv);
    EXPECT_NEAR(ev - brighterEv, 2.0f, 0.5f);  // half-stop bins
    double meanBefore = 0.0, meanAfter = 0.0;
    for (std::size_t i = 0; i < before.size(); i += 4) meanBefore += before[i + 1];
    for (std::size_t i = 0; i < after.size(); i += 4) meanAfter += after[i + 1];
    EXPECT_NEAR(meanAfter / meanBefore, 1.0, 0.15);
    // Compensation adds stops to the metered value.
    settings.output.exposureEv = 1.0f;
    render(scene, settings);
    EXPECT_NEAR(renderer_->exposureEv(settings), brighterEv + 1.0f, 0.01f);
}

std::filesystem::path sharedScene(const char* relative) {
    std::vector<std::filesystem::path> roots;
    if (const char* env = std::getenv("LIT_SCENES_DIR"); env && *env) roots.emplace_back(env);
    roots.push_back(sourceDir() / ".." / "shared" / "scenes");        // /work/main → /work/shared
    roots.push_back(sourceDir() / ".." / ".." / "shared" / "scenes");  // a worktree /work/wt/x
    for (const auto& root : roots)
        if (std::filesystem::exists(root / relative)) return root / relative;
    return {};
}

// Sponza has no lights and no camera. From inside the atrium, with every setting at its
// default, the image has the brightness the path-traced reference gives this view, and the sky
// lights the galleries through the GI. Skipped without the shared scenes; about 30 s (the load,
// one render with sun and sky, one with the sky alone, both in the default mode).
//
// The bounds come from the reference renderer (reference/PathTracer.h) of this view, 128 × 96,
// with the same default sun and gradient sky (docs/UNITS.md "Sponza's atrium under the default sun
// and sky"):
//  - the mean linear luminance with sun and sky, every bounce, 16 spp: 0.0243. Lit must be
//    within 25 % of it (the bar for the Blender scenes against Cycles); Lit measures 0.0247 (the
//    cached mode, the default), 0.0254 (accurate mode) and 0.0256 (fast mode). A bound of
//    mean > 0.05 would ask for twice the light the scene physically gives this view (about 3 stops
//    under the sunlit ground).
//  - sky light on surfaces, sun off: the diffuse light the sky gives the surfaces in view by one
//    segment (Lit's one-bounce cones return the sky, its voxels hold no sky light), as a mean over
//    all pixels (background 0): 0.00099 (every bounce: 0.00118). This is a presence check, not an
//    accuracy check: the default (cached) mode measures 0.00026 = 0.26 of it, the accurate mode
//    (anisotropic voxels, footprint 0.25, cones per pixel) 0.00028 = 0.28 (0.33: 0.23; narrower
//    footprints read more: 0.1 → 0.00054, 0.03 → 0.00075; the coarse voxels over the atrium's 11 m
//    walls block most of its opening, docs/UNITS.md), the fast mode 2·10⁻⁵ = 0.02 (lost). The
//    bar, more than a tenth of the reference, fails when the sky light is lost as in the fast mode
//    and passes with the cone-traced modes' known gap (docs/GI.md, "Known limits"); the upper bar,
//    1.25 × the reference, fails if the sky is counted twice. A bound of > 0.01 would be ten times
//    the reference's sky light.
TEST_F(SceneDefaults, SponzaFromInsideTheAtriumIsLitBySunAndSky) {
    const std::filesystem::path path = sharedScene("sponza/Sponza.gltf");
    if (path.empty()) GTEST_SKIP() << "Sponza not found (set LIT_SCENES_DIR or put it in ../shared/scenes): skipped";
    Scene scene = loadGltf(path, log_);
    ASSERT_TRUE(scene.lights.empty());
    // A view from one end of the atrium along its length, 2 m above the floor.
    const Aabb bounds = scene.worldBounds();
    const glm::vec3 centre = bounds.center();
    const glm::vec3 size = bounds.max - bounds.min;
    Camera camera;
    camera.yfov = 1.0f;
    // Sponza's floor is at y ≈ 0 (its bounds reach 1 m below it); the atrium runs along x.
    const glm::vec3 eye(centre.x + 0.2f * size.x, 1.7f, centre.z);
    addCameraNode(scene, camera, eye, glm::vec3(centre.x - 0.4f * size.x, 4.0f, centre.z));
    scene.updateWorldTransforms();
    RenderSettings settings;
    settings.output.width = 128;
    settings.output.height = 96;
    settings.gi.voxelResolution = 128;
    const CameraView view = sceneCameraView(scene, 0, 128.0f / 96.0f);
    EXPECT_LT(view.znear, 0.1f) << "the near plane must not cut into the atrium";
    const HdrImage image = render(scene, settings);
    writePng(outputDir() / "sponza_default_light.png", settings.output.width, settings.output.height,
             renderer_->readOutputRgba8());
    const float mean = meanLuminance(image);
    RenderSettings skyOnly = settings;
    skyOnly.sky.sunIrradiance = 0.0f;  // the default GI mode, as `settings`
    skyOnly.debug.view = View::IndirectDiffuse;
    const float skyLight = meanLuminance(render(scene, skyOnly));
    constexpr float kReferenceMean = 0.0243f;      // sun and sky, every bounce, 16 spp
    constexpr float kReferenceSkyLight = 0.00099f;  // sky only, by one segment, diffuse, on surfaces
    std::printf("Sponza from inside (eye %.1f %.1f %.1f): mean luminance %.4f (reference %.4f); sky light on surfaces "
                "in the default mode %.5f (reference %.5f, ratio %.2f)\n",
                eye.x, eye.y, eye.z, mean, kReferenceMean, skyLight, kReferenceSkyLight, skyLight / kReferenceSkyLight);
    EXPECT_GT(mean, 0.75f * kReferenceMean);
    EXPECT_LT(mean, 1.25f * kReferenceMean);
    EXPECT_GT(skyLight, 0.1f * kReferenceSkyLight);
    EXPECT_LT(skyLight, 1.25f * kReferenceSkyLight);
}

}  // namespace
}  // namespace lit::test
