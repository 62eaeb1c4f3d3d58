// Voxel debug views (VoxelDebugPass) on the Cornell box at 64³: the slice view shows the walls
// where they are, with their colours on the correct sides; channels, axes and mips each change
// the image; a coarser mip is a blurred finer one; the grid appears once voxels are ≥ 4 px.
#include <algorithm>
#include <cmath>

#include "GlTestSupport.h"
#include "gi/VoxelVolume.h"
#include "passes/VoxelDebugPass.h"

namespace lit::test {
namespace {

class VoxelViewTest : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        scene_ = loadCornellBox();
        renderer_->setScene(scene_);
    }

    // Z slice through the middle of the box, albedo, mip 0, GI on (the views need the volume).
    static RenderSettings sliceSettings(int size = 128) {
        RenderSettings s = smallSettings(size);
        s.gi.enabled = true;
        s.debug.view = View::VoxelSlice;
        s.debug.voxelSliceAxis = 2;
        s.debug.voxelSlice = 0.5f;
        s.debug.voxelMip = 0;
        s.debug.voxelChannel = VoxelChannel::Albedo;
        return s;
    }

    HdrImage draw(const RenderSettings& settings) {
        renderer_->render(scene_, cameraFor(scene_, settings), settings);
        return HdrImage{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    }

    // Pixel rectangle of a Z slice (square image) covering world x ∈ [x0, x1], y ∈ [y0, y1].
    struct Rect {
        int x0, y0, x1, y1;  // bottom-up, inclusive-exclusive
    };
    Rect worldRect(const HdrImage& image, float x0, float y0, float x1, float y1) const {
        const VoxelVolume* volume = renderer_->voxels();
        const glm::vec3 min = volume->minCorner();
        const float side = volume->side();
        auto px = [&](float v, float lo, int size) {
            return std::clamp(static_cast<int>(std::lround((v - lo) / side * static_cast<float>(size))), 0, size);
        };
        return {px(x0, min.x, image.width), px(y0, min.y, image.height), px(x1, min.x, image.width),
                px(y1, min.y, image.height)};
    }

    static glm::vec3 rectMean(const HdrImage& image, const Rect& r) {
        glm::dvec3 sum(0.0);
        int count = 0;
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) {
                sum += glm::dvec3(image.at(x, y));
                ++count;
            }
        return count ? glm::vec3(sum / double(count)) : glm::vec3(0.0f);
    }
    static float rectMax(const HdrImage& image, const Rect& r) {
        float m = 0.0f;
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) {
                const glm::vec3 c = image.at(x, y);
                m = std::max({m, c.r, c.g, c.b});
            }
        return m;
    }
    static double meanAbsDifference(const HdrImage& a, const HdrImage& b) {
        double sum = 0.0;
        for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(double(a.rgb[i]) - double(b.rgb[i]));
        return sum / double(a.rgb.size());
    }
    static double meanOf(const HdrImage& image) {
        double sum = 0.0;
        for (float v : image.rgb) sum += v;
        return sum / double(image.rgb.size());
    }
    // Mean colour of the pixels that show an occupied voxel (non-black).
    static glm::vec3 occupiedMean(const HdrImage& image) {
        glm::dvec3 sum(0.0);
        int count = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                if (image.at(x, y) != glm::vec3(0.0f)) {
                    sum += glm::dvec3(image.at(x, y));
                    ++count;
                }
        return count ? glm::vec3(sum / double(count)) : glm::vec3(0.0f);
    }
    static int nonZeroPixels(const HdrImage& image) {
        int count = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) count += image.at(x, y) != glm::vec3(0.0f);
        return count;
    }

    Scene scene_;
};

TEST_F(VoxelViewTest, MiddleZSliceShowsRedWallLeftAndGreenWallRight) {
    const HdrImage image = draw(sliceSettings());
    ASSERT_NE(renderer_->voxels(), nullptr);
    // Strips around the side walls (x = ∓1) at mid height, a few voxels wide.
    const glm::vec3 left = rectMean(image, worldRect(image, -1.08f, 0.5f, -0.92f, 1.5f));
    const glm::vec3 right = rectMean(image, worldRect(image, 0.92f, 0.5f, 1.08f, 1.5f));
    EXPECT_GT(left.r, 0.05f);
    EXPECT_GT(left.r, 3.0f * left.g) << "left wall should be red";
    EXPECT_GT(left.r, 3.0f * left.b);
    EXPECT_GT(right.g, 0.05f);
    EXPECT_GT(right.g, 2.0f * right.r) << "right wall should be green";
    EXPECT_GT(right.g, 2.0f * right.b);
    // The floor and ceiling in between are white (grey 0.73).
    const glm::vec3 floor = rectMean(image, worldRect(image, -0.2f, -0.04f, 0.2f, 0.04f));
    EXPECT_GT(floor.r, 0.05f);
    EXPECT_NEAR(floor.r, floor.g, 0.02f);
    EXPECT_NEAR(floor.g, floor.b, 0.02f);
}

TEST_F(VoxelViewTest, OpacityIsSetOnWallsAndZeroInsideTheEmptyRoom) {
    RenderSettings s = sliceSettings();
    s.debug.voxelChannel = VoxelChannel::Opacity;
    const HdrImage image = draw(s);
    const glm::vec3 left = rectMean(image, worldRect(image, -1.08f, 0.5f, -0.92f, 1.5f));
    const glm::vec3 ceiling = rectMean(image, worldRect(image, -0.5f, 1.92f, 0.5f, 2.08f));
    EXPECT_GT(left.r, 0.2f);
    EXPECT_GT(ceiling.r, 0.2f);
    EXPECT_EQ(left.r, left.g) << "opacity is grey";
    EXPECT_EQ(rectMax(image, worldRect(image, -0.4f, 1.4f, 0.4f, 1.75f)), 0.0f) << "the air in the room is empty";
}

