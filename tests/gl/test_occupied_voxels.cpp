// The occupied-voxel list: VoxelizePass appends every voxel it occupies, InjectPass lights only
// those (indirect dispatch), and MipmapPass builds the mip chain over their parents only.
// Checked against the volume itself and the whole-grid passes on the Cornell box at 64³.
// Cost: about 3 s on llvmpipe, plus MipmapOverOccupiedParents (below).
#include <shared.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <set>
#include <string>
#include <tuple>

#include "GlTestSupport.h"
#include "gi/InjectPass.h"
#include "gi/MipmapPass.h"
#include "gi/VoxelRegions.h"
#include "gi/VoxelVolume.h"
#include "gi/VoxelizePass.h"
#include "gl/Objects.h"
#include "passes/LightSetup.h"
#include "passes/ShadowPass.h"
#include "scene/GpuScene.h"

namespace lit::test {
namespace {

// Injection over the occupied-voxel list, and over the whole grid.
lit::InjectOptions overList() { return {}; }
lit::InjectOptions wholeGrid() {
    lit::InjectOptions options;
    options.overList = false;
    return options;
}

class OccupiedVoxels : public ContextFixture {
protected:
    void SetUp() override {
        ContextFixture::SetUp();
        if (HasFatalFailure()) return;
        voxelize_ = std::make_unique<VoxelizePass>(sourceDir() / "shaders");
        inject_ = std::make_unique<InjectPass>(sourceDir() / "shaders");
        shadow_ = std::make_unique<ShadowPass>(sourceDir() / "shaders");
        mipmap_ = std::make_unique<MipmapPass>(sourceDir() / "shaders");
    }
    void TearDown() override {
        mipmap_.reset();
        shadow_.reset();
        inject_.reset();
        voxelize_.reset();
        volume_.reset();
        gpuScene_.reset();
        lightBuffer_ = {};
        frameBuffer_ = {};
        context_.reset();
    }

