// Compressed glTF renders as the uncompressed file: the Blender point scene and its
// glTF-Transform `draco` and `meshopt` versions (tests/data/compressed, made by
// tools/make-compressed-scenes.sh) give the same image with Lit's default settings, GI included,
// within what the compressors' quantization moves (positions by up to 0.4 mm, normals by a few
// degrees).
#include <cmath>
#include <cstdio>

#include "GlTestSupport.h"

namespace lit::test {
namespace {

class CompressedScenesRender : public GlFixture, public ::testing::WithParamInterface<const char*> {};

TEST_P(CompressedScenesRender, LikeTheUncompressedFile) {
    const std::filesystem::path data = sourceDir() / "tests" / "data";
    const Scene plain = loadGltf(data / "blender" / "point.gltf", log_);
    const Scene compressed = loadGltf(data / "compressed" / GetParam(), log_);
    ASSERT_FALSE(compressed.decodedCompression.empty());
    RenderSettings settings;  // the defaults, GI on
    settings.output.width = 96;
    settings.output.height = 96;
    const HdrImage want = render(plain, settings);
    const HdrImage got = render(compressed, settings);
    ASSERT_EQ(want.rgb.size(), got.rgb.size());

    double meanWant = 0.0, meanGot = 0.0, meanDifference = 0.0;
    const std::size_t pixels = want.rgb.size() / 3;
    std::vector<double> differences(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const float a = luminance({want.rgb[3 * i], want.rgb[3 * i + 1], want.rgb[3 * i + 2]});
        const float b = luminance({got.rgb[3 * i], got.rgb[3 * i + 1], got.rgb[3 * i + 2]});
        meanWant += a;
        meanGot += b;
        differences[i] = std::abs(double(a) - double(b));
        meanDifference += differences[i];
    }
    meanWant /= double(pixels);
    meanGot /= double(pixels);
    meanDifference /= double(pixels);
    ASSERT_GT(meanWant, 0.0) << "the scene is lit";
    std::size_t far = 0;
    for (double d : differences) far += d > 0.25 * meanWant;
    std::printf(
        "%s: mean luminance %.5f vs %.5f (ratio %.4f), mean |difference| %.2f%% of the mean, %zu of %zu "
        "pixels differ by more than 25%% of the mean\n",
        GetParam(), meanGot, meanWant, meanGot / meanWant, 100.0 * meanDifference / meanWant, far, pixels);
    // Two bars: the whole image within 1 % of the mean (the geometry is the same within 0.4 mm
    // and the lighting the same), and at most 1 % of the pixels (92 of 9 216) far off, for the
    // silhouette pixels a sub-millimetre shift of an edge may flip. Measured on llvmpipe: Draco
    // ratio 1.0000, mean difference 0.01 %; meshopt 1.0002, 0.05 %; no pixel far off in either.
    EXPECT_NEAR(meanGot / meanWant, 1.0, 0.01);
    EXPECT_LT(meanDifference, 0.01 * meanWant);
    EXPECT_LE(far, pixels / 100);
}

INSTANTIATE_TEST_SUITE_P(GltfTransform, CompressedScenesRender,
                         ::testing::Values("point_draco.glb", "point_meshopt.glb"), [](const auto& info) {
                             return std::string(info.param).substr(0, std::string(info.param).find('.'));
                         });

}  // namespace
}  // namespace lit::test
