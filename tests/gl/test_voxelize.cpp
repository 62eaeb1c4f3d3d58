// Voxelization and radiance injection on scenes built in code, where the answer is known:
// which voxels a box's surface occupies, that a tilted thin wall leaves no holes, that the
// running average mixes coincident surfaces, and the radiance a lit floor and an emitter inject.
#include <shared.h>

#include <array>
#include <chrono>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <iostream>

#include "GlTestSupport.h"
#include "gi/InjectPass.h"
#include "gi/SolidVoxelsPass.h"
#include "gi/VoxelVolume.h"
#include "gi/VoxelizePass.h"
#include "gl/Objects.h"
#include "passes/LightSetup.h"
#include "passes/ShadowPass.h"
#include "scene/GpuScene.h"
#include "scene/SceneBuilder.h"
#include "scene/SpecularMeanAlbedo.h"

namespace lit::test {
namespace {

// Builds the voxel passes directly (no Renderer) and runs them the way the Renderer does.
class VoxelFixture : public ContextFixture {
protected:
    void SetUp() override {
        ContextFixture::SetUp();
        if (HasFatalFailure()) return;
        voxelize_ = std::make_unique<VoxelizePass>(sourceDir() / "shaders");
        inject_ = std::make_unique<InjectPass>(sourceDir() / "shaders");
    }

    // Uploads `scene`, fits an n³ volume around it and voxelizes it.
    void voxelize(const Scene& scene, int n, const RenderSettings& settings = {}) {
        gpuScene_ = std::make_unique<GpuScene>(scene, log_);
        volume_ = std::make_unique<VoxelVolume>();
        volume_->ensure(n, settings.gi.radianceRgba8, log_);
        volume_->fitTo(scene.worldBounds());
        volume_->updateUniforms(settings, 0);
        DrawCounters counters;
        voxelize_->execute(scene, *gpuScene_, *volume_, counters);
    }

    // Lights, shadow maps and the frame UBO as the Renderer binds them, then injection.
    void inject(const Scene& scene, const RenderSettings& settings = {}) {
        const LightSetup lights = buildLightSetup(scene, scene.worldBounds(), settings, log_);
        lightBuffer_ = gl::Buffer("lights", sizeof(gpu::GpuLight) * LIT_MAX_LIGHTS, nullptr, GL_DYNAMIC_STORAGE_BIT);
        if (!lights.lights.empty())
            lightBuffer_.update(0, lights.lights.size() * sizeof(gpu::GpuLight), lights.lights.data());
        gpu::FrameUniforms frame{};
        frame.exposure = glm::vec4(settings.output.exposureScale(), settings.shadows.pcfRadius, 0.0f, 0.0f);
        frame.counts = glm::ivec4(static_cast<int>(lights.lights.size()), 0, 0, 0);
        frameBuffer_ = gl::Buffer("frame uniforms", sizeof frame, &frame, 0);
        shadow_ = std::make_unique<ShadowPass>(sourceDir() / "shaders");
        DrawCounters counters;
        shadow_->execute(scene, *gpuScene_, lights, settings, counters);

        frameBuffer_.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);
        lightBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_LIGHTS);
        shadow_->bindMaps();
        inject_->execute(*volume_);
    }

    int n() const { return volume_->resolution(); }
    float voxelSize() const { return volume_->voxelSize(); }
    std::size_t index(const glm::ivec3& v) const {
        return static_cast<std::size_t>(v.x) + static_cast<std::size_t>(n()) * (v.y + static_cast<std::size_t>(n()) * v.z);
    }
    glm::vec3 centre(const glm::ivec3& v) const { return volume_->minCorner() + (glm::vec3(v) + 0.5f) * voxelSize(); }
    // World point → continuous voxel coordinates (voxel i spans [i, i+1)).
    glm::vec3 toVoxels(const glm::vec3& p) const { return (p - volume_->minCorner()) / voxelSize(); }

    Log log_;
    std::unique_ptr<VoxelizePass> voxelize_;
    std::unique_ptr<InjectPass> inject_;
    std::unique_ptr<ShadowPass> shadow_;
    std::unique_ptr<GpuScene> gpuScene_;
    std::unique_ptr<VoxelVolume> volume_;
    gl::Buffer lightBuffer_, frameBuffer_;
};

// One fixture, two suites: voxelization alone, and voxelization followed by injection.
using Voxelize = VoxelFixture;
using VoxelInject = VoxelFixture;

// Distance from `p` to the surface of the axis-aligned box [lo, hi].
float distanceToBoxSurface(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 outside = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
    if (glm::length(outside) > 0.0f) return glm::length(outside);
    const glm::vec3 inside = glm::min(p - lo, hi - p);
    return std::min({inside.x, inside.y, inside.z});
}

float fraction(float x) { return x - std::floor(x); }

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// ---- Box: the occupied voxels are exactly the shell of voxels its faces pass through -----------

