// The camera's shadow cascades of a directional light (ShadowSettings::cascades; docs/ARCHITECTURE.md,
// "Shadow cascades") on the generated city (assets/gi/city.gltf, 640 m across): the direct light
// against the reference's shadow rays, and maps drawn again only when their fit moves.
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "GlTestSupport.h"
#include "reference/AccuracyRegions.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"

namespace lit::test {
namespace {

class ShadowCascadesGl : public GlFixture {
protected:
    Scene loadCity() { return loadGltf(sourceDir() / "assets" / "gi" / "city.gltf", log_); }
};

// The share of the surface pixels whose direct diffuse light is off the reference's (exact shadow
// rays, sampled at the pixel centres as the rasterizer samples) by more than a quarter of the
// sunlit mean: pixels on the wrong side of a shadow's edge.
double wrongSideShare(const std::vector<float>& raster, const std::vector<float>& truth,
                      const reference::PixelMask& surfaces) {
    double sunlit = 0.0;
    std::size_t sunlitCount = 0, wrong = 0, counted = 0;
    const auto lum = [](const std::vector<float>& rgb, std::size_t i) {
        return luminance({rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]});
    };
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        if (surfaces[i] && lum(truth, i) > 0.0f) {
            sunlit += lum(truth, i);
            ++sunlitCount;
        }
    const double threshold = 0.25 * sunlit / static_cast<double>(std::max<std::size_t>(sunlitCount, 1));
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        if (!surfaces[i]) continue;
        ++counted;
        if (std::abs(lum(raster, i) - lum(truth, i)) > threshold) ++wrong;
    }
    return counted ? static_cast<double>(wrong) / static_cast<double>(counted) : 1.0;
}

// One map over the city has texels of about 0.7 m, and its normal offset and filter darken sunlit
// faces a metre or more from a shadow's edge: 0.73 % of the street view's pixels are on the wrong
// side of an edge (by more than a quarter of the sunlit mean) at 1024², none with the default four
// cascades, whose first map has texels of a few centimetres. Bar: at most 0.2 % with cascades and
// at most a quarter of the single map's share. ~1 s.
TEST_F(ShadowCascadesGl, CityStreetDirectLightMatchesTheReferencesShadowRays) {
    const Scene scene = loadCity();
    RenderSettings settings = smallSettings(128);
    settings.debug.view = View::DirectDiffuse;
    ASSERT_EQ(settings.shadows.cascades, 4) << "the default";
    const CameraView camera = cameraFor(scene, settings);
    Log quiet;
    quiet.setSink(nullptr);
    const reference::ReferenceScene rs(scene, quiet);
    const std::vector<reference::FirstHit> hits = reference::traceFirstHits(rs, camera, 128, 128);
    const reference::PixelMask surfaces = reference::erodeEdges(reference::surfaceMask(hits), hits, 128, 128, 1);
    const std::vector<float> truth =
        tracedAtPixelCentres(rs, camera, 128, 128, 1, 4).viewRgb(View::DirectDiffuse, settings);

    const double cascaded = wrongSideShare(render(scene, settings).rgb, truth, surfaces);
    settings.shadows.cascades = 0;
    const double single = wrongSideShare(render(scene, settings).rgb, truth, surfaces);
    std::printf(
        "city street, direct diffuse against the reference's shadow rays: %.2f %% of the pixels on the wrong side "
        "of an edge with four cascades, %.2f %% with one map over the scene\n",
        100.0 * cascaded, 100.0 * single);
    EXPECT_LE(cascaded, 0.002);
    EXPECT_LE(cascaded, 0.25 * single);
}

// A cascade is drawn again only when its snapped fit moves, and at most one a frame: a step of
// 1 cm draws none, a step of 30 m along the street draws the moved maps over as many frames.
TEST_F(ShadowCascadesGl, CascadesAreDrawnAgainOnlyWhenTheirFitMoves) {
    const Scene scene = loadCity();
    const RenderSettings settings = smallSettings(64);
    renderer_->setScene(scene);
    CameraView camera = cameraFor(scene, settings);
    const auto renderFrom = [&](const glm::vec3& offset) {
        CameraView moved = camera;
        moved.position += offset;
        moved.view = glm::translate(camera.view, -offset);
        renderer_->render(scene, moved, settings);
        return renderer_->stats().shadowCascadesDrawn;
    };
    EXPECT_EQ(renderFrom(glm::vec3(0.0f)), 4) << "the first frame draws every cascade";
    EXPECT_EQ(renderFrom(glm::vec3(0.0f)), 0) << "a still camera draws none";
    EXPECT_EQ(renderFrom(glm::vec3(0.01f, 0.0f, 0.0f)), 0) << "a step far below a snap step draws none";
    // A move that shifts several maps draws one a frame, the finest first, until every map holds
    // its fit.
    const glm::vec3 step = camera.forward() * 30.0f;
    EXPECT_EQ(renderFrom(step), 1);
    int frames = 1;
    while (renderFrom(step) == 1) ++frames;
    EXPECT_EQ(renderFrom(step), 0);
    EXPECT_GE(frames, 2) << "a 30 m step moves more than the first map";
    EXPECT_LE(frames, 4);
    RenderSettings fewer = settings;
    fewer.shadows.cascades = 2;
    renderer_->render(scene, camera, fewer);
    EXPECT_GE(renderer_->stats().shadowCascadesDrawn, 1) << "a new cascade count fits the maps anew";
}

}  // namespace
}  // namespace lit::test
