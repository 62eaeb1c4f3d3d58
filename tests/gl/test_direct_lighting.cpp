// Direct lighting on the Cornell box (GI off): properties that fail for the right reason.
// World points below are on the box as assets/README.md describes it: the spot light hangs at
// (0, 1.9, 0) pointing down; the tall box stands at (−0.33, 0, −0.3), the short one at (0.35, 0, 0.35).
#include "GlTestSupport.h"

namespace lit::test {
namespace {

class CornellDirect : public GlFixture {};

TEST_F(CornellDirect, SpotPoolOnFloorIsBrighterThanCeiling) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings();
    const HdrImage image = render(scene, settings);
    const float floorPool = luminance(radianceAt(scene, settings, image, {-0.6f, 0.0f, 0.45f}));
    const float ceiling = luminance(radianceAt(scene, settings, image, {0.0f, 2.0f, 0.0f}));
    // Analytic check of the units: E = I cosθ / d² at the floor point, L = albedo/π · E.
    const glm::vec3 toLight = glm::vec3(0.0f, 1.9f, 0.0f) - glm::vec3(-0.6f, 0.0f, 0.45f);
    const float d = glm::length(toLight);
    const float cosTheta = toLight.y / d;  // floor normal is +Y, and the spot axis is −Y: same angle
    const float expected = 0.73f / glm::pi<float>() * 20.0f * cosTheta / (d * d);  // inside the inner cone
    EXPECT_NEAR(floorPool, expected, 0.05f * expected) << "white floor under the spot";
    EXPECT_GT(floorPool, 20.0f * std::max(ceiling, 1e-3f)) << "floor " << floorPool << " ceiling " << ceiling;
}

TEST_F(CornellDirect, RedWallIsRedAndGreenWallIsGreen) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings();
    const HdrImage image = render(scene, settings);
    const glm::vec3 red = radianceAt(scene, settings, image, {-1.0f, 0.5f, 0.7f});
    const glm::vec3 green = radianceAt(scene, settings, image, {1.0f, 0.5f, 0.7f});
    EXPECT_GT(red.r, 0.05f);
    EXPECT_GT(red.r, 5.0f * red.g) << "left wall " << red.r << "," << red.g << "," << red.b;
    EXPECT_GT(green.g, 0.05f);
    EXPECT_GT(green.g, 2.0f * green.r) << "right wall " << green.r << "," << green.g << "," << green.b;
}

class CornellShadows : public GlFixture {
protected:
    float shadowRatio(const Scene& scene, const RenderSettings& settings, const HdrImage& image) const {
        const float shadowed = luminance(radianceAt(scene, settings, image, {-1.0f, 0.3f, -0.2f}, 1));
        const float lit = luminance(radianceAt(scene, settings, image, {-1.0f, 0.3f, 0.6f}, 1));
        return shadowed / std::max(lit, 1e-6f);
    }
};

TEST_F(CornellShadows, TallBoxShadowsTheRedWall) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings();
    const HdrImage image = render(scene, settings);
    EXPECT_LT(shadowRatio(scene, settings, image), 0.2f);
}

TEST_F(CornellShadows, ShadowTestFailsWithShadowsDisabled) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = smallSettings();
    settings.shadows.enabled = false;
    const HdrImage image = render(scene, settings);
    // Without shadow maps the same point is lit: the check above would fail.
    EXPECT_GT(shadowRatio(scene, settings, image), 0.5f);
}

TEST_F(CornellShadows, LitBoxTopIsBrighterThanItsShadowSide) {
    // The short box: its top faces the light; its front (+Z-ish) face turns away from it.
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings();
    const HdrImage image = render(scene, settings);
    const float top = luminance(radianceAt(scene, settings, image, {0.35f, 0.6f, 0.35f}, 1));
    const float front = luminance(radianceAt(scene, settings, image, {0.45f, 0.3f, 0.67f}, 1));
    EXPECT_GT(top, 0.5f);
    EXPECT_LT(front, 0.05f * top) << "top " << top << " front " << front;
}

TEST_F(CornellShadows, NoShadowAcneOnDirectlyLitFloor) {
    // Acne shows as speckle: neighbouring floor pixels under the spot must vary smoothly.
    const Scene scene = loadCornellBox();
    RenderSettings settings = smallSettings(256);
    const HdrImage image = render(scene, settings);
    const glm::ivec2 c = projectToPixel(cameraFor(scene, settings), {-0.6f, 0.0f, 0.45f}, image.width, image.height);
    float worst = 0.0f;
    for (int y = c.y - 4; y <= c.y + 4; ++y)
        for (int x = c.x - 6; x < c.x + 6; ++x) {
            const float a = luminance(image.at(x, y)), b = luminance(image.at(x + 1, y));
            worst = std::max(worst, std::abs(a - b) / std::max(a, 1e-4f));
        }
    EXPECT_LT(worst, 0.05f) << "relative jump between neighbouring floor pixels";
}

}  // namespace
}  // namespace lit::test