TEST_F(Voxelize, BoxBecomesItsSurfaceShell) {
    // A 4 m floor fixes the volume (4 m + padding → 4·64/60 m at 64³, 1/15 m voxels); the 1 m box
    // floats above it, its faces at fractional voxel positions so the expected shell is unambiguous
    // (z −0.10, not −0.12 as before the grid's ¼-voxel shift in y and z, which put its −z face 0.05
    // voxel from a voxel face).
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f));
    addMeshNode(scene, makePlaneMesh("floor", 4.0f, white), glm::vec3(0.0f));
    const glm::vec3 boxCentre{0.21f, 1.13f, -0.10f};
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), white), boxCentre);
    voxelize(scene, 64);
    ASSERT_EQ(n(), 64);
    ASSERT_NEAR(voxelSize(), 4.0f / 60.0f, 1e-5f);

    const glm::vec3 boxLo = boxCentre - 0.5f, boxHi = boxCentre + 0.5f;
    const glm::vec3 a0 = toVoxels(boxLo), a1 = toVoxels(boxHi);
    for (int axis = 0; axis < 3; ++axis) {
        ASSERT_TRUE(fraction(a0[axis]) > 0.1f && fraction(a0[axis]) < 0.9f) << "face on a voxel boundary";
        ASSERT_TRUE(fraction(a1[axis]) > 0.1f && fraction(a1[axis]) < 0.9f) << "face on a voxel boundary";
    }
    // The shell: voxels that meet the box's closed surface = those meeting the box minus those
    // strictly inside it.
    const glm::ivec3 outerLo = glm::ivec3(glm::floor(a0)), outerHi = glm::ivec3(glm::floor(a1));
    const glm::ivec3 innerLo = glm::ivec3(glm::ceil(a0)), innerHi = glm::ivec3(glm::floor(a1)) - 1;
    const auto inRange = [](const glm::ivec3& v, const glm::ivec3& lo, const glm::ivec3& hi) {
        return glm::all(glm::greaterThanEqual(v, lo)) && glm::all(glm::lessThanEqual(v, hi));
    };
    const auto inShell = [&](const glm::ivec3& v) { return inRange(v, outerLo, outerHi) && !inRange(v, innerLo, innerHi); };
    const glm::ivec3 outer = outerHi - outerLo + 1, inner = innerHi - innerLo + 1;
    const long expectedShell = long(outer.x) * outer.y * outer.z - long(inner.x) * inner.y * inner.z;

    const std::vector<glm::ivec3> occupied = occupiedVoxels(*volume_);
    EXPECT_EQ(occupied.size(), countOccupiedVoxels(*volume_));
    std::vector<std::uint8_t> isOccupied(static_cast<std::size_t>(n()) * n() * n(), 0);
    long boxVoxels = 0, strays = 0;
    for (const glm::ivec3& v : occupied) {
        isOccupied[index(v)] = 1;
        const glm::vec3 c = centre(v);
        const float toBox = distanceToBoxSurface(c, boxLo, boxHi) / voxelSize();
        const bool nearFloor = std::abs(c.y) <= voxelSize() && std::abs(c.x) <= 2.0f + voxelSize() &&
                               std::abs(c.z) <= 2.0f + voxelSize();
        if (toBox <= 1.0f) {
            ++boxVoxels;
            EXPECT_TRUE(inShell(v)) << "box voxel " << v.x << "," << v.y << "," << v.z << " outside the shell";
        } else if (!nearFloor) {
            ++strays;
        }
    }
    long missing = 0;
    for (int z = outerLo.z; z <= outerHi.z; ++z)
        for (int y = outerLo.y; y <= outerHi.y; ++y)
            for (int x = outerLo.x; x <= outerHi.x; ++x)
                if (inShell({x, y, z}) && !isOccupied[index({x, y, z})]) ++missing;
    EXPECT_EQ(strays, 0) << "occupied voxels farther than 1 voxel from the box and the floor";
    EXPECT_EQ(missing, 0) << "shell voxels the box's surface passes through but left empty (of " << expectedShell << ")";
    // Conservative rasterization may touch a few extra voxels where an enlarged pixel grazes an
    // edge numerically; 1% of the shell allows that, and catches a shrunk (non-conservative) box.
    EXPECT_NEAR(double(boxVoxels), double(expectedShell), 0.01 * expectedShell);
    // The floor is one layer of about (4 m / voxel)² voxels.
    const double floorColumns = std::pow(4.0 / voxelSize(), 2.0);
    const double floorVoxels = double(occupied.size() - boxVoxels - strays);
    EXPECT_GT(floorVoxels, floorColumns);
    EXPECT_LT(floorVoxels, std::pow(4.0 / voxelSize() + 2.0, 2.0));
}

// ---- Thin wall: every voxel column it crosses holds a voxel ------------------------------------

// Separating-axis test: does the convex polygon `poly` overlap the square [lo, hi]²?
bool overlapsSquare(const std::array<glm::vec2, 4>& poly, glm::vec2 lo, glm::vec2 hi) {
    std::array<glm::vec2, 6> axes{glm::vec2(1, 0), glm::vec2(0, 1)};
    for (int i = 0; i < 4; ++i) {
        const glm::vec2 e = poly[(i + 1) % 4] - poly[i];
        axes[2 + i] = glm::vec2(e.y, -e.x);
    }
    const std::array<glm::vec2, 4> square{lo, glm::vec2(hi.x, lo.y), hi, glm::vec2(lo.x, hi.y)};
    for (const glm::vec2& axis : axes) {
        float p0 = 1e30f, p1 = -1e30f, s0 = 1e30f, s1 = -1e30f;
        for (const glm::vec2& p : poly) p0 = std::min(p0, glm::dot(p, axis)), p1 = std::max(p1, glm::dot(p, axis));
        for (const glm::vec2& s : square) s0 = std::min(s0, glm::dot(s, axis)), s1 = std::max(s1, glm::dot(s, axis));
        if (p1 < s0 || s1 < p0) return false;
    }
    return true;
}

glm::vec3 swizzleForAxis(const glm::vec3& p, int axis) {
    if (axis == 0) return {p.y, p.z, p.x};
    if (axis == 1) return {p.z, p.x, p.y};
    return p;
}
glm::ivec3 voxelOfColumn(int i, int j, int k, int axis) {
    if (axis == 0) return {k, i, j};
    if (axis == 1) return {j, k, i};
    return {i, j, k};
}

