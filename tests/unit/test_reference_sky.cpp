// The editor's progressive reference (Reference and Difference views) sees the rasterizer's sky
// and default sun (docs/REFERENCE.md): a scene without lights under the default
// gradient sky. 16×16 pixels, direct light only: well under a second.

#include <gtest/gtest.h>

#include "RenderSettings.h"
#include "reference/ProgressiveReference.h"
#include "scene/CameraView.h"
#include "scene/SceneBuilder.h"
#include "scene/Sky.h"

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <thread>

namespace lit::reference {
namespace {

constexpr int kSize = 16;

struct Bare {
    Scene scene;
    CameraView camera;
};

// A grey floor, no lights, a camera looking down at it from above its edge: the top rows see
// the sky, the bottom rows the floor.
Bare bareFloor() {
    Bare b;
    const int grey = addMaterial(b.scene, glm::vec3(0.5f));
    addMeshNode(b.scene, makeBoxMesh("floor", glm::vec3(6.0f, 0.1f, 6.0f), grey), glm::vec3(0.0f, -0.05f, 0.0f));
    b.scene.updateWorldTransforms();
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.5f, 3.5f), glm::vec3(0.0f, 0.6f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    b.camera = makeCameraView(glm::inverse(view), 1.0f, 1.0f, 0.05f, 100.0f);
    return b;
}

// The world direction of the ray through the centre of pixel (x, y) (rows bottom-up).
glm::vec3 pixelDirection(const CameraView& camera, int x, int y) {
    const glm::mat4 inverse = glm::inverse(camera.projection * camera.view);
    const glm::vec2 ndc = (glm::vec2(x, y) + 0.5f) / float(kSize) * 2.0f - 1.0f;
    glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f), farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    return glm::normalize(glm::vec3(farPoint) / farPoint.w - glm::vec3(nearPoint) / nearPoint.w);
}

// The Final image once every pixel has `samples` samples of the current job (at most ~10 s).
std::vector<float> finalImage(ProgressiveReference& progressive, const RenderSettings& terms, std::uint64_t restarts,
                              int samples = 2) {
    for (int i = 0; i < 2000; ++i) {
        const ProgressiveStatus s = progressive.status();
        if (s.restarts >= restarts && s.samplesPerPixel >= samples) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::vector<float> rgb;
    int width = 0, height = 0;
    EXPECT_TRUE(progressive.latest(View::Final, terms, rgb, width, height));
    EXPECT_EQ(progressive.status().restarts, restarts);
    return rgb;
}

glm::vec3 pixel(const std::vector<float>& rgb, int x, int y) {
    const std::size_t i = 3 * static_cast<std::size_t>(y * kSize + x);
    return i + 2 < rgb.size() ? glm::vec3(rgb[i], rgb[i + 1], rgb[i + 2]) : glm::vec3(-1.0f);
}

TEST(ReferenceSky, TheEditorsReferenceSeesTheSameSkyAndSunAsTheRasterizer) {
    Bare b = bareFloor();
    ReferenceSettings settings;
    settings.bounces = 0;
    settings.pixelCentres = true;  // the sky pixels are then exact
    RenderSettings lighting;       // Auto sky: the gradient for a scene without lights; the default sun
    ASSERT_EQ(resolveSky(b.scene, lighting, nullptr).mode, SkyMode::Gradient);
    ASSERT_TRUE(hasDefaultSun(b.scene, lighting));
    const int skyX = kSize / 2, skyY = kSize - 1, floorX = kSize / 2, floorY = 0;

    ProgressiveReference progressive(8);
    // Without the rasterizer's settings (a caller that passes none): black.
    progressive.update(b.scene, b.camera, kSize, kSize, settings);
    const std::vector<float> unlit = finalImage(progressive, lighting, 1);
    EXPECT_EQ(pixel(unlit, skyX, skyY), glm::vec3(0.0f));
    EXPECT_EQ(pixel(unlit, floorX, floorY), glm::vec3(0.0f));

    progressive.update(b.scene, b.camera, kSize, kSize, settings, &lighting);
    const std::vector<float> lit = finalImage(progressive, lighting, 2);
    const Sky sky = resolveSky(b.scene, lighting, nullptr);
    const glm::vec3 expectedSky = skyRadiance(sky, pixelDirection(b.camera, skyX, skyY));
    // Camera rays that miss add the sky as it is: the same skyRadiance the background shows
    // (float rounding of the direction only).
    const glm::vec3 seen = pixel(lit, skyX, skyY);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], expectedSky[c], 1e-4f * expectedSky[c] + 1e-7f);
    // The floor, lit by the sun (and by the sky through BRDF-sampled rays): the sun alone gives
    // albedo/π · E · cos θ = 0.5/π · 4 W/m² · sin 60° ≈ 0.55 W/(sr·m²) (RenderSettings defaults).
    const float sunOnly = 0.5f / 3.14159265f * lighting.sky.sunIrradiance * std::sin(lighting.sky.sunElevation);
    EXPECT_GT(pixel(lit, floorX, floorY).g, 0.9f * sunOnly);
    // The same settings again: nothing restarts.
    progressive.update(b.scene, b.camera, kSize, kSize, settings, &lighting);
    EXPECT_EQ(progressive.status().restarts, 2u);

    // A brighter sky is a new job, and the background follows it.
    RenderSettings brighter = lighting;
    brighter.sky.intensity = 2.0f;
    progressive.update(b.scene, b.camera, kSize, kSize, settings, &brighter);
    const std::vector<float> twice = finalImage(progressive, brighter, 3);
    EXPECT_NEAR(pixel(twice, skyX, skyY).b, 2.0f * expectedSky.b, 1e-4f * expectedSky.b);

    // A scene with a light of its own gets neither the default sun nor (Auto) the sky.
    Light lamp;
    lamp.intensity = 0.0f;  // dark: anything seen comes from the sky or the sun
    addLightNode(b.scene, lamp, glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    b.scene.updateWorldTransforms();
    ++b.scene.lightRevision;
    progressive.update(b.scene, b.camera, kSize, kSize, settings, &lighting);
    const std::vector<float> ownLight = finalImage(progressive, lighting, 4);
    EXPECT_EQ(pixel(ownLight, skyX, skyY), glm::vec3(0.0f));
    EXPECT_EQ(pixel(ownLight, floorX, floorY), glm::vec3(0.0f));
    progressive.stop();
}

}  // namespace
}  // namespace lit::reference
