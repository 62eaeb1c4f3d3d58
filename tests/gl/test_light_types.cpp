// Every light type casts a shadow and follows the KHR_lights_punctual falloff, on a scene built in
// code: a 4 m white floor, a 0.6 m box floating 1 m above its centre, one light 3 m up.
#include "GlTestSupport.h"

#include "scene/SceneBuilder.h"
#include "scene/SceneMemory.h"

#include <glm/gtc/constants.hpp>

namespace lit::test {
namespace {

struct LightCase {
    const char* name;
    LightType type;
};

class LightTypes : public GlFixture, public ::testing::WithParamInterface<LightCase> {
protected:
    Scene makeScene(LightType type) {
        Scene scene;
        const int white = addMaterial(scene, glm::vec3(0.8f), 0.9f, 0.0f, "white");
        addMeshNode(scene, makePlaneMesh("floor", 4.0f, white, 4), glm::vec3(0.0f));
        addMeshNode(scene, makeBoxMesh("occluder", glm::vec3(0.6f), white), glm::vec3(0.0f, 1.0f, 0.0f));
        Light light;
        light.type = type;
        light.intensity = type == LightType::Directional ? 3.0f : 27.0f;
        light.outerConeAngle = 0.9f;
        light.innerConeAngle = 0.7f;
        addLightNode(scene, light, glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
        Camera camera;
        camera.yfov = 0.9f;
        addCameraNode(scene, camera, glm::vec3(0.0f, 4.0f, 3.0f), glm::vec3(0.0f, 0.0f, 0.0f));
        return scene;
    }
};

TEST_P(LightTypes, OccluderCastsAShadowBelowIt) {
    const Scene scene = makeScene(GetParam().type);
    const RenderSettings settings = smallSettings();
    const HdrImage image = render(scene, settings);
    // (0,0,0.05) is below the box for every light type; (1.2,0,0) is outside its shadow.
    const float shadowed = luminance(radianceAt(scene, settings, image, {0.0f, 0.0f, 0.05f}, 1));
    const float lit = luminance(radianceAt(scene, settings, image, {1.2f, 0.0f, 0.0f}, 1));
    EXPECT_GT(lit, 0.1f);
    EXPECT_LT(shadowed, 0.1f * lit) << "shadowed " << shadowed << " lit " << lit;
}

TEST_P(LightTypes, WithoutShadowsTheSamePointIsLit) {
    const Scene scene = makeScene(GetParam().type);
    RenderSettings settings = smallSettings();
    settings.shadows.enabled = false;
    const HdrImage image = render(scene, settings);
    const float below = luminance(radianceAt(scene, settings, image, {0.0f, 0.0f, 0.05f}, 1));
    EXPECT_GT(below, 0.1f);
}

TEST_P(LightTypes, IrradianceFollowsTheUnits) {
    // L = albedo/π · E, E = I·cosθ/d² (point, spot inside the inner cone) or E = lux·cosθ.
    const Scene scene = makeScene(GetParam().type);
    RenderSettings settings = smallSettings();
    const HdrImage image = render(scene, settings);
    const glm::vec3 p{1.2f, 0.0f, 0.0f};
    const glm::vec3 toLight = glm::vec3(0.0f, 3.0f, 0.0f) - p;
    const float d = glm::length(toLight);
    const float cosTheta = toLight.y / d;
    const float E = GetParam().type == LightType::Directional ? 3.0f : 27.0f * cosTheta / (d * d);
    const float expected = 0.8f / glm::pi<float>() * E;
    const float measured = luminance(radianceAt(scene, settings, image, p, 1));
    EXPECT_NEAR(measured, expected, 0.04f * expected);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, LightTypes,
                         ::testing::Values(LightCase{"directional", LightType::Directional},
                                           LightCase{"point", LightType::Point}, LightCase{"spot", LightType::Spot}),
                         [](const auto& info) { return std::string(info.param.name); });

// The lighting programs compile out the shadow lookups of a kind no light has (ShadowKinds,
// lights.glsl): a scene with a spot and a point light, each casting a shadow, renders as the sum of
// the two lights alone (each of which runs a program with one kind of lookup), shadows included.
TEST_F(GlFixture, SpotAndPointShadowsTogetherAreTheSumOfEachAlone) {
    const auto makeScene = [](bool spot, bool point) {
        Scene scene;
        const int white = addMaterial(scene, glm::vec3(0.8f), 0.9f, 0.0f, "white");
        addMeshNode(scene, makePlaneMesh("floor", 4.0f, white, 4), glm::vec3(0.0f));
        addMeshNode(scene, makeBoxMesh("left occluder", glm::vec3(0.5f), white), glm::vec3(-0.8f, 1.0f, 0.0f));
        addMeshNode(scene, makeBoxMesh("right occluder", glm::vec3(0.5f), white), glm::vec3(0.8f, 1.0f, 0.0f));
        Light light;
        light.intensity = 27.0f;
        light.outerConeAngle = 0.9f;
        light.innerConeAngle = 0.7f;
        light.type = LightType::Spot;
        if (spot) addLightNode(scene, light, glm::vec3(-0.8f, 3.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
        light.type = LightType::Point;
        if (point) addLightNode(scene, light, glm::vec3(0.8f, 3.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
        Camera camera;
        camera.yfov = 0.9f;
        addCameraNode(scene, camera, glm::vec3(0.0f, 4.0f, 3.0f), glm::vec3(0.0f, 0.0f, 0.0f));
        return scene;
    };
    const RenderSettings settings = smallSettings();
    const Scene both = makeScene(true, true);
    const HdrImage together = render(both, settings);
    const HdrImage spotAlone = render(makeScene(true, false), settings);
    const HdrImage pointAlone = render(makeScene(false, true), settings);
    // Per value: the terms are RGBA16F (2^-11 relative), the HDR image their 32-bit sum.
    double worst = 0.0;
    for (std::size_t i = 0; i < together.rgb.size(); ++i) {
        const double error = std::abs(together.rgb[i] - spotAlone.rgb[i] - pointAlone.rgb[i]);
        worst = std::max(worst, error / (std::abs(together.rgb[i]) + 1e-3));
    }
    EXPECT_LT(worst, 2e-3);
    // Each occluder's shadow is there: below the left box the spot is blocked, below the right one the point light.
    const float belowLeft = luminance(radianceAt(both, settings, together, {-0.8f, 0.0f, 0.05f}, 1));
    const float belowRight = luminance(radianceAt(both, settings, together, {0.8f, 0.0f, 0.05f}, 1));
    const float spotBelowLeft = luminance(radianceAt(both, settings, spotAlone, {-0.8f, 0.0f, 0.05f}, 1));
    const float pointBelowRight = luminance(radianceAt(both, settings, pointAlone, {0.8f, 0.0f, 0.05f}, 1));
    const float spotLit = luminance(radianceAt(both, settings, spotAlone, {-0.8f, 0.0f, 1.2f}, 1));
    const float pointLit = luminance(radianceAt(both, settings, pointAlone, {0.8f, 0.0f, 1.2f}, 1));
    EXPECT_LT(spotBelowLeft, 0.1f * spotLit);
    EXPECT_LT(pointBelowRight, 0.1f * pointLit);
    EXPECT_GT(belowLeft, 0.0f);
    EXPECT_GT(belowRight, 0.0f);
}

// A spot and a point light 6 m from a 0.3 m wall: the floor right behind the wall is in its
// shadow. The shadow maps' constant depth bias is a share of the depth range in linear depth
// (lights.glsl, perspectiveShadowDepth); subtracted from the projected depth it grew with the
// square of the distance, and at 6 m the floor behind the wall read 1.25× the floor beside it.
TEST_F(GlFixture, DistantSpotAndPointLightsDoNotShineThroughAWall) {
    for (const LightType type : {LightType::Spot, LightType::Point}) {
        Scene scene;
        const int white = addMaterial(scene, glm::vec3(0.8f), 0.9f, 0.0f, "white");
        addMeshNode(scene, makePlaneMesh("floor", 16.0f, white, 8), glm::vec3(0.0f));
        addMeshNode(scene, makeBoxMesh("wall", glm::vec3(0.3f, 2.0f, 4.0f), white), glm::vec3(0.0f, 1.0f, 0.0f));
        Light light;
        light.type = type;
        light.intensity = 200.0f;
        light.outerConeAngle = 0.7f;
        light.innerConeAngle = 0.6f;
        const glm::vec3 position(-6.0f, 3.0f, 0.0f);
        addLightNode(scene, light, position, glm::normalize(glm::vec3(0.4f, 0.0f, 0.0f) - position));
        Camera camera;
        camera.yfov = 1.0f;
        addCameraNode(scene, camera, glm::vec3(2.5f, 5.0f, 0.5f), glm::vec3(0.6f, 0.0f, 1.0f));
        const RenderSettings settings = smallSettings(128);
        const HdrImage image = render(scene, settings);
        // Behind the wall (the light's ray to it crosses the wall 0.2 m above the floor), and beside it.
        const float behind = luminance(radianceAt(scene, settings, image, {0.5f, 0.0f, 0.0f}, 1));
        const float beside = luminance(radianceAt(scene, settings, image, {0.5f, 0.0f, 2.8f}, 1));
        const char* name = type == LightType::Spot ? "spot" : "point";
        ASSERT_GT(beside, 0.0f) << name << ": the floor beside the wall must be lit";
        EXPECT_LT(behind, 0.02f * beside) << name << ": light through the wall";
    }
}

TEST_F(GlFixture, SpotFalloffMatchesTheSpec) {
    // A spot straight down over a floor: radiance at increasing angles follows
    // saturate(cosθ·scale + offset)² · cosθ / d² (KHR_lights_punctual).
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(1.0f), 1.0f, 0.0f, "white");
    addMeshNode(scene, makePlaneMesh("floor", 8.0f, white, 8), glm::vec3(0.0f));
    Light spot;
    spot.type = LightType::Spot;
    spot.intensity = 10.0f;
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.6f;
    spot.castsShadow = false;
    addLightNode(scene, spot, glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    Camera camera;
    camera.yfov = 1.2f;
    addCameraNode(scene, camera, glm::vec3(0.0f, 3.0f, 0.01f), glm::vec3(0.0f, 0.0f, 0.0f));
    const RenderSettings settings = smallSettings(256);
    const HdrImage image = render(scene, settings);
    const float scale = 1.0f / (std::cos(0.2f) - std::cos(0.6f));
    const float offset = -std::cos(0.6f) * scale;
    for (float angle : {0.1f, 0.3f, 0.4f, 0.5f, 0.7f}) {
        const float x = 2.0f * std::tan(angle);
        const float d = 2.0f / std::cos(angle);
        const float cone = std::clamp(std::cos(angle) * scale + offset, 0.0f, 1.0f);
        const float expected = 1.0f / glm::pi<float>() * 10.0f * cone * cone * std::cos(angle) / (d * d);
        const float measured = luminance(radianceAt(scene, settings, image, {x, 0.0f, 0.0f}, 0));
        EXPECT_NEAR(measured, expected, 0.03f * expected + 2e-3f) << "angle " << angle;
    }
}

// The shadow maps the renderer allocates are what SceneMemory counts against the memory budget
// (before loading, in the loader), apart from the small layer kept for a kind no light uses.
TEST_F(GlFixture, ShadowMapMemoryIsWhatTheBudgetCounts) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f), 0.9f, 0.0f, "white");
    const int glass = addMaterial(scene, glm::vec3(0.9f), 0.1f, 0.0f, "glass");
    addMeshNode(scene, makePlaneMesh("floor", 4.0f, white, 4), glm::vec3(0.0f));
    addMeshNode(scene, makeBoxMesh("pane", glm::vec3(1.0f, 1.0f, 0.02f), glass), glm::vec3(0.0f, 1.0f, 0.0f));
    Light sun;
    sun.type = LightType::Directional;
    addLightNode(scene, sun, glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    Camera camera;
    addCameraNode(scene, camera, glm::vec3(0.0f, 3.0f, 3.0f), glm::vec3(0.0f));
    RenderSettings settings = smallSettings(64);
    settings.shadows.mapSize = 256;
    const std::uint64_t unusedKinds = 64 * 1024;  // 16² texels × 7 layers × 4 bytes, and white texels
    const auto check = [&](const char* what) {
        render(scene, settings);
        const std::uint64_t counted = estimateSceneMemory(scene, RenderFootprint::of(settings)).shadowMaps;
        const std::uint64_t allocated = renderer_->stats().shadowMapBytes;
        EXPECT_GE(allocated, counted) << what;
        EXPECT_LT(allocated - counted, unusedKinds) << what << ": " << allocated << " bytes allocated, " << counted << " counted";
    };
    check("a sun");
    Light point;
    point.type = LightType::Point;
    addLightNode(scene, point, glm::vec3(1.0f, 2.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    check("a sun and a point light");
    scene.materials[static_cast<std::size_t>(glass)].transmission = 1.0f;
    check("a sun, a point light and a sheet");
    // The sun's map and the point light's six faces, each with a colour layer, and the sun's cascades.
    EXPECT_EQ(estimateSceneMemory(scene, RenderFootprint::of(settings)).shadowMaps,
              256u * 256 * 7 * (4 + 8) + 256u * 256 * settings.shadows.cascades * 4);
}

}  // namespace
}  // namespace lit::test