TEST_F(Voxelize, TiltedThinWallHasNoHoles) {
    // A zero-thickness 2 m square tilted 30° about X and 30° about Z: its projection along the
    // dominant axis has edges at odd angles, so many columns are only partly covered.
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f));
    const glm::quat tilt = glm::angleAxis(glm::radians(30.0f), glm::vec3(1, 0, 0)) *
                           glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 0, 1));
    const int node = addMeshNode(scene, makePlaneMesh("wall", 2.0f, white), glm::vec3(0.1f, 0.2f, 0.05f), tilt);
    voxelize(scene, 64);

    const glm::mat4& world = scene.nodes[static_cast<std::size_t>(node)].world;
    const glm::vec3 normal = glm::normalize(glm::vec3(world * glm::vec4(0, 1, 0, 0)));
    const glm::vec3 an = glm::abs(normal);
    const int axis = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
    std::array<glm::vec2, 4> projected;
    const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    glm::vec3 origin{0.0f};
    for (int i = 0; i < 4; ++i) {
        const glm::vec3 s = swizzleForAxis(
            toVoxels(glm::vec3(world * glm::vec4(corners[i].x, 0.0f, corners[i].y, 1.0f))), axis);
        projected[static_cast<std::size_t>(i)] = glm::vec2(s);
        if (i == 0) origin = s;
    }
    const glm::vec3 sn = swizzleForAxis(normal, axis);
    const auto depthAt = [&](glm::vec2 uv) {  // the wall's plane along the projection axis (voxels)
        return origin.z - (sn.x * (uv.x - origin.x) + sn.y * (uv.y - origin.y)) / sn.z;
    };

    const std::vector<std::uint32_t> albedo = readMaterialVoxels(volume_->albedo());
    const auto occupied = [&](const glm::ivec3& v) {
        return glm::all(glm::greaterThanEqual(v, glm::ivec3(0))) && glm::all(glm::lessThan(v, glm::ivec3(n()))) &&
               (albedo[index(v)] >> 24) != 0;
    };
    // Columns whose square overlaps the projected wall by more than a sliver (0.02 voxel, so
    // exact touches do not count) must hold a voxel where the plane crosses them.
    constexpr float kSliver = 0.02f;
    int columns = 0, holes = 0;
    for (int j = 0; j < n(); ++j)
        for (int i = 0; i < n(); ++i) {
            if (!overlapsSquare(projected, glm::vec2(i, j) + kSliver, glm::vec2(i + 1, j + 1) - kSliver)) continue;
            ++columns;
            const int k = static_cast<int>(std::floor(depthAt(glm::vec2(i + 0.5f, j + 0.5f))));
            bool found = false;
            for (int dk = -1; dk <= 1 && !found; ++dk) found = occupied(voxelOfColumn(i, j, k + dk, axis));
            if (!found) ++holes;
        }
    EXPECT_GT(columns, 500);
    EXPECT_EQ(holes, 0) << holes << " of " << columns << " columns crossing the wall hold no voxel";

    // Nothing far from the wall: within one voxel of its plane and of its square.
    const glm::vec3 wallCentre = glm::vec3(world[3]);
    const glm::vec3 tangentU = glm::vec3(world * glm::vec4(1, 0, 0, 0)), tangentV = glm::vec3(world * glm::vec4(0, 0, 1, 0));
    int strays = 0;
    for (const glm::ivec3& v : occupiedVoxels(*volume_)) {
        const glm::vec3 d = centre(v) - wallCentre;
        const float offPlane = std::abs(glm::dot(d, normal)) / voxelSize();
        const float outside = std::max(std::abs(glm::dot(d, tangentU)), std::abs(glm::dot(d, tangentV))) - 1.0f;
        if (offPlane > 1.0f || outside > voxelSize() * std::sqrt(2.0f)) ++strays;
    }
    EXPECT_EQ(strays, 0);
}

// ---- Running average: coincident surfaces mix -------------------------------------------------

TEST_F(Voxelize, RunningAverageMixesCoincidentSurfaces) {
    Scene scene;
    const int red = addMaterial(scene, glm::vec3(1.0f, 0.0f, 0.0f));
    const int blue = addMaterial(scene, glm::vec3(0.0f, 0.0f, 1.0f));
    // Without a specular lobe the voxels' albedo is the base colour alone (ReflectsEveryLobesMeanAlbedo).
    for (Material& m : scene.materials) m.specularFactor = 0.0f;
    addMeshNode(scene, makePlaneMesh("red", 1.0f, red), glm::vec3(0.0f));
    addMeshNode(scene, makePlaneMesh("blue", 1.0f, blue), glm::vec3(0.0f));
    voxelize(scene, 64);

    const std::vector<std::uint32_t> albedo = readMaterialVoxels(volume_->albedo());
    const std::vector<std::uint32_t> normals = readMaterialVoxels(volume_->normal());
    int occupied = 0, unmixed = 0;
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < albedo.size(); ++i) {
        const glm::vec4 a = unpackVoxel(albedo[i]);
        if (a.a == 0.0f) continue;
        ++occupied;
        sum += glm::dvec3(a);
        // Each quad lands in each of its voxels at least once, so every voxel holds both colours
        // (1/3..2/3 each where a triangle diagonal adds a second fragment of one colour).
        if (a.r < 0.3f || a.b < 0.3f || a.g > 0.01f || a.a * 255.0f < 1.5f) ++unmixed;
        const glm::vec3 nrm = glm::vec3(unpackVoxel(normals[i])) * 2.0f - 1.0f;
        EXPECT_NEAR(nrm.y, 1.0f, 0.02f);
    }
    ASSERT_GT(occupied, 100);
    EXPECT_EQ(unmixed, 0) << "voxels holding one colour only (overwritten instead of averaged)";
    const glm::dvec3 mean = sum / double(occupied);
    EXPECT_NEAR(mean.r, 0.5, 0.05);
    EXPECT_NEAR(mean.b, 0.5, 0.05);
}

