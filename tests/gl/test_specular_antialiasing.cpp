// Geometric specular anti-aliasing (specular_footprint.glsl) on the smooth clear coat of the
// material-layers scene (roughness 0.05, whose highlights are smaller than a pixel): the truth is
// the highlight's integral over the image, which the mean over a grid of sub-pixel image shifts of
// the unfiltered rasterizer gives (its BRDF at a point is the reference's: MaterialLayers). A
// highlight that a pixel centre catches or misses makes each shift's total jump; widened by its
// normal's footprint it keeps its total wherever the pixels fall. Flat surfaces are untouched.
#include <glm/gtc/matrix_transform.hpp>

#include "GlTestSupport.h"

namespace lit::test {
namespace {

constexpr int kWidth = 192, kHeight = 108;  // the Blender camera's 16:9

class SpecularAntialiasing : public GlFixture {
protected:
    static RenderSettings settingsFor(bool specularAntialiasing) {
        RenderSettings s = smallSettings();
        s.output.width = kWidth;
        s.output.height = kHeight;
        s.output.specularAntialiasing = specularAntialiasing;
        s.debug.view = View::DirectSpecular;
        return s;
    }

    // The pixels around the node named `name` (its first-hit box, grown by 3 pixels).
    struct Box {
        int x0, y0, x1, y1;
    };
    static Box boxAround(const Scene& scene, const CameraView& camera, const std::string& name, Log& log) {
        const reference::ReferenceScene rs(scene, log);
        const std::vector<reference::FirstHit> hits = reference::traceFirstHits(rs, camera, kWidth, kHeight);
        Box box{kWidth, kHeight, -1, -1};
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const int node = hits[static_cast<std::size_t>(y * kWidth + x)].node;
                if (node < 0 || scene.nodes[static_cast<std::size_t>(node)].name != name) continue;
                box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x), std::max(box.y1, y)};
            }
        return {std::max(box.x0 - 3, 0), std::max(box.y0 - 3, 0), std::min(box.x1 + 3, kWidth - 1),
                std::min(box.y1 + 3, kHeight - 1)};
    }

    // The sum of luminance over `box` with the image shifted by (dx, dy) pixels.
    double shiftedTotal(const Scene& scene, CameraView camera, const RenderSettings& settings, const Box& box, float dx,
                        float dy) {
        camera.projection = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f * dx / kWidth, 2.0f * dy / kHeight, 0.0f)) *
                            camera.projection;
        renderer_->render(scene, camera, settings);
        const std::vector<float> rgb = renderer_->readHdrRgb();
        double sum = 0.0;
        // readHdrRgb's rows run bottom-up, as traceFirstHits' do.
        for (int y = box.y0; y <= box.y1; ++y)
            for (int x = box.x0; x <= box.x1; ++x) {
                const std::size_t p = static_cast<std::size_t>(y * kWidth + x);
                sum += luminance({rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]});
            }
        return sum;
    }
};

TEST_F(SpecularAntialiasing, AHighlightKeepsItsTotalWhereverThePixelsFall) {
    const Scene scene =
        loadGltf(sourceDir() / "tests" / "data" / "blender" / "material_layers" / "material_layers.gltf", log_);
    const RenderSettings off = settingsFor(false), on = settingsFor(true);
    const CameraView camera = cameraFor(scene, off);
    const Box box = boxAround(scene, camera, "clearcoat", log_);
    ASSERT_GT(box.x1 - box.x0, 8) << "the clear-coated sphere must be in view";
    renderer_->setScene(scene);

    // The truth: the unfiltered highlight's mean over a 16 × 16 grid of shifts within a pixel.
    constexpr int kGrid = 16;
    double truth = 0.0;
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i)
            truth += shiftedTotal(scene, camera, off, box, (i + 0.5f) / kGrid - 0.5f, (j + 0.5f) / kGrid - 0.5f);
    truth /= kGrid * kGrid;
    ASSERT_GT(truth, 0.0);

    // Eight shifts, as the anti-aliasing cycle's offsets spread them.
    double worstOff = 0.0, worstOn = 0.0, meanOn = 0.0;
    constexpr int kShifts = 8;
    for (int k = 0; k < kShifts; ++k) {
        const float dx = (k + 0.5f) / kShifts - 0.5f, dy = std::fmod(0.37f + 0.618f * k, 1.0f) - 0.5f;
        const double withoutFootprint = shiftedTotal(scene, camera, off, box, dx, dy);
        const double withFootprint = shiftedTotal(scene, camera, on, box, dx, dy);
        std::printf("shift (%+.3f, %+.3f): unfiltered %.3f, widened %.3f (truth %.3f)\n", dx, dy, withoutFootprint,
                    withFootprint, truth);
        worstOff = std::max(worstOff, std::abs(withoutFootprint / truth - 1.0));
        worstOn = std::max(worstOn, std::abs(withFootprint / truth - 1.0));
        meanOn += withFootprint / kShifts;
    }
    RecordProperty("unfiltered_worst_percent", std::to_string(100.0 * worstOff));
    RecordProperty("widened_worst_percent", std::to_string(100.0 * worstOn));
    RecordProperty("widened_mean_ratio", std::to_string(meanOn / truth));
    // Unfiltered, a shift's total is the highlight caught or missed: far from the truth.
    EXPECT_GT(worstOff, 0.3) << "the highlight must be smaller than a pixel, or this proves nothing";
    // Widened, every shift's total holds the highlight's energy, and its mean is the truth.
    EXPECT_LT(worstOn, 0.15);
    EXPECT_NEAR(meanOn / truth, 1.0, 0.1);
}

TEST_F(SpecularAntialiasing, FlatSurfacesAreDrawnAsWithout) {
    // The Cornell box is all flat faces, and so are the layer-textures scene's planes, whose
    // normal maps (the base's, the coat's ridges) must not count as spread: their normals are
    // computed in branches, where the derivatives at triangle edges are undefined.
    const Scene cornell = loadCornellBox();
    const Scene planes =
        loadGltf(sourceDir() / "tests" / "data" / "blender" / "layer_textures" / "layer_textures.gltf", log_);
    for (const Scene* scene : {&cornell, &planes}) {
        RenderSettings off = smallSettings(160);
        off.output.height = 90;
        off.debug.view = View::DirectSpecular;
        RenderSettings on = off;
        on.output.specularAntialiasing = true;
        const HdrImage a = render(*scene, off), b = render(*scene, on);
        ASSERT_EQ(a.rgb.size(), b.rgb.size());
        EXPECT_EQ(a.rgb, b.rgb) << (scene == &cornell ? "cornell box" : "layer textures");
    }
}

}  // namespace
}  // namespace lit::test