TEST_F(VoxelViewTest, ChannelsAxesAndMipsChangeTheImage) {
    const RenderSettings base = sliceSettings(64);
    const HdrImage reference = draw(base);
    ASSERT_GT(meanOf(reference), 0.01);
    for (VoxelChannel channel : {VoxelChannel::Radiance, VoxelChannel::Normal, VoxelChannel::Opacity}) {
        RenderSettings s = base;
        s.debug.voxelChannel = channel;
        EXPECT_GT(meanAbsDifference(draw(s), reference), 0.01) << toString(channel);
    }
    for (int axis : {0, 1}) {
        RenderSettings s = base;
        s.debug.voxelSliceAxis = axis;
        EXPECT_GT(meanAbsDifference(draw(s), reference), 0.01) << "axis " << axis;
    }
    RenderSettings coarse = base;
    coarse.debug.voxelMip = 2;
    EXPECT_GT(meanAbsDifference(draw(coarse), reference), 0.01) << "mip 2";
    RenderSettings volume = base;
    volume.debug.view = View::Voxels;
    const HdrImage volumeImage = draw(volume);
    EXPECT_GT(meanAbsDifference(volumeImage, reference), 0.01) << "3D view";
    // Far past the last level the mip clamps instead of failing.
    RenderSettings beyond = base;
    beyond.debug.voxelMip = 99;
    EXPECT_EQ(VoxelDebugPass::mipLevel(beyond, *renderer_->voxels()), renderer_->voxels()->mipCount() - 1);
    EXPECT_GT(meanOf(draw(beyond)), 0.0);
}

TEST_F(VoxelViewTest, MipOneIsABlurredMipZero) {
    // Albedo: each level-1 voxel shows the mean colour of its occupied children (opacity is not
    // averaged but stacked, see mipmap.comp.glsl, so it is not the channel to compare means in).
    // 64 px: one pixel per voxel at mip 0, two at mip 1 (no grid in either).
    RenderSettings s = sliceSettings(64);
    const HdrImage mip0 = draw(s);
    s.debug.voxelMip = 1;
    const HdrImage mip1 = draw(s);
    const glm::vec3 mean0 = occupiedMean(mip0), mean1 = occupiedMean(mip1);
    ASSERT_GT(mean0.r, 0.05f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean1[c], mean0[c], 0.1f * mean0[c] + 0.01f) << "channel " << c;
    // Blurred: the walls spread over more pixels, and they are still where they were.
    EXPECT_GT(nonZeroPixels(mip1), nonZeroPixels(mip0));
    const glm::vec3 left = rectMean(mip1, worldRect(mip1, -1.1f, 0.5f, -0.9f, 1.5f));
    EXPECT_GT(left.r, 3.0f * left.g);
    EXPECT_EQ(rectMax(mip1, worldRect(mip1, -0.4f, 1.4f, 0.4f, 1.75f)), 0.0f);
}

TEST_F(VoxelViewTest, GridAppearsOnlyWhenVoxelsAreAtLeastFourPixels) {
    RenderSettings s = sliceSettings(64);
    s.debug.voxelChannel = VoxelChannel::Opacity;
    auto gridPixels = [&](const HdrImage& image) {
        // Inside the empty room every pixel is 0 except grid lines (mix(0, 0.5, 0.5) = 0.25).
        const Rect r = worldRect(image, -0.4f, 1.4f, 0.4f, 1.75f);
        int count = 0;
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) count += std::abs(image.at(x, y).r - 0.25f) < 1e-3f;
        return count;
    };
    EXPECT_EQ(gridPixels(draw(s)), 0) << "1 px per voxel: no grid";
    s.debug.voxelMip = 2;  // 16 voxels across 64 px: 4 px each
    EXPECT_GT(gridPixels(draw(s)), 10);
}

TEST_F(VoxelViewTest, VolumeViewShowsTheRedWallOnTheLeft) {
    RenderSettings s = sliceSettings(64);
    s.debug.view = View::Voxels;
    const HdrImage image = draw(s);
    // The camera looks down −Z into the box: the left wall fills the left edge of the picture.
    const glm::vec3 left = image.mean(0.0f, 0.3f, 0.08f, 0.7f);
    const glm::vec3 right = image.mean(0.92f, 0.3f, 1.0f, 0.7f);
    EXPECT_GT(left.r, 2.0f * left.g);
    EXPECT_GT(right.g, 1.5f * right.r);
    // Without GI there is no volume: black, not a failure.
    s.gi.enabled = false;
    EXPECT_EQ(meanOf(draw(s)), 0.0);
}

// The voxel views show no lighting term: they skip direct lighting and cone tracing, which the
// final view of the same renderer then runs.
TEST_F(VoxelViewTest, VoxelViewsSkipLightingAndConeTracing) {
    RenderSettings s = sliceSettings(64);
    for (const View view : {View::VoxelSlice, View::Voxels}) {
        s.debug.view = view;
        draw(s);
    }
    renderer_->profiler().flush();
    EXPECT_EQ(renderer_->profiler().lastRun("lighting"), nullptr);
    EXPECT_EQ(renderer_->profiler().lastRun("cone trace"), nullptr);
    s.debug.view = View::Final;
    draw(s);
    renderer_->profiler().flush();
    EXPECT_NE(renderer_->profiler().lastRun("lighting"), nullptr);
    EXPECT_NE(renderer_->profiler().lastRun("cone trace"), nullptr);
}

}  // namespace
}  // namespace lit::test