// A voxel reflects what its surface reflects of light from every direction: the diffuse
// (1 − metalness)·colour plus the specular lobe's hemispherical mean F0·Ā + F90·B̄, so a metal is
// not black and a dielectric's specular light is not lost (docs/GI.md, "Voxelization").
TEST_F(Voxelize, ReflectsEveryLobesMeanAlbedo) {
    struct Case {
        const char* name;
        glm::vec3 baseColor;
        float roughness, metallic;
        glm::vec3 expected;
    };
    const glm::vec2 rough = specularMeanAlbedo(0.8f), glossy = specularMeanAlbedo(0.3f);
    const Case cases[] = {
        {"dielectric", glm::vec3(0.5f, 0.25f, 0.1f), 0.8f, 0.0f, glm::vec3(0.5f, 0.25f, 0.1f) + 0.04f * rough.x + rough.y},
        {"gold", glm::vec3(1.0f, 0.77f, 0.34f), 0.3f, 1.0f, glm::vec3(1.0f, 0.77f, 0.34f) * glossy.x + glossy.y},
    };
    for (const Case& c : cases) {
        Scene scene;
        addMeshNode(scene, makePlaneMesh(c.name, 1.0f, addMaterial(scene, c.baseColor, c.roughness, c.metallic)),
                    glm::vec3(0.0f));
        voxelize(scene, 64);
        const std::vector<std::uint32_t> albedo = readMaterialVoxels(volume_->albedo());
        glm::dvec3 sum(0.0);
        int occupied = 0;
        for (const std::uint32_t packed : albedo) {
            const glm::vec4 a = unpackVoxel(packed);
            if (a.a == 0.0f) continue;
            ++occupied;
            sum += glm::dvec3(glm::vec3(a));
        }
        ASSERT_GT(occupied, 100) << c.name;
        const glm::vec3 mean = glm::vec3(sum / double(occupied));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(mean[k], c.expected[k], 2.0f / 255.0f) << c.name << " channel " << k;
    }
    // What the specular lobe adds is what a brute-force check says it is (SpecularMeanAlbedo.*):
    // about 0.03 for a rough dielectric, and a glossy metal keeps most of its colour.
    EXPECT_GT(0.04f * rough.x + rough.y, 0.02f);
    EXPECT_GT(glossy.x, 0.8f);
}

// The inside of a closed box is solid, and stays solid where a second box stands on it (their
// touching faces are buried back to back); the air around is not, nor the space behind a lone quad
// facing down, and no surface voxel is (SolidVoxelsPass, docs/GI.md "Solid voxels").
TEST_F(Voxelize, SolidVoxelsAreTheInsidesOfClosedSurfaces) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f));
    addMeshNode(scene, makeBoxMesh("slab", {2.0f, 0.4f, 2.0f}, white), {0.0f, 0.2f, 0.0f});
    addMeshNode(scene, makeBoxMesh("pillar", {0.4f, 1.2f, 0.4f}, white), {0.5f, 1.0f, 0.5f});
    // A ceiling of one quad facing down (the plane's +y turned over), above the slab's far half.
    addMeshNode(scene, makePlaneMesh("ceiling", 0.8f, white), {-0.5f, 1.4f, -0.5f},
                glm::angleAxis(glm::pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f)));
    voxelize(scene, 64);
    SolidVoxelsPass solid(sourceDir() / "shaders");
    solid.execute(*volume_);
    std::vector<std::uint32_t> bits(volume_->solidVoxels().size() / 4);
    glGetNamedBufferSubData(volume_->solidVoxels().id(), 0, static_cast<GLsizeiptr>(volume_->solidVoxels().size()), bits.data());
    const auto solidAt = [&](const glm::vec3& p) {
        const std::size_t i = index(glm::ivec3(glm::floor(toVoxels(p))));
        return (bits[i >> 5] >> (i & 31)) & 1u;
    };
    EXPECT_TRUE(solidAt({-0.5f, 0.2f, -0.5f})) << "inside the slab";
    EXPECT_TRUE(solidAt({0.5f, 0.2f, 0.5f})) << "inside the slab under the pillar";
    EXPECT_TRUE(solidAt({0.5f, 1.0f, 0.5f})) << "inside the pillar";
    EXPECT_TRUE(solidAt({0.5f, 0.5f, 0.5f})) << "in the pillar just above where it stands on the slab";
    EXPECT_FALSE(solidAt({-0.5f, 0.9f, -0.5f})) << "the air between the slab and the ceiling";
    EXPECT_FALSE(solidAt({-0.5f, 1.55f, -0.5f})) << "above the lone ceiling";
    EXPECT_FALSE(solidAt({0.0f, 1.0f, 0.0f})) << "the air beside the pillar";
    int solidSurfaces = 0, solidCount = 0;
    const std::vector<std::uint32_t> albedo = readMaterialVoxels(volume_->albedo());
    for (std::size_t i = 0; i < albedo.size(); ++i) {
        const bool isSolid = (bits[i >> 5] >> (i & 31)) & 1u;
        solidCount += isSolid;
        if (isSolid && (albedo[i] >> 24) != 0) ++solidSurfaces;
    }
    EXPECT_EQ(solidSurfaces, 0) << "surface voxels are never solid";
    // The slab's and the pillar's insides, roughly: (2 × 0.4 × 2 + 0.4 × 1.2 × 0.4) m³ less a shell.
    const float insideVoxels = (2.0f * 0.4f * 2.0f + 0.4f * 1.2f * 0.4f) / std::pow(voxelSize(), 3.0f);
    EXPECT_GT(solidCount, 0.4f * insideVoxels);
    EXPECT_LT(solidCount, 1.0f * insideVoxels);

    // After a voxelization of changed boxes only the columns through them are walked again, and
    // give what the whole walk gave; the others are left as they were (here: cleared).
    const glm::ivec3 p0 = glm::ivec3(glm::floor(toVoxels({0.3f, 0.0f, 0.3f})));
    const glm::ivec3 p1 = glm::ivec3(glm::floor(toVoxels({0.7f, 1.6f, 0.7f}))) + 1;
    const VoxelBox box{p0, p1};
    glClearNamedBufferData(volume_->solidVoxels().id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    solid.execute(*volume_, std::span<const VoxelBox>(&box, 1));
    std::vector<std::uint32_t> boxBits(bits.size());
    glGetNamedBufferSubData(volume_->solidVoxels().id(), 0, static_cast<GLsizeiptr>(volume_->solidVoxels().size()),
                            boxBits.data());
    int walked = 0, wrong = 0, touched = 0;
    for (int z = 0; z < n(); ++z)
        for (int y = 0; y < n(); ++y)
            for (int x = 0; x < n(); ++x) {
                const std::size_t i = index({x, y, z});
                const bool whole = (bits[i >> 5] >> (i & 31)) & 1u, part = (boxBits[i >> 5] >> (i & 31)) & 1u;
                if (x >= box.min.x && x < box.max.x && z >= box.min.z && z < box.max.z) {
                    walked += whole;
                    wrong += whole != part;
                } else if (x / 32 != box.min.x / 32 && x / 32 != (box.max.x - 1) / 32) {
                    touched += part;  // outside the box's words of 32 columns: not walked
                }
            }
    EXPECT_GT(walked, 100) << "the pillar's and the slab's insides under it";
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(touched, 0);
}

