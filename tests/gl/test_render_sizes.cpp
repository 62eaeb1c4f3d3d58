// Render-size changes (the editor's interactive render scale switches between the full size when
// still and a smaller one while moving): the G-buffer, lighting-term and post targets of the
// previous size are kept as a spare and reused when that size comes back (TargetsBySize). An image
// rendered after a switch back must be exactly the image a renderer that never changed size
// renders, including the indirect terms (reduced-resolution trace and resolve) and a data view.
// Cost: about 3 s on llvmpipe (2 cores): two renderers, 96² and 64², 64³ voxels.
#include "GlTestSupport.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lit::test {
namespace {

class RenderSizes : public GlFixture {
protected:
    static constexpr int kFull = 96, kSmall = 64;

    static RenderSettings settingsAt(int size, View view) {
        RenderSettings s;
        s.output.width = s.output.height = size;
        s.gi.voxelResolution = 64;
        s.gi.enabled = true;  // indirect scale 2 (the default): trace, resolve and fallback run
        s.debug.view = view;
        return s;
    }
    static CameraView insideTheBox() {
        const glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.95f));
        return makeCameraView(world, glm::radians(70.0f), 1.0f, 0.05f, 20.0f);
    }
    // The HDR image and the tone-mapped output, as floats one after the other.
    std::vector<float> renderAt(Renderer& renderer, const Scene& scene, int size, View view) {
        renderer.render(scene, insideTheBox(), settingsAt(size, view));
        std::vector<float> image = renderer.readHdrRgb();
        for (std::uint8_t v : renderer.readOutputRgba8()) image.push_back(static_cast<float>(v));
        return image;
    }
};

TEST_F(RenderSizes, SwitchingBackToASizeGivesTheSameImage) {
    if (HasFatalFailure()) return;
    const Scene scene = loadCornellBox();

    Renderer fresh(sourceDir() / "shaders", log_);
    fresh.setScene(scene);
    const std::vector<float> finalImage = renderAt(fresh, scene, kFull, View::Final);
    const std::vector<float> albedoImage = renderAt(fresh, scene, kFull, View::Albedo);

    renderer_->setScene(scene);
    const std::vector<float> first = renderAt(*renderer_, scene, kFull, View::Final);
    const std::vector<float> small = renderAt(*renderer_, scene, kSmall, View::Final);  // full size → spare
    ASSERT_EQ(small.size(), static_cast<std::size_t>(kSmall * kSmall * (3 + 4)));
    const std::vector<float> back = renderAt(*renderer_, scene, kFull, View::Final);   // spare reused
    const std::vector<float> smallAgain = renderAt(*renderer_, scene, kSmall, View::Final);
    const std::vector<float> backAlbedo = renderAt(*renderer_, scene, kFull, View::Albedo);

    ASSERT_EQ(first.size(), static_cast<std::size_t>(kFull * kFull * (3 + 4)));
    EXPECT_EQ(first, finalImage);
    EXPECT_EQ(back, finalImage) << "the image after switching back to the first size differs";
    EXPECT_EQ(smallAgain, small);
    EXPECT_EQ(backAlbedo, albedoImage);
    // Not trivially equal: the image has light in it.
    double sum = 0.0;
    for (float v : back) sum += v;
    EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace lit::test