    void voxelize(const Scene& scene, int n, bool rgba8 = false) {
        gpuScene_ = std::make_unique<GpuScene>(scene, log_);
        volume_ = std::make_unique<VoxelVolume>();
        volume_->ensure(n, rgba8, log_);
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
        frame.exposure = glm::vec4(settings_.output.exposureScale(), settings_.shadows.pcfRadius, 0.0f, 0.0f);
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
    std::unique_ptr<MipmapPass> mipmap_;
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
    inject_->execute(*volume_, wholeGrid());
    const std::vector<glm::vec4> grid = readRadianceVoxels(*volume_);
    // Zero level 0 (as a voxelization does: the list writes occupied voxels only), so nothing of
    // the grid's result survives, then inject from the list.
    volume_->clearRadianceLevel0();
    inject_->execute(*volume_, overList());
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

// Voxelizing only the boxes a move changed (VoxelizePass::executeBoxes, VoxelChangeTracker) gives
// the material volumes of voxelizing the whole volume again, to the bit, and keeps the list: its
// entries before the move stay in place, the voxels new to it are appended once, and every voxel
// occupied now is listed exactly once (voxels the box left stay listed, empty). The tall box of the
// Cornell box moves 0.25 m along x and 0.15 m along z, at 64³; ~2 s.
TEST_F(OccupiedVoxels, VoxelizingTheChangedBoxesEqualsTheWholeVolume) {
    Scene scene = loadGltf(sourceDir() / "assets" / "cornell_box.gltf", log_);
    voxelize(scene, 64);
    const std::vector<glm::ivec3> listBefore = volume_->readOccupiedList();
    const VoxelPlacement placement = volume_->placement();
    VoxelChangeTracker tracker;
    tracker.voxelizedAll(itemPoses(scene, *gpuScene_), placement);
    bool moved = false;
    for (Node& node : scene.nodes)
        if (node.name == "tall_box") {
            node.translation += glm::vec3(0.25f, 0.0f, 0.15f);
            moved = true;
        }
    ASSERT_TRUE(moved);
    scene.updateWorldTransforms();
    const std::vector<ItemPose> items = itemPoses(scene, *gpuScene_);
    const auto boxes = tracker.voxelizeChanged(items, placement);
    ASSERT_TRUE(boxes) << "a moved box: its boxes only";
    std::int64_t boxVoxels = 0;
    for (const VoxelBox& box : *boxes) boxVoxels += box.voxels();
    DrawCounters counters;
    voxelize_->executeBoxes(scene, *gpuScene_, *volume_, *boxes, items, counters);
    std::vector<std::vector<std::uint32_t>> partial;
    for (const gl::Texture* t : {&volume_->albedo(), &volume_->normal(), &volume_->emission(), &volume_->surface()})
        partial.push_back(readMaterialVoxels(*t));
    const std::vector<glm::ivec3> listAfter = volume_->readOccupiedList();
    const std::vector<glm::ivec3> occupiedNow = occupiedVoxels(*volume_);

    VoxelVolume whole;
    whole.ensure(64, false, log_);
    whole.fitTo(scene.worldBounds());
    ASSERT_EQ(whole.minCorner(), volume_->minCorner()) << "the move must not change the volume's placement";
    whole.updateUniforms(settings_, 0);
    voxelize_->execute(scene, *gpuScene_, whole, counters);
    const char* names[] = {"albedo", "normal", "emission", "surface"};
    int volumeIndex = 0;
    for (const gl::Texture* t : {&whole.albedo(), &whole.normal(), &whole.emission(), &whole.surface()}) {
        const std::vector<std::uint32_t> expected = readMaterialVoxels(*t);
        const std::vector<std::uint32_t>& got = partial[static_cast<std::size_t>(volumeIndex)];
        ASSERT_EQ(got.size(), expected.size());
        std::size_t different = 0;
        for (std::size_t i = 0; i < got.size(); ++i) different += got[i] != expected[i];
        EXPECT_EQ(different, 0u) << names[volumeIndex] << " voxels differ from the whole volume's voxelization";
        ++volumeIndex;
    }
    std::printf("tall box moved at 64³: %zu changed boxes of %lld voxels (%.1f %% of the volume), list %zu → %zu entries\n",
                boxes->size(), static_cast<long long>(boxVoxels), 100.0 * static_cast<double>(boxVoxels) / (64.0 * 64.0 * 64.0),
                listBefore.size(), listAfter.size());
    ASSERT_GE(listAfter.size(), listBefore.size());
    EXPECT_TRUE(std::equal(listBefore.begin(), listBefore.end(), listAfter.begin())) << "entries keep their places";
    std::vector<glm::ivec3> sorted = listAfter;
    std::sort(sorted.begin(), sorted.end(), less);
    EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "a voxel listed twice";
    for (const glm::ivec3& v : occupiedNow)
        EXPECT_TRUE(std::binary_search(sorted.begin(), sorted.end(), v, less)) << "an occupied voxel is not listed";
    EXPECT_GT(listAfter.size(), listBefore.size()) << "the box moved into voxels it did not occupy";
    EXPECT_LT(static_cast<double>(boxVoxels), 0.2 * 64.0 * 64.0 * 64.0);
}

// The bytes of every mip level ≥ 1 of the radiance volume and every level of the six
// directional chains, as stored (RGBA8 bytes or RGBA16F half floats): compared bit for bit.
struct MipBytes {
    std::vector<std::vector<std::uint8_t>> levels;  // radiance 1..mipCount−1, then directional X, Y, Z
    std::vector<std::string> names;
};

std::vector<std::uint8_t> textureBytes(const gl::Texture& t, int level, bool rgba8) {
    const int w = std::max(t.desc().width >> level, 1), h = std::max(t.desc().height >> level, 1),
              d = std::max(t.desc().depth >> level, 1);
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(w) * h * d * (rgba8 ? 4 : 8));
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(t.id(), level, GL_RGBA, rgba8 ? GL_UNSIGNED_BYTE : GL_HALF_FLOAT,
                      static_cast<GLsizei>(bytes.size()), bytes.data());
    return bytes;
}

MipBytes readMips(const VoxelVolume& volume) {
    MipBytes m;
    const bool rgba8 = volume.radianceRgba8();
    for (int level = 1; level < volume.mipCount(); ++level) {
        m.levels.push_back(textureBytes(volume.radiance(), level, rgba8));
        m.names.push_back("radiance level " + std::to_string(level));
    }
    for (int axis = 0; axis < LIT_VOXEL_AXIS_COUNT; ++axis)
        for (int level = 0; level < volume.directional(axis).desc().levels; ++level) {
            m.levels.push_back(textureBytes(volume.directional(axis), level, rgba8));
            m.names.push_back("directional axis " + std::to_string(axis) + " level " + std::to_string(level));
        }
    return m;
}

// "" when equal, else the first levels that differ and how many bytes.
std::string compareMips(const MipBytes& occupied, const MipBytes& grid) {
    std::string failures;
    for (std::size_t i = 0; i < grid.levels.size() && i < occupied.levels.size(); ++i) {
        std::size_t different = 0;
        for (std::size_t b = 0; b < grid.levels[i].size(); ++b) different += occupied.levels[i][b] != grid.levels[i][b];
        if (different) failures += grid.names[i] + ": " + std::to_string(different) + " bytes differ; ";
    }
    if (occupied.levels.size() != grid.levels.size()) failures += "level counts differ";
    return failures;
}

// Voxels whose alpha is non-zero in level `level` of the radiance volume (from its bytes).
std::size_t nonEmptyVoxels(const std::vector<std::uint8_t>& bytes, bool rgba8) {
    std::size_t count = 0;
    const std::size_t texel = rgba8 ? 4 : 8;
    for (std::size_t i = 0; i + texel <= bytes.size(); i += texel)
        count += rgba8 ? bytes[i + 3] != 0 : (bytes[i + 6] | bytes[i + 7]) != 0;
    return count;
}

// The mip chain built over the occupied parents only (MipmapPass::listOccupiedParents, then
// execute over the lists) is the whole-grid chain to the bit, isotropic and directional, in both
// radiance formats; also after the tall box moved and the volume was voxelized again, when voxels
// the box left are empty and their parents must not keep the old values (VoxelizePass clears the
// chain; the directional chains are zeroed before their first build after it). Each level's list
// is checked against the parents of the occupied-voxel list computed on the CPU. The volume is
// lit (injection over the list), so the values are real radiance with partial opacities.
// Cost: about 4 s per format on llvmpipe (two voxelizations at 64³, four chains with directional).
class MipmapOverOccupiedParents : public OccupiedVoxels, public ::testing::WithParamInterface<bool> {};

TEST_P(MipmapOverOccupiedParents, EqualsTheWholeGridChainAlsoAfterAnObjectMoved) {
    const bool rgba8 = GetParam();
    Scene scene = loadGltf(sourceDir() / "assets" / "cornell_box.gltf", log_);
    std::size_t tallBox = scene.nodes.size();
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].name == "tall_box") tallBox = i;
    ASSERT_LT(tallBox, scene.nodes.size());
    constexpr int kResolution = 64;

