// Transmissive sheets in the reference path tracer (label cpu): KHR_materials_transmission drawn as
// a thin sheet that lets T = t·(1 − m)·c·(1 − F(|cosθ|)) through along the same line
// (docs/MATERIALS.md, "Transmission"), against closed forms.
#include "QuietLog.h"
#include "ReferenceTestScenes.h"
#include "reference/MicrofacetBrdf.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/CameraView.h"
#include "scene/SceneBuilder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lit::reference {
namespace {

using lit::testing::QuietLog;
using testing::addCamera;

constexpr float kFloorAlbedo = 0.8f;
const glm::vec3 kTint(0.9f, 0.5f, 0.2f);

// A white floor at y = 0 and, unless `sheet` is false, a tinted transmissive sheet (t = 1,
// roughness 0.5) over it at y = 1, both 60 m wide; `light` shines straight down.
Scene floorUnderSheet(bool sheet, const glm::vec3& cameraPosition, const glm::vec3& cameraTarget, bool light) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(kFloorAlbedo), 1.0f, 0.0f, "white");
    addMeshNode(scene, makePlaneMesh("floor", 60.0f, white), glm::vec3(0.0f));
    if (sheet) {
        const int glass = addMaterial(scene, kTint, 0.5f, 0.0f, "glass");
        scene.materials[static_cast<std::size_t>(glass)].transmission = 1.0f;
        addMeshNode(scene, makePlaneMesh("sheet", 60.0f, glass), glm::vec3(0.0f, 1.0f, 0.0f));
    }
    if (light) {
        Light sun;
        sun.type = LightType::Directional;
        sun.intensity = 3.0f;
        addLightNode(scene, sun, glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    }
    addCamera(scene, cameraPosition, cameraTarget);
    scene.updateWorldTransforms();
    return scene;
}

float fresnel(float cosine) { return 0.04f + 0.96f * std::pow(1.0f - cosine, 5.0f); }

// The sun through the sheet onto the floor, and the floor seen through the sheet: every pixel's
// direct diffuse light is the bare floor's times T at the light's angle (normal incidence) times T
// at the view's angle. Pixel centres and a punctual light: no noise, the ratio is exact.
TEST(ReferenceSheets, SunAndViewThroughASheetAreDimmedByItsTransmittanceTwice) {
    const glm::vec3 eye(0.0f, 3.0f, 2.5f), target(0.0f);
    ReferenceSettings settings;
    settings.bounces = 0;
    settings.pixelCentres = true;
    QuietLog log;
    constexpr int kSize = 16;
    const Scene bare = floorUnderSheet(false, eye, target, true), covered = floorUnderSheet(true, eye, target, true);
    const ReferenceScene bareScene(bare, log), coveredScene(covered, log);
    const CameraView view = sceneCameraView(bare, 0, 1.0f);
    PathTracer bareTracer(bareScene, view, kSize, kSize, settings), coveredTracer(coveredScene, view, kSize, kSize, settings);
    bareTracer.addSamples(1);
    coveredTracer.addSamples(1);
    const std::vector<FirstHit> hits = traceFirstHits(coveredScene, view, kSize, kSize);
    int checked = 0;
    for (std::size_t p = 0; p < hits.size(); ++p) {
        ASSERT_GE(hits[p].node, 0);
        const float cosView = std::abs(glm::normalize(view.position - hits[p].position).y);
        const glm::vec3 expected = bareTracer.image().mean(Term::DirectDiffuse, p) * kTint * kTint *
                                   (1.0f - fresnel(1.0f)) * (1.0f - fresnel(cosView));
        const glm::vec3 got = coveredTracer.image().mean(Term::DirectDiffuse, p);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-4f + 1e-4f * expected[c]) << "pixel " << p;
        EXPECT_TRUE(hits[p].litBy & 1u) << "the sun lights the floor through the sheet";
        ++checked;
    }
    EXPECT_EQ(checked, kSize * kSize);
}

// A uniform sky through the sheet onto the floor, seen from under the sheet: the floor's radiance
// is ρ·L_sky·c·2∫(1 − F(μ))μ dμ = ρ·L_sky·c·0.96·20/21 (F = 0.04 + 0.96(1 − μ)⁵). The paths that
// meet the sheet pass through it or scatter by chance: the mean must still be exact.
TEST(ReferenceSheets, SkyThroughASheetMatchesTheClosedForm) {
    const Scene scene = floorUnderSheet(true, glm::vec3(0.0f, 0.6f, 0.4f), glm::vec3(0.0f, 0.0f, -0.2f), false);
    QuietLog log;
    const ReferenceScene reference(scene, log);
    ReferenceSettings settings;
    settings.bounces = 0;
    settings.environment = [](const glm::vec3&) { return glm::vec3(1.0f); };
    constexpr int kSize = 24;
    PathTracer tracer(reference, sceneCameraView(scene, 0, 1.0f), kSize, kSize, settings);
    tracer.addSamples(256);
    glm::dvec3 sum(0.0);
    for (std::size_t p = 0; p < static_cast<std::size_t>(kSize * kSize); ++p)
        sum += glm::dvec3(tracer.image().mean(Term::DirectDiffuse, p));
    const glm::vec3 mean(sum / double(kSize * kSize));
    const glm::vec3 expected = kFloorAlbedo * kTint * (0.96f * 20.0f / 21.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], expected[c], 0.015f * expected[c]) << "channel " << c;
}

// A sheet of transmission 0.5 keeps half its diffuse albedo: under the sun, its own direct diffuse
// is (1 − t)·ρ/π·E, what an opaque one of the same colour reflects, halved.
TEST(ReferenceSheets, PartialTransmissionHalvesTheDiffuseLobe) {
    Scene scene;
    const int grey = addMaterial(scene, glm::vec3(0.6f), 1.0f, 0.0f, "grey");
    scene.materials[0].transmission = 0.5f;
    addMeshNode(scene, makePlaneMesh("sheet", 60.0f, grey), glm::vec3(0.0f));
    Light sun;
    sun.type = LightType::Directional;
    sun.intensity = 2.0f;
    addLightNode(scene, sun, glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    addCamera(scene, glm::vec3(0.0f, 3.0f, 2.5f), glm::vec3(0.0f));
    scene.updateWorldTransforms();
    QuietLog log;
    const ReferenceScene reference(scene, log);
    ReferenceSettings settings;
    settings.bounces = 0;
    settings.pixelCentres = true;
    PathTracer tracer(reference, sceneCameraView(scene, 0, 1.0f), 8, 8, settings);
    tracer.addSamples(1);
    const float expected = 0.5f * 0.6f / kPi * 2.0f;
    for (std::size_t p = 0; p < 64; ++p) EXPECT_NEAR(tracer.image().mean(Term::DirectDiffuse, p).g, expected, 1e-4f);
}

}  // namespace
}  // namespace lit::reference
