// The occupied-voxel list: VoxelizePass appends every voxel it occupies, InjectPass lights only
// those (indirect dispatch). Checked against the volume itself on the Cornell box at 64³.
// Cost: about 3 s on llvmpipe.
#include "GlTestSupport.h"

#include "gl/Objects.h"
#include "passes/InjectPass.h"
#include "passes/LightSetup.h"
#include "passes/ShadowPass.h"
#include "passes/VoxelVolume.h"
#include "passes/VoxelizePass.h"
#include "scene/GpuScene.h"

#include <shared.h>

#include <algorithm>
#include <cstdio>

namespace lit::test {
namespace {

class OccupiedVoxels : public ContextFixture {
protected:
    void SetUp() override {
        ContextFixture::SetUp();
        if (HasFatalFailure()) return;
        voxelize_ = std::make_unique<VoxelizePass>(sourceDir() / "shaders");
        inject_ = std::make_unique<InjectPass>(sourceDir() / "shaders");
        shadow_ = std::make_unique<ShadowPass>(sourceDir() / "shaders");
    }
    void TearDown() override {
        shadow_.reset();
        inject_.reset();
        voxelize_.reset();
        volume_.reset();
        gpuScene_.reset();
        lightBuffer_ = {};
        frameBuffer_ = {};
        context_.reset();
    }

    void voxelize(const Scene& scene, int n) {
        gpuScene_ = std::make_unique<GpuScene>(scene, log_);
        volume_ = std::make_unique<VoxelVolume>();
        volume_->ensure(n, false, log_);
        volume_->fitTo(scene.worldBounds());
        volume_->updateUniforms(settings_, 0);
        DrawCounters counters;
        voxelize_->execute(scene, *gpuScene_, *volume_, counters);
    }

    // Lights and shadow maps bound as the Renderer binds them (shadow maps rendered once).
    void bindLights(const Scene& scene) {
        const LightSetup lights = buildLightSetup(scene, scene.worldBounds(), settings_, log_);
        lightBuffer_ = gl::Buffer("lights", sizeof(gpu::GpuLight) * LIT_MAX_LIGHTS, nullptr, GL_DYNAMIC_STORAGE_BIT);
        if (!lights.lights.empty())
            lightBuffer_.update(0, lights.lights.size() * sizeof(gpu::GpuLight), lights.lights.data());
        gpu::FrameUniforms frame{};
        frame.exposure = glm::vec4(settings_.exposureScale(), settings_.shadowPcfRadius, 0.0f, 0.0f);
        frame.counts = glm::ivec4(static_cast<int>(lights.lights.size()), 0, 0, 0);
        frameBuffer_ = gl::Buffer("frame uniforms", sizeof frame, &frame, 0);
        DrawCounters counters;
        shadow_->execute(scene, *gpuScene_, lights, settings_, counters);
        frameBuffer_.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);
        lightBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_LIGHTS);
        shadow_->bindMaps();
        volume_->uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    }

    static bool less(const glm::ivec3& a, const glm::ivec3& b) {
        return a.z != b.z ? a.z < b.z : (a.y != b.y ? a.y < b.y : a.x < b.x);
    }

    Log log_;
    RenderSettings settings_;
    std::unique_ptr<VoxelizePass> voxelize_;
    std::unique_ptr<InjectPass> inject_;
    std::unique_ptr<ShadowPass> shadow_;
    std::unique_ptr<VoxelVolume> volume_;
    std::unique_ptr<GpuScene> gpuScene_;
    gl::Buffer lightBuffer_, frameBuffer_;
};

// The list holds each occupied voxel once: its count is the CPU count of voxels with a non-zero
// albedo sample count, and its coordinates are exactly those voxels.
TEST_F(OccupiedVoxels, ListEqualsTheVolumesOccupiedVoxels) {
    const Scene scene = loadGltf(sourceDir() / "assets" / "cornell_box.gltf", log_);
    voxelize(scene, 64);
    const std::uint32_t count = volume_->readOccupiedCount();
    std::vector<glm::ivec3> listed = volume_->readOccupiedList();
    const std::vector<glm::ivec3> expected = occupiedVoxels(*volume_);  // CPU scan, index order
    std::printf("Cornell box at 64³: %u occupied voxels listed, %zu counted on the CPU (%.2f %% of the grid)\n", count,
                expected.size(), 100.0 * count / (64.0 * 64.0 * 64.0));
    ASSERT_LE(count, volume_->occupiedCapacity());
    EXPECT_EQ(count, expected.size());
    EXPECT_EQ(count, countOccupiedVoxels(*volume_));
    std::sort(listed.begin(), listed.end(), less);
    EXPECT_TRUE(listed == expected) << "the list should hold every occupied voxel exactly once";
    // Five 2 m walls of 64-voxel-wide volume cross at least 5 · (60 × 60) voxels: not a trivial list.
    EXPECT_GT(count, 5u * 60u * 60u);
}

// Injecting over the list gives the same radiance volume as injecting over the whole grid.
TEST_F(OccupiedVoxels, InjectionOverTheListEqualsTheWholeGrid) {
    const Scene scene = loadGltf(sourceDir() / "assets" / "cornell_box.gltf", log_);
    voxelize(scene, 64);
    bindLights(scene);
    inject_->execute(*volume_, false);
    const std::vector<glm::vec4> grid = readRadianceVoxels(*volume_);
    // Zero level 0 (as a voxelization does: the list writes occupied voxels only), so nothing of
    // the grid's result survives, then inject from the list.
    volume_->clearRadianceLevel0();
    inject_->execute(*volume_, true);
    const std::vector<glm::vec4> listed = readRadianceVoxels(*volume_);
    ASSERT_EQ(grid.size(), listed.size());
    std::size_t lit = 0, different = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        if (grid[i].a > 0.0f) ++lit;
        if (grid[i] != listed[i]) ++different;
    }
    EXPECT_GT(lit, 10000u);
    EXPECT_EQ(different, 0u);
}

}  // namespace
}  // namespace lit::test
