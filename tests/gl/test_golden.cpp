// Golden-image comparison of the Cornell box (direct light only), tone-mapped sRGB output.
//
// Two thresholds, as llvmpipe versions and CPUs can differ in the last bits of float math:
//  - mean absolute difference over all channels ≤ 1.0/255: catches a global change (exposure,
//    tone curve, a light's intensity) that would be invisible per pixel;
//  - at most 0.5% of pixels may differ by more than 16/255 in any channel: allows edge pixels
//    to flip while catching any visible local change (a missing shadow, a wrong material).
// Update the golden images after an intended change with tools/update-goldens.sh and look at
// them before committing (tests/golden/README.md).
#include "GlTestSupport.h"

#include "image/ImageIO.h"

#include <stb_image.h>

#include <cstdlib>

namespace lit::test {
namespace {

struct GoldenCase {
    const char* name;
    View view;
};

class Golden : public GlFixture, public ::testing::WithParamInterface<GoldenCase> {};

TEST_P(Golden, CornellBoxMatchesGoldenImage) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = smallSettings(128);
    settings.debug.view = GetParam().view;
    render(scene, settings);
    const std::vector<std::uint8_t> rendered = renderer_->readOutputRgba8();
    const std::filesystem::path golden = sourceDir() / "tests" / "golden" / (std::string(GetParam().name) + ".png");
    const std::filesystem::path actual = outputDir() / (std::string(GetParam().name) + ".actual.png");
    writePng(actual, settings.output.width, settings.output.height, rendered);

    if (const char* update = std::getenv("LIT_UPDATE_GOLDENS"); update && std::string(update) == "1") {
        writePng(golden, settings.output.width, settings.output.height, rendered);
        GTEST_SKIP() << "wrote " << golden;
    }
    int w = 0, h = 0, channels = 0;
    stbi_set_flip_vertically_on_load(1);  // our buffers are bottom-up, PNGs top-down
    std::unique_ptr<stbi_uc, void (*)(void*)> expected(stbi_load(golden.c_str(), &w, &h, &channels, 4), stbi_image_free);
    ASSERT_TRUE(expected) << "missing golden image " << golden << " (run tools/update-goldens.sh)";
    ASSERT_EQ(w, settings.output.width);
    ASSERT_EQ(h, settings.output.height);

    double sum = 0.0;
    int bad = 0;
    for (int i = 0; i < w * h; ++i) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(rendered[std::size_t(i) * 4 + c]) - int(expected.get()[i * 4 + c]));
            sum += d;
            worst = std::max(worst, d);
        }
        if (worst > 16) ++bad;
    }
    const double mean = sum / (3.0 * w * h);
    EXPECT_LE(mean, 1.0) << "mean abs difference (of 255); see " << actual;
    EXPECT_LE(bad, w * h / 200) << "pixels off by more than 16/255; see " << actual;
}

INSTANTIATE_TEST_SUITE_P(Views, Golden,
                         ::testing::Values(GoldenCase{"cornell_direct_final", View::Final},
                                           GoldenCase{"cornell_albedo", View::Albedo},
                                           GoldenCase{"cornell_normal", View::Normal}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace lit::test
