// Rendering along a camera path (renderer/animation/CameraPath.h) headless: a 3-key path over the
// Cornell box, frame by frame. Consecutive frames must differ a little (the camera moves) and
// never a lot (no jumps).

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "GlTestSupport.h"
#include "animation/CameraPath.h"
#include "image/ImageIO.h"

namespace lit::test {
namespace {

// Camera-to-world rotation of a camera at `eye` looking at `target` (+Y up).
glm::quat lookAt(const glm::vec3& eye, const glm::vec3& target) {
    return glm::quat_cast(glm::inverse(glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f))));
}

// Mean absolute difference of two RGBA8 images over RGB, in 8-bit levels, comparing pixel
// (x, y) of `a` with pixel (x + shift, y) of `b` over the columns both have.
double meanAbsDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int width, int height,
                         int shift = 0) {
    double sum = 0.0;
    std::size_t count = 0;
    for (int y = 0; y < height; ++y)
        for (int x = std::max(0, -shift); x < std::min(width, width - shift); ++x)
            for (int c = 0; c < 3; ++c) {
                const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4 + c;
                const std::size_t j = (static_cast<std::size_t>(y) * width + x + shift) * 4 + c;
                sum += std::abs(int(a[i]) - int(b[j]));
                ++count;
            }
    return count ? sum / double(count) : 0.0;
}

class PathRender : public GlFixture {};

TEST_F(PathRender, ConsecutiveFramesDifferALittleNeverALot) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = smallSettings(64);  // GI off: direct light and shadows only
    renderer_->setScene(scene);

    // Three keys sweeping 1 m across the open side in 2 s, always looking at the box's centre.
    const glm::vec3 centre(0.0f, 1.0f, 0.0f);
    const std::vector<glm::vec3> eyes = {{-0.5f, 1.1f, 3.6f}, {0.0f, 1.0f, 3.4f}, {0.5f, 0.9f, 3.6f}};
    std::vector<CameraKey> keys;
    for (std::size_t i = 0; i < eyes.size(); ++i) keys.push_back({float(i), eyes[i], lookAt(eyes[i], centre), 0.69f});
    const CameraPath path(keys);

    const double fps = 15.0;
    const std::vector<double> times = path.frameTimes(fps);
    ASSERT_EQ(times.size(), 31u);
    const float aspect = 1.0f;
    const Aabb bounds = scene.worldBounds();
    std::vector<std::vector<std::uint8_t>> frames;
    for (const double t : times) {
        renderer_->render(scene, *path.view(t, aspect, bounds), settings);
        frames.push_back(renderer_->readOutputRgba8());
    }
    const int w = settings.output.width, h = settings.output.height;
    writePng(outputDir() / "path_first.png", w, h, frames.front());
    writePng(outputDir() / "path_last.png", w, h, frames.back());

    // The threshold comes from the picture itself. The camera glides ~0.035 m a frame while
    // turning to keep the box centred: at ~3.5 m, with 0.69 rad over 64 px, that moves the image
    // by well under a pixel a frame. So a frame may differ from the one before by no more than the
    // first frame differs from itself shifted by one whole pixel (≈ 7.6 levels here; the steps
    // measure 0.5–2.8). Skipping ten frames' worth of path — a jump — differs by more (checked).
    const double threshold = meanAbsDifference(frames.front(), frames.front(), w, h, 1);
    const double jump = meanAbsDifference(frames.front(), frames[10], w, h);
    ASSERT_GT(threshold, 1.0) << "the first frame is nearly flat; the test would see nothing";
    EXPECT_GT(jump, threshold) << "ten frames apart look alike; the threshold would catch no jump";

    std::vector<double> steps;
    for (std::size_t i = 1; i < frames.size(); ++i) {
        const double d = meanAbsDifference(frames[i - 1], frames[i], w, h);
        steps.push_back(d);
        EXPECT_GT(d, 0.0) << "frames " << i - 1 << " and " << i << " are identical: the camera did not move";
        EXPECT_LT(d, threshold) << "frames " << i - 1 << " and " << i << " jump (threshold " << threshold << ")";
    }
    // An even glide: no step stands out from the rest. Edges snapping to pixels make even motion
    // give steps up to ~2.2× the median here; a skip of ten frames would be ≥ 4.8× it.
    std::vector<double> sorted = steps;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    EXPECT_LT(sorted.back(), 4.0 * median) << "largest step " << sorted.back() << ", median " << median;
    ::testing::Test::RecordProperty("threshold", std::to_string(threshold));
    ::testing::Test::RecordProperty("medianStep", std::to_string(median));
    ::testing::Test::RecordProperty("largestStep", std::to_string(sorted.back()));
    ::testing::Test::RecordProperty("tenFramesApart", std::to_string(jump));
}

}  // namespace
}  // namespace lit::test