// Where the pillar stands on the slab, the slab's top under it and the pillar's bottom are buried
// back to back and cancel in their voxels' normals, and the conservative voxelization spreads the
// pillar's bottom a voxel beyond its side, over the visible slab top. So the voxels along the
// pillar's foot (its side and the buried pair) and the strip of slab top beside it read two-sided;
// the solid pass makes them one-sided along the faces that run through them: the foot along the
// pillar's side, the strip between that and the slab's top, a bevel (buried_faces.comp.glsl). The
// buried voxels under the pillar, beside which no face runs through, stay as they were.
TEST_F(Voxelize, JunctionsWhereSolidsTouchFaceTheirOpenSide) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f));
    addMeshNode(scene, makeBoxMesh("slab", {2.0f, 0.4f, 2.0f}, white), {0.0f, 0.2f, 0.0f});
    addMeshNode(scene, makeBoxMesh("pillar", {0.4f, 1.2f, 0.4f}, white), {0.5f, 1.0f, 0.5f});
    voxelize(scene, 64);
    const auto normalAt = [&](const std::vector<std::uint32_t>& normals, const glm::ivec3& c) {
        return glm::vec3(unpackVoxel(normals[index(c)])) * 2.0f - 1.0f;
    };
    const glm::ivec3 foot = glm::ivec3(glm::floor(toVoxels({0.7f, 0.4f, 0.5f})));  // the pillar's +x side meets the slab
    const glm::ivec3 strip = foot + glm::ivec3(1, 0, 0);                             // the slab's top beside it
    const glm::ivec3 buried = glm::ivec3(glm::floor(toVoxels({0.5f, 0.4f, 0.5f})));  // under the pillar's middle
    const std::vector<std::uint32_t> before = readMaterialVoxels(volume_->normal());
    const glm::vec3 buriedBefore = normalAt(before, buried);
    ASSERT_LT(glm::length(normalAt(before, foot)), 0.5f) << "the foot's voxel must read two-sided after the voxelization";
    ASSERT_LT(glm::length(normalAt(before, strip)), 0.5f) << "the strip's voxel must read two-sided after the voxelization";
    SolidVoxelsPass solid(sourceDir() / "shaders");
    solid.execute(*volume_);
    const std::vector<std::uint32_t> after = readMaterialVoxels(volume_->normal());
    const glm::vec3 footAfter = normalAt(after, foot), stripAfter = normalAt(after, strip);
    std::printf("foot (%.2f %.2f %.2f), strip (%.2f %.2f %.2f)\n", footAfter.x, footAfter.y, footAfter.z, stripAfter.x,
                stripAfter.y, stripAfter.z);
    EXPECT_GT(glm::length(footAfter), 0.9f) << "the foot is one-sided";
    EXPECT_GT(footAfter.x, 0.9f) << "along the pillar's side";
    EXPECT_GT(glm::length(stripAfter), 0.9f) << "the strip is one-sided";
    EXPECT_GT(stripAfter.x, 0.5f) << "a bevel between the pillar's side";
    EXPECT_GT(stripAfter.y, 0.5f) << "and the slab's top";
    EXPECT_NEAR(glm::length(normalAt(after, buried)), glm::length(buriedBefore), 0.01f)
        << "the buried voxel stays as it was";
}

TEST_F(Voxelize, SkipsAlphaMaskedTexelsAndClearsOldContent) {
    Scene scene;
    const int opaque = addMaterial(scene, glm::vec3(0.5f));
    const int cutout = addMaterial(scene, glm::vec3(0.5f));
    scene.materials[static_cast<std::size_t>(cutout)].alphaMode = AlphaMode::Mask;
    scene.materials[static_cast<std::size_t>(cutout)].baseColorFactor.a = 0.2f;  // below the 0.5 cutoff
    addMeshNode(scene, makePlaneMesh("kept", 1.0f, opaque), glm::vec3(0.0f));
    addMeshNode(scene, makePlaneMesh("cut", 1.0f, cutout), glm::vec3(0.0f, 0.5f, 0.0f));
    voxelize(scene, 64);
    for (const glm::ivec3& v : occupiedVoxels(*volume_))
        EXPECT_LT(std::abs(centre(v).y), voxelSize()) << "voxel of the masked plane at y = " << centre(v).y;
    // Executing again must give the same volume, not accumulate onto the previous one.
    const std::vector<std::uint32_t> first = readMaterialVoxels(volume_->albedo());
    DrawCounters counters;
    voxelize_->execute(scene, *gpuScene_, *volume_, counters);
    EXPECT_TRUE(first == readMaterialVoxels(volume_->albedo()));
}