    std::vector<std::uint8_t> level1BeforeMove;
    for (int pass = 0; pass < 2; ++pass) {
        SCOPED_TRACE(pass == 0 ? "first voxelization" : "after the tall box moved");
        if (pass == 0) {
            voxelize(scene, kResolution, rgba8);
        } else {
            // Move the box 0.4 m sideways (13 voxels at 64³ over the 2 m box) and voxelize the same
            // volume again, as the Renderer does after a transform edit.
            scene.nodes[tallBox].translation.x += 0.4f;
            scene.updateWorldTransforms();
            ++scene.geometryRevision;
            DrawCounters counters;
            voxelize_->execute(scene, *gpuScene_, *volume_, counters);
        }
        ASSERT_LE(volume_->readOccupiedCount(), volume_->occupiedCapacity());
        bindLights(scene);
        inject_->execute(*volume_, overList());
        mipmap_->listOccupiedParents(*volume_);
        ASSERT_TRUE(volume_->parentListsValid());

        // Each level's list: exactly the parents of the occupied voxels, each once.
        const std::vector<glm::ivec3> occupied = volume_->readOccupiedList();
        for (int level = 1; level < volume_->mipCount(); ++level) {
            std::set<std::tuple<int, int, int>> expected;
            for (const glm::ivec3& v : occupied) expected.emplace(v.x >> level, v.y >> level, v.z >> level);
            const std::vector<glm::ivec3> listed = volume_->readParentList(level);
            std::set<std::tuple<int, int, int>> got;
            for (const glm::ivec3& p : listed) got.emplace(p.x, p.y, p.z);
            EXPECT_EQ(listed.size(), got.size()) << "level " << level << " lists a parent twice";
            EXPECT_TRUE(got == expected) << "level " << level << ": " << got.size() << " listed, " << expected.size()
                                         << " expected";
            if (level == 1)
                std::printf("%s, %s: %zu occupied voxels, %zu of %d level-1 voxels listed (%.1f %%)\n",
                            rgba8 ? "RGBA8" : "RGBA16F", pass == 0 ? "first voxelization" : "box moved",
                            occupied.size(), listed.size(), (kResolution / 2) * (kResolution / 2) * (kResolution / 2),
                            100.0 * static_cast<double>(listed.size()) / ((kResolution / 2) * (kResolution / 2) * (kResolution / 2)));
        }

        mipmap_->execute(*volume_, true, true);
        const MipBytes overParents = readMips(*volume_);
        mipmap_->execute(*volume_, true, false);
        const MipBytes wholeGrid = readMips(*volume_);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        const std::string failures = compareMips(overParents, wholeGrid);
        EXPECT_TRUE(failures.empty()) << failures;
        // Not a chain of zeros: the walls and boxes are there at every level.
        EXPECT_GT(nonEmptyVoxels(wholeGrid.levels[0], rgba8), 5000u);

        if (pass == 0) {
            level1BeforeMove = wholeGrid.levels[0];
        } else {
            // The move emptied level-1 voxels that were occupied before: the case a chain built
            // over the new parents alone would leave stale.
            std::size_t emptied = 0;
            const std::size_t texel = rgba8 ? 4 : 8;
            const std::vector<std::uint8_t>& now = wholeGrid.levels[0];
            for (std::size_t i = 0; i + texel <= now.size(); i += texel) {
                const bool before = rgba8 ? level1BeforeMove[i + 3] != 0
                                          : (level1BeforeMove[i + 6] | level1BeforeMove[i + 7]) != 0;
                const bool after = rgba8 ? now[i + 3] != 0 : (now[i + 6] | now[i + 7]) != 0;
                emptied += before && !after;
            }
            EXPECT_GT(emptied, 100u) << "the move should empty some level-1 voxels";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, MipmapOverOccupiedParents, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "Rgba8" : "Rgba16f"; });

}  // namespace
}  // namespace lit::test