// ---- Injection -------------------------------------------------------------------------------

TEST_F(VoxelInject, FloorGetsLambertRadianceAndShadows) {
    // A 0.8-albedo 4 m floor under a 3 lux directional light straight down, a 1 m box 1 m above
    // its centre: lit floor voxels reflect L = 0.8/π · 3 W/(sr·m²); under the box, ≈ 0.
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f));
    addMeshNode(scene, makePlaneMesh("floor", 4.0f, white, 4), glm::vec3(0.0f));
    addMeshNode(scene, makeBoxMesh("occluder", glm::vec3(1.0f), white), glm::vec3(0.0f, 1.0f, 0.0f));
    Light sun;
    sun.type = LightType::Directional;
    sun.intensity = 3.0f;
    addLightNode(scene, sun, glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    RenderSettings settings;
    voxelize(scene, 64, settings);
    inject(scene, settings);

    const float expected = 0.8f / glm::pi<float>() * 3.0f;
    const std::vector<glm::vec4> radiance = readRadianceVoxels(*volume_);
    const float margin = 3.0f * voxelSize();  // PCF and voxel extent blur the shadow's edge
    int lit = 0, shadowed = 0, wrongLit = 0, wrongShadowed = 0, emptyWithRadiance = 0;
    float worstLit = 0.0f, worstShadowed = 0.0f;
    const std::vector<std::uint32_t> albedo = readMaterialVoxels(volume_->albedo());
    for (int z = 0; z < n(); ++z)
        for (int y = 0; y < n(); ++y)
            for (int x = 0; x < n(); ++x) {
                const glm::ivec3 v{x, y, z};
                const glm::vec4 r = radiance[index(v)];
                if ((albedo[index(v)] >> 24) == 0) {
                    if (r != glm::vec4(0.0f)) ++emptyWithRadiance;
                    continue;
                }
                EXPECT_EQ(r.a, 1.0f);
                const glm::vec3 c = centre(v);
                if (std::abs(c.y) > voxelSize() || std::max(std::abs(c.x), std::abs(c.z)) > 2.0f - voxelSize())
                    continue;  // not the floor, or its rim (partly outside, averaged with nothing)
                const float reach = std::max(std::abs(c.x), std::abs(c.z));
                if (reach > 0.5f + margin) {
                    ++lit;
                    const float error = std::abs(r.g - expected) / expected;
                    worstLit = std::max(worstLit, error);
                    if (error > 0.10f) ++wrongLit;
                } else if (reach < 0.5f - margin) {
                    ++shadowed;
                    worstShadowed = std::max(worstShadowed, r.g);
                    if (r.g > 0.05f * expected) ++wrongShadowed;
                }
            }
    EXPECT_EQ(emptyWithRadiance, 0);
    EXPECT_GT(lit, 1000);
    EXPECT_GT(shadowed, 50);
    EXPECT_EQ(wrongLit, 0) << "lit floor voxels off by > 10% (worst " << worstLit * 100.0f << "%) of " << expected;
    EXPECT_EQ(wrongShadowed, 0) << "shadowed floor voxels above 5% of lit (worst " << worstShadowed << ")";
}

// A voxel across a box's edge holds a lit face and a dark one: it sends the mean of their light,
// weighted by its fragments as its averaged normal n̄ = s_top·up + s_side·n_side is, so
// L = ρ/π · E · s_top under a light straight down. The normalized normal gave s_top/|n̄| (1.41× at
// an even split). The box is turned about y so that its edges cross the voxels at every offset.
TEST_F(VoxelInject, BoxEdgeVoxelsSendTheMeanOfTheirFacesLight) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f));
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f, 0.6f, 1.0f), white), glm::vec3(0.0f),
                glm::angleAxis(glm::radians(10.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
    Light sun;
    sun.type = LightType::Directional;
    sun.intensity = 3.0f;
    addLightNode(scene, sun, glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    voxelize(scene, 64);
    inject(scene);
    const std::vector<glm::vec4> radiance = readRadianceVoxels(*volume_);
    const std::vector<std::uint32_t> albedo = readMaterialVoxels(volume_->albedo());
    const std::vector<std::uint32_t> normals = readMaterialVoxels(volume_->normal());
    int edgeVoxels = 0, wrong = 0, topVoxels = 0, wrongTop = 0;
    float worst = 0.0f;
    for (const glm::ivec3& v : occupiedVoxels(*volume_)) {
        const glm::vec3 n = glm::vec3(unpackVoxel(normals[index(v)])) * 2.0f - 1.0f;
        const float sTop = n.y, sSide = glm::length(glm::vec2(n.x, n.z));
        const float lambert = unpackVoxel(albedo[index(v)]).g / glm::pi<float>() * 3.0f;
        if (sTop > 0.98f) {  // the top's inside: the flat face's own light
            ++topVoxels;
            if (std::abs(radiance[index(v)].g - lambert) > 0.05f * lambert) ++wrongTop;
            continue;
        }
        // Edges between the top and one side only (not the corners, where two sides share n̄),
        // split evenly enough that the two rules differ by more than the tolerance.
        if (sTop < 0.25f || sTop > 0.75f || std::abs(sTop + sSide - 1.0f) > 0.04f) continue;
        ++edgeVoxels;
        const float expected = lambert * sTop;
        const float error = std::abs(radiance[index(v)].g - expected) / expected;
        worst = std::max(worst, error);
        if (error > 0.06f) ++wrong;
    }
    EXPECT_GT(topVoxels, 500);
    EXPECT_EQ(wrongTop, 0);
    EXPECT_GT(edgeVoxels, 30);
    EXPECT_EQ(wrong, 0) << "edge voxels off the mean of their faces' light by > 6% (worst " << worst * 100.0f << "%)";
}

// Under a low sun a voxel is lit where its surface is: the shadow a box casts on the floor starts
// in the floor's voxels where it starts on the floor, within half a voxel. A lookup from the voxel
// centre a voxel out along the normal saw the light of the floor 1–3 voxels further along it, and
// the shadow moved towards the light (inject.comp.glsl, kShadowSurfaceOffsetVoxels). The edge
// near the box is the one checked: the far one, cast by the box's top, ends 1.6 voxels short with
// either lookup, for a reason not found yet.
TEST_F(VoxelInject, LowSunLightsTheFloorVoxelsWhereItLightsTheFloor) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f));
    addMeshNode(scene, makePlaneMesh("floor", 4.0f, white, 4), glm::vec3(0.0f));
    addMeshNode(scene, makeBoxMesh("occluder", glm::vec3(0.6f), white), glm::vec3(0.0f, 0.6f, 0.0f));
    // Travelling along +z, 30° above the horizon: a point at height y shades the floor y·cot 30° further.
    const float elevation = glm::radians(30.0f);
    const glm::vec3 direction{0.0f, -std::sin(elevation), std::cos(elevation)};
    Light sun;
    sun.type = LightType::Directional;
    sun.intensity = 3.0f;
    addLightNode(scene, sun, -3.0f * direction, direction);
    voxelize(scene, 64);
    inject(scene);
    // The box spans y 0.3..0.9 and z ±0.3: its shadow starts at z = −0.3 + 0.3·cot 30°.
    const float nearEdge = -0.3f + 0.3f / std::tan(elevation);
    const std::vector<glm::vec4> radiance = readRadianceVoxels(*volume_);
    const float lit = 0.8f / glm::pi<float>() * 3.0f * std::sin(elevation);
    // Along each column of floor voxels under the box's middle (|x| < 0.15), the centre of the
    // shadow's first voxel in z.
    int columns = 0, wrong = 0;
    float worst = 0.0f;
    for (int x = 0; x < n(); ++x) {
        if (std::abs(centre({x, 0, 0}).x) > 0.15f) continue;
        float first = 1e9f;
        for (int z = 0; z < n(); ++z)
            for (int y = 0; y < n(); ++y) {
                const glm::vec3 c = centre({x, y, z});
                if (std::abs(c.y) > voxelSize() || std::abs(c.z) > 2.0f - voxelSize()) continue;
                const glm::vec4 r = radiance[index({x, y, z})];
                if (r.a > 0.0f && r.g < 0.5f * lit) first = std::min(first, c.z);
            }
        ++columns;
        const float error = std::abs(first - nearEdge) / voxelSize();
        worst = std::max(worst, error);
        if (error > 0.5f) ++wrong;
    }
    EXPECT_GT(columns, 3);
    EXPECT_EQ(wrong, 0) << "the shadow starts more than half a voxel off where it starts on the floor (worst " << worst
                        << " voxels)";
}

// A 1 cm slab: its top and bottom faces share voxels, whose averaged normals cancel (two-sided
// voxels). Each is lit from the side the light is on, and sends that light to that side only: level
// 0 holds the mean of its sides, its sides texel the slab's axis and the half difference, so that a
// ray ending on the lit side sees the face's whole light and one from the other side none
// (voxel.glsl, "Sides"). Lit as one-sided voxels, they would be dark or random from one side; lit
// as before, they glowed on both sides with the lit face's light (the light that leaked through
// Sponza's gallery floors: docs/GI.md, "Two-sided voxels").
TEST_F(VoxelInject, WallThinnerThanAVoxelSendsEachSideItsOwnLight) {
    for (float from : {1.0f, -1.0f}) {
        SCOPED_TRACE(from > 0.0f ? "lit from above" : "lit from below");
        Scene scene;
        const int white = addMaterial(scene, glm::vec3(0.8f));
        addMeshNode(scene, makeBoxMesh("slab", glm::vec3(2.0f, 0.01f, 2.0f), white), glm::vec3(0.0f));
        // Off to the side, it moves the volume so that no voxel boundary splits the slab.
        addMeshNode(scene, makeBoxMesh("marker", glm::vec3(0.1f), white), glm::vec3(1.2f, 0.3f, 0.0f));
        Light sun;
        sun.type = LightType::Directional;
        sun.intensity = 3.0f;
        addLightNode(scene, sun, glm::vec3(0.0f, 3.0f * from, 0.0f), glm::vec3(0.0f, -from, 0.0f));
        voxelize(scene, 64);
        inject(scene);
        ASSERT_EQ(std::floor(toVoxels(glm::vec3(0.0f, 0.005f, 0.0f)).y), std::floor(toVoxels(glm::vec3(0.0f, -0.005f, 0.0f)).y))
            << "the slab's faces fall into different voxel layers";
        const float expected = 0.8f / glm::pi<float>() * 3.0f;
        const std::vector<glm::vec4> radiance = readRadianceVoxels(*volume_);
        const std::vector<VoxelSides> sides = readVoxelSides(*volume_);
        // The brightest voxel of each column well inside the slab.
        int columns = 0, wrong = 0;
        float worstMean = 0.0f, worstLit = 0.0f, worstDark = 0.0f;
        for (int z = 0; z < n(); ++z)
            for (int x = 0; x < n(); ++x) {
                const glm::vec3 c = centre({x, 0, z});
                if (std::max(std::abs(c.x), std::abs(c.z)) > 1.0f - 2.0f * voxelSize()) continue;
                int brightest = 0;
                for (int y = 0; y < n(); ++y)
                    if (radiance[index({x, y, z})].g > radiance[index({x, brightest, z})].g) brightest = y;
                const std::size_t i = index({x, brightest, z});
                ++columns;
                const VoxelSides& side = sides[i];
                if (!side.split || std::abs(side.axis.y) < 0.95f) {
                    ++wrong;
                    continue;
                }
                // The lit side is the one towards the light (+y lit from above).
                const float towardsLight = side.axis.y * from > 0.0f ? 1.0f : -1.0f;
                const float mean = radiance[i].g, lit = mean + towardsLight * side.delta.g,
                            dark = mean - towardsLight * side.delta.g;
                worstMean = std::max(worstMean, std::abs(mean - 0.5f * expected) / (0.5f * expected));
                worstLit = std::max(worstLit, std::abs(lit - expected) / expected);
                worstDark = std::max(worstDark, std::abs(dark) / expected);
                if (std::abs(mean - 0.5f * expected) > 0.05f * expected ||
                    std::abs(lit - expected) > 0.10f * expected || std::abs(dark) > 0.02f * expected)
                    ++wrong;
            }
        EXPECT_GT(columns, 500);
        EXPECT_EQ(wrong, 0) << "columns without the slab's axis or off (worst: mean " << worstMean * 100.0f
                            << " %, lit side " << worstLit * 100.0f << " %, dark side " << worstDark * 100.0f
                            << " % of the lit face's light)";
    }
}

TEST_F(VoxelInject, EmissiveMaterialGivesItsEmission) {
    // No lights: an emissive box's voxels carry its emission, the floor's nothing. Both radiance
    // formats: RGBA16F as is, RGBA8 scaled by voxelRadianceRange.
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f));
    const int glow = addMaterial(scene, glm::vec3(0.5f));
    const glm::vec3 emission{4.0f, 2.0f, 1.0f};  // W/(sr·m²); multiples of 16/255 survive the RGBA8 packing
    scene.materials[static_cast<std::size_t>(glow)].emissiveFactor = emission;
    addMeshNode(scene, makePlaneMesh("floor", 2.0f, white), glm::vec3(0.0f));
    addMeshNode(scene, makeBoxMesh("lamp", glm::vec3(0.5f), glow), glm::vec3(0.0f, 0.6f, 0.0f));
    for (bool rgba8 : {false, true}) {
        SCOPED_TRACE(rgba8 ? "RGBA8 radiance" : "RGBA16F radiance");
        RenderSettings settings;
        settings.gi.radianceRgba8 = rgba8;
        settings.gi.radianceRange = 8.0f;
        settings.sky.sunIrradiance = 0.0f;  // really no light: not the default sun of a bare scene
        voxelize(scene, 64, settings);
        inject(scene, settings);
        const std::vector<glm::vec4> radiance = readRadianceVoxels(*volume_, 0, settings.gi.radianceRange);
        int lampVoxels = 0, wrong = 0;
        for (const glm::ivec3& v : occupiedVoxels(*volume_)) {
            const glm::vec3 r = glm::vec3(radiance[index(v)]);
            if (centre(v).y > 0.2f) {
                ++lampVoxels;
                // 8-bit packing: ±1/255 of the 16 W/(sr·m²) emission range, then of the RGBA8 range.
                if (glm::any(glm::greaterThan(glm::abs(r - emission), glm::vec3(0.03f) * emission + 0.07f))) ++wrong;
            } else if (r != glm::vec3(0.0f)) {
                ++wrong;
            }
        }
        EXPECT_GT(lampVoxels, 200);
        EXPECT_EQ(wrong, 0);
    }
}

// ---- The Cornell box: closed walls, and how long it takes ---------------------------------------

TEST_F(VoxelInject, CornellBoxVoxelizesAndLightsWithTimings) {
    const Scene scene = loadGltf(sourceDir() / "assets" / "cornell_box.gltf", log_);
    for (int resolution : {64, 128}) {
        RenderSettings settings;
        settings.gi.voxelResolution = resolution;
        voxelize(scene, resolution, settings);  // warm-up: shader compilation on first use
        inject(scene, settings);
        // Best of three: the machine running the tests is shared, the minimum is the least noisy.
        double voxelizeMs = 1e30, injectMs = 1e30;
        DrawCounters counters;
        for (int run = 0; run < 3; ++run) {
            glFinish();
            const auto t0 = Clock::now();
            counters = {};
            voxelize_->execute(scene, *gpuScene_, *volume_, counters);
            glFinish();
            voxelizeMs = std::min(voxelizeMs, msSince(t0));
            const auto t1 = Clock::now();
            inject_->execute(*volume_);
            glFinish();
            injectMs = std::min(injectMs, msSince(t1));
        }
        const std::size_t occupied = countOccupiedVoxels(*volume_);
        std::cout << "Cornell box " << resolution << "³: voxelize " << voxelizeMs << " ms, inject " << injectMs
                  << " ms, " << occupied << " occupied voxels, " << counters.triangles << " triangles\n";
        RecordProperty("voxelize_ms_" + std::to_string(resolution), static_cast<int>(voxelizeMs));
        RecordProperty("inject_ms_" + std::to_string(resolution), static_cast<int>(injectMs));
        // Five 2 m walls and two boxes: at least the five walls' (2 m / voxel)² columns.
        const double wallColumns = 5.0 * std::pow(2.0 / voxelSize(), 2.0);
        EXPECT_GT(double(occupied), wallColumns);
        EXPECT_LT(double(occupied), 2.0 * wallColumns);
        // Some voxels are lit by the ceiling spot, and none holds a non-finite value.
        const std::vector<glm::vec4> radiance = readRadianceVoxels(*volume_);
        int litVoxels = 0, bad = 0;
        for (const glm::vec4& r : radiance) {
            if (!std::isfinite(r.r) || !std::isfinite(r.g) || !std::isfinite(r.b) || r.r < 0.0f) ++bad;
            if (r.g > 0.01f) ++litVoxels;
        }
        EXPECT_EQ(bad, 0);
        EXPECT_GT(litVoxels, 1000);
    }
}

}  // namespace
}  // namespace lit::test
