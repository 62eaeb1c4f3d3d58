// GI accuracy: the criteria that say the cone-traced light lands in the right places,
// each in a scene with a known answer, rendered through the whole Renderer (voxelize, inject,
// bounces, mips, cone trace) at 64³-128³ and 96²-128² pixels.
//  - a lone lit floor does not light itself (self-illumination);
//  - a sealed room with a strong light outside stays dark inside (no leaks through two-voxel walls);
//  - a thin wall lit on one side does not glow on the other (directional injection);
//  - the Cornell box's indirectly lit regions do not change with the voxel resolution;
//  - the directional volumes treat −x and +x alike (the Cornell box and its mirror image), and so
//    does the accurate mode's cone sampling (stratified cone sets);
//  - bounces add up as a geometric series in a closed emissive box (the bounce furnace).
// docs/GI.md ("Accuracy against the reference", "Known limits", "Approaches that did not work")
// has the numbers.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <sstream>
#include <string>

#include "GlTestSupport.h"
#include "gi/InjectPass.h"
#include "gi/VoxelVolume.h"
#include "reference/AccuracyRegions.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/SceneBuilder.h"

namespace lit::test {
namespace {

CameraView lookAt(const glm::vec3& eye, const glm::vec3& target, float aspect = 1.0f, float yfov = 1.2f) {
    CameraView c;
    c.position = eye;
    c.yfov = yfov;
    c.znear = 0.02f;
    c.zfar = 30.0f;
    const glm::vec3 up = std::abs(glm::normalize(target - eye).y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    c.view = glm::lookAt(eye, target, up);
    c.projection = glm::perspective(c.yfov, aspect, c.znear, c.zfar);
    return c;
}

Light directionalLight(float lux) {
    Light l;
    l.name = "sun";
    l.type = LightType::Directional;
    l.intensity = lux;
    return l;
}

// Mean of an image over the rectangle [u0,u1]×[v0,v1] of picture coordinates (origin top left).
glm::vec3 meanOf(const HdrImage& image, float u0, float v0, float u1, float v1) { return image.mean(u0, v0, u1, v1); }

// A copy of shaders/ under the temp folder with `define` added after bounce.comp.glsl's #version: a
// shader variant to render against (removed again with the object).
struct ShaderVariant {
    std::filesystem::path root;
    ShaderVariant(const std::filesystem::path& shaders, const std::string& file, const std::string& name,
                  const std::string& define) {
        namespace fs = std::filesystem;
        root = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
        fs::create_directories(root);
        fs::copy(shaders, root, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
        std::stringstream text;
        text << std::ifstream(shaders / file).rdbuf();
        std::string source = text.str();
        source.insert(source.find('\n') + 1, define + "\n");
        std::ofstream(root / file, std::ios::trunc) << source;
    }
    ~ShaderVariant() {
        std::error_code ignored;
        std::filesystem::remove_all(root, ignored);
    }
    ShaderVariant(const ShaderVariant&) = delete;
    ShaderVariant& operator=(const ShaderVariant&) = delete;
};

// bounce.comp.glsl (the voxels' bounces and irradiance) with `define`.
struct BounceShaderVariant : ShaderVariant {
    BounceShaderVariant(const std::filesystem::path& shaders, const std::string& name, const std::string& define)
        : ShaderVariant(shaders, "bounce.comp.glsl", name, define) {}
};

class GiAccuracy : public GlFixture {
protected:
    // Renders `settings` on the running renderer (whose scene is `scene`: only the settings changed) and
    // on a fresh one; returns the fresh image and the running one's difference from it (0: the change
    // was picked up).
    std::pair<HdrImage, double> againstFreshRenderer(const Scene& scene, const CameraView& camera,
                                                     const RenderSettings& settings) {
        renderer_->render(scene, camera, settings);
        const HdrImage changed{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
        Renderer fresh(sourceDir() / "shaders", log_);
        fresh.setScene(scene);
        fresh.render(scene, camera, settings);
        HdrImage freshImage{settings.output.width, settings.output.height, fresh.readHdrRgb()};
        const double stale = relativeDifference(changed, freshImage);
        return {std::move(freshImage), stale};
    }
    // The cached mode at 64³, L_ID, 48², one bounce and cones (giSettings' pins).
    static RenderSettings cachedAt64() {
        RenderSettings settings = giSettings(64, View::IndirectDiffuse, 48);
        settings.gi.mode = GiMode::Cached;
        return settings;
    }
    // The defaults' GI (the cached mode, two bounces, 32 voxel rays) at 64³, L_ID, 48², without
    // temporal accumulation (its history would blur frames together).
    static RenderSettings twoBouncesWithRays() {
        RenderSettings settings = cachedAt64();
        settings.gi.bounces = 2;
        settings.gi.voxelRays = 32;
        settings.indirect.temporalAccumulation = false;
        return settings;
    }
    // Every bounce with voxel rays, otherwise as twoBouncesWithRays.
    static RenderSettings everyBounceWithRays() {
        RenderSettings settings = twoBouncesWithRays();
        settings.gi.bounces = kAllBounces;
        return settings;
    }
    // What an update spread over frames must end on: a fresh renderer's image with the whole update
    // in one frame (the default GiBudget). Replaces the fixture's renderer.
    HdrImage allAtOnceInAFreshRenderer(const Scene& scene, const CameraView& camera, RenderSettings settings) {
        renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
        return renderFrom(scene, camera, settings);
    }
    // The update's voxels a frame that replay a pass over `occupied` list entries in `frames` frames.
    static GiBudget replayedOver(std::uint32_t occupied, int frames) {
        const std::uint32_t replayed = static_cast<std::uint32_t>(frames) * kReplayVoxelsPerFrameFactor;
        return {(occupied + replayed - 1) / replayed, 0};
    }
    HdrImage renderFrom(const Scene& scene, const CameraView& camera, const RenderSettings& settings) {
        renderer_->setScene(scene);
        renderer_->render(scene, camera, settings);
        return HdrImage{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    }
    // The accurate GI mode: anisotropic voxels and footprint-bounded cones traced per pixel. The
    // tests that compare with the fast mode's isotropic voxels switch them off explicitly; those of
    // the cached mode (the default) switch it on.
    static RenderSettings giSettings(int voxels, View view = View::Final, int size = 96) {
        RenderSettings s = smallSettings(size);
        s.gi.enabled = true;
        s.gi.voxelResolution = voxels;
        s.debug.view = view;
        // The accurate mode (cones traced per pixel), one bounce, cones for the voxels' own light,
        // whatever the defaults (the cached mode, two bounces, 32 voxel rays): the measurements in
        // the comments below are theirs. Tests of the defaults, of rays and of bounces say so.
        s.gi.mode = GiMode::Accurate;
        s.gi.bounces = 1;
        s.gi.voxelRays = 0;
        return s;
    }
    // The renderer's defaults (RenderSettings as constructed: the cached mode, two bounces, 32 voxel
    // rays) but for the size, GI on and the voxel resolution: what a user gets.
    static RenderSettings defaultSettings(int voxels, int size) {
        RenderSettings s = smallSettings(size);
        s.gi.enabled = true;
        s.gi.voxelResolution = voxels;
        return s;
    }
    // The end of the sealed-room tests: the same view without GI, then the GI image's mean (the
    // leak) and the GI-off image's as shares of the outside radiance `outside`. The GI-off image
    // must be dark, else the shadow maps let the sun in and the leak is not GI's; the bar on the
    // GI image is 1 %.
    void expectNoLeak(const Scene& scene, const CameraView& inside, RenderSettings settings, const HdrImage& gi,
                      float outside, const std::string& label) {
        settings.gi.enabled = false;
        const HdrImage noGi = renderFrom(scene, inside, settings);
        const float leak = luminance(meanOf(gi, 0.0f, 0.0f, 1.0f, 1.0f));
        const float directLeak = luminance(meanOf(noGi, 0.0f, 0.0f, 1.0f, 1.0f));
        std::printf("%s: outside %.3f, inside with GI %.5f (%.2f %%), without GI %.5f\n", label.c_str(), outside, leak,
                    100.0f * leak / outside, directLeak);
        EXPECT_LT(directLeak, 0.001f * outside) << "the shadow maps must keep the sun out (else the test is not GI's)";
        EXPECT_LT(leak, 0.01f * outside) << "light leaking through the walls";
    }
};

// A white floor (one quad, so one voxel thick) alone in the volume, lit from above: nothing else
// can send light back, so its indirect light is exactly 0. Cones that leave it must not see its
// own voxels. With isotropic stacked mips and no footprint bound: L_ID = 0.69 L at 64³
// (docs/GI.md, "Footprint-bounded cones"). Bar: 5 % of the floor's own radiance.
TEST_F(GiAccuracy, LoneLitFloorDoesNotLightItself) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f), 1.0f, 0.0f, "white");
    addMeshNode(scene, makePlaneMesh("floor", 2.0f, white), {0.0f, 0.0f, 0.0f});
    addLightNode(scene, directionalLight(3.0f), {0.0f, 3.0f, 0.0f}, glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f)));
    const CameraView camera = lookAt({0.0f, 1.2f, 0.6f}, {0.0f, 0.0f, 0.0f});
    // The accurate mode's cones, and the defaults (the cached mode, two bounces, voxel rays, whose
    // rays leave the floor's plane and cannot cross it again).
    for (RenderSettings settings : {giSettings(64, View::DirectDiffuse, 48), defaultSettings(64, 48)}) {
        const char* mode = settings.gi.voxelRays > 0 ? "the defaults" : "the accurate mode";
        settings.debug.view = View::DirectDiffuse;
        const HdrImage direct = renderFrom(scene, camera, settings);
        settings.debug.view = View::IndirectDiffuse;
        const HdrImage indirect = renderFrom(scene, camera, settings);
        // The middle of the picture: the floor, away from its edges.
        const float own = luminance(meanOf(direct, 0.3f, 0.3f, 0.7f, 0.7f));
        const float self = luminance(meanOf(indirect, 0.3f, 0.3f, 0.7f, 0.7f));
        std::printf("lone floor, %s: own radiance %.4f, indirect %.4f (%.1f %%)\n", mode, own, self, 100.0f * self / own);
        ASSERT_GT(own, 0.1f) << "the floor must be lit";
        EXPECT_LT(self, 0.05f * own) << "self-illumination, " << mode;
    }
}

// A closed room (walls, floor and roof two voxels thick at 64³) on a ground lit by a strong
// sun; a camera inside. No light can get in: everything the inside shows is a leak. Bar: 1 % of
// the outside ground's radiance. Measured: 0.43 % at 128³; at 64³ 0.48 %, 0.23 % with slab-backed
// surfaces sending no light edge-on (mipmap_directional.comp.glsl, "backed"); with the isotropic voxels
// (anisotropicVoxels off, no footprint bound) the benchmark's sealed room leaked 12 %, 7.4 %,
// 4.0 % at 64³, 128³, 256³.
TEST_F(GiAccuracy, SealedRoomDoesNotLeakLightIn) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f), 1.0f, 0.0f, "white");
    const float groundSize = 4.0f;
    constexpr int kVoxels = 64;  // the benchmark measures 128³ and 256³ (docs/tables/gi-accuracy.md)
    // VoxelVolume::fitTo pads the scene by 2 voxels per side: voxel = extent / (N − 4).
    const float voxel = groundSize / float(kVoxels - 4);
    const float w = 2.0f * voxel;  // wall thickness
    const float h = 1.0f;          // inner half extent (m); room inside [−1, 1] × [0, 2] × [−1, 1]
    addMeshNode(scene, makePlaneMesh("ground", groundSize, white), {0.0f, -w, 0.0f});
    // Floor and roof span the whole footprint; the walls overlap them, so no seam is open.
    addMeshNode(scene, makeBoxMesh("room floor", {2 * (h + w), w, 2 * (h + w)}, white), {0.0f, -0.5f * w, 0.0f});
    addMeshNode(scene, makeBoxMesh("roof", {2 * (h + w), w, 2 * (h + w)}, white), {0.0f, 2 * h + 0.5f * w, 0.0f});
    for (const float side : {-1.0f, 1.0f}) {
        addMeshNode(scene, makeBoxMesh("wall x", {w, 2 * h + 2 * w, 2 * (h + w)}, white), {side * (h + 0.5f * w), h, 0.0f});
        addMeshNode(scene, makeBoxMesh("wall z", {2 * (h + w), 2 * h + 2 * w, w}, white), {0.0f, h, side * (h + 0.5f * w)});
    }
    const glm::vec3 sunDirection = glm::normalize(glm::vec3(0.5f, -1.0f, 0.3f));
    const float lux = 20.0f;
    addLightNode(scene, directionalLight(lux), {0.0f, 4.0f, 0.0f}, sunDirection);
    scene.updateWorldTransforms();
    // Outgoing radiance of the lit ground: albedo/π · E⊥ · cosθ.
    const float outside = 0.8f / glm::pi<float>() * lux * -sunDirection.y;
    const CameraView inside = lookAt({0.3f, 1.2f, 0.8f}, {-0.3f, 0.6f, -1.0f}, 1.0f, 1.4f);
    // The accurate mode's cones, and the defaults (the cached mode, two bounces, voxel rays).
    for (const RenderSettings& settings : {giSettings(kVoxels, View::Final, 64), defaultSettings(kVoxels, 64)}) {
        const HdrImage gi = renderFrom(scene, inside, settings);
        ASSERT_NE(renderer_->voxels(), nullptr);
        ASSERT_NEAR(renderer_->voxels()->voxelSize(), voxel, 1e-4f) << "walls must be two voxels thick";
        expectNoLeak(scene, inside, settings, gi, outside,
                     "sealed room at " + std::to_string(kVoxels) + "³, " +
                         (settings.gi.voxelRays > 0 ? "the defaults" : "the accurate mode"));
    }
}

// The benchmark's sealed room (tools/make_gi_suite.cpp: interior 4 × 3 × 4 m, walls 0.2 m, sunlit
// roof, walls and ground) on a ground 8 m wide, so that at 128³ the walls are 3.1 voxels thick,
// more than the two of the test above, but a twentieth of the room: a footprint-bounded cone in the
// middle of the room samples voxels 0.3-0.7 m wide, each holding the wall and the sunlit surface
// outside it. With edge-on emission weight 1 the directional faces that see a wall edge-on show
// that outer surface's light to cones from inside: 1.17 % of the ground's radiance leaked in on
// the benchmark at 256³ (same wall thickness in voxels), 1.36 % at 128³. Level 1 of the directional
// chains gives a surface seen edge-on no light when the other side of its slab lies right
// behind it (mipmap_directional.comp.glsl, "backed"): measured here 1.16 % without that, 0.15 %
// with it (docs/GI.md, "Anisotropic voxels"). Bar: 1 %. ~1.5 s on llvmpipe.
TEST_F(GiAccuracy, SealedRoomWithWallsAFractionOfItsConesWidthDoesNotLeak) {
    Scene scene;
    const int ground = addMaterial(scene, glm::vec3(0.5f), 0.9f, 0.0f, "ground");
    const int wall = addMaterial(scene, glm::vec3(0.73f), 0.9f, 0.0f, "white");
    constexpr int kVoxels = 128;
    const float groundSize = 8.0f;
    addMeshNode(scene, makePlaneMesh("ground", groundSize, ground, 4), {0.0f, 0.0f, 0.0f});
    constexpr float t = 0.2f, w = 4.0f, h = 3.0f;
    addMeshNode(scene, makeBoxMesh("room floor", {w + 2 * t, t, w + 2 * t}, wall), {0.0f, 0.5f * t, 0.0f});
    addMeshNode(scene, makeBoxMesh("roof", {w + 2 * t, t, w + 2 * t}, wall), {0.0f, t + h + 0.5f * t, 0.0f});
    for (const float side : {-1.0f, 1.0f}) {
        addMeshNode(scene, makeBoxMesh("wall z", {w + 2 * t, h, t}, wall), {0.0f, t + 0.5f * h, side * 0.5f * (w + t)});
        addMeshNode(scene, makeBoxMesh("wall x", {t, h, w}, wall), {side * 0.5f * (w + t), t + 0.5f * h, 0.0f});
    }
    const glm::vec3 sunDirection = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
    const float lux = 50.0f;
    addLightNode(scene, directionalLight(lux), {0.0f, 8.0f, 0.0f}, sunDirection);
    scene.updateWorldTransforms();
    const float outside = 0.5f / glm::pi<float>() * lux * -sunDirection.y;
    const CameraView inside = lookAt({1.2f, 1.6f, 1.6f}, {-1.0f, 1.4f, -1.5f}, 1.0f, 1.2f);
    // The accurate mode's cones, and the defaults (the cached mode, two bounces, voxel rays): the
    // rays pass in front of one-sided voxels and reach the voxels at the room's inner edges, which
    // are lit through the wall unless injection also looks half a voxel out (the benchmark's room
    // at 128³: 0.73 % without that look, 0.42 % with it; docs/GI.md, "Injection").
    for (const RenderSettings& settings : {giSettings(kVoxels, View::Final, 48), defaultSettings(kVoxels, 48)}) {
        const HdrImage gi = renderFrom(scene, inside, settings);
        ASSERT_NE(renderer_->voxels(), nullptr);
        const float voxel = renderer_->voxels()->voxelSize();
        ASSERT_GT(t / voxel, 3.0f) << "walls must be more than two voxels thick";
        char label[96];
        std::snprintf(label, sizeof label, "sealed room, walls %.1f voxels at %d³, %s", t / voxel, kVoxels,
                      settings.gi.voxelRays > 0 ? "the defaults" : "the accurate mode");
        expectNoLeak(scene, inside, settings, gi, outside, label);
    }
}

// A closed box of `material` from `lo` to `hi` (m).
void addBoxNode(Scene& scene, const char* name, glm::vec3 lo, glm::vec3 hi, int material) {
    addMeshNode(scene, makeBoxMesh(name, hi - lo, material), 0.5f * (lo + hi));
}

// The rooms of touching slabs below: a floor slab, a roof slab and the walls standing between
// them, closed boxes kSlab thick around an inside kRoomWidth square and kRoomHeight high, the
// inside from y = kSlab; the +z wall (x in ±kRoomWidth/2, z from kRoomWidth/2 out) is the test's.
constexpr float kSlab = 0.3f, kRoomWidth = 4.0f, kRoomHeight = 2.6f;
void addSlabRoom(Scene& scene, int material) {
    const float t = kSlab, h = kRoomHeight, o = 0.5f * kRoomWidth + t, z = 0.5f * kRoomWidth;
    addBoxNode(scene, "floor", {-o, 0.0f, -o}, {o, t, o}, material);
    addBoxNode(scene, "roof", {-o, t + h, -o}, {o, 2 * t + h, o}, material);
    addBoxNode(scene, "wall -x", {-o, t, -o}, {-z, t + h, o}, material);
    addBoxNode(scene, "wall +x", {z, t, -o}, {o, t + h, o}, material);
    addBoxNode(scene, "wall -z", {-z, t, -o}, {z, t + h, -z}, material);
}

// A room built as users build one in Blender: a floor slab, walls standing on it and a roof slab
// resting on them, each a closed box 0.3 m thick that touches the next, lit by a sun through one
// window, and the same room with the window closed by a box that touches its reveals. Where two
// boxes touch their faces are buried back to back, and the voxelization writes surfaces only, so
// the inside of each slab is empty space: an inner-edge voxel's rays that start in the wall beside
// it, and the buried voxels' rays, ran through the slabs to the sunlit outside, and bright dots
// along every inner edge lit the closed room. SolidVoxelsPass marks the slabs' insides, and no ray
// starts there, and makes the voxels along the inner edges one-sided (their buried faces cancelled
// their normals). Measured here (64³, the defaults): the closed room holds 0.00 % of the open
// room's light, 0.25 % with the insides marked alone, 3.1 % with neither (the sun room made in
// Blender, closed the same way, at 128³: 1.0 % and 6.0 % without the edges). Bar: 1 %.
TEST_F(GiAccuracy, ClosedWindowLetsNoLightAlongTheRoomsEdges) {
    constexpr float t = kSlab, h = kRoomHeight;
    constexpr float x0 = -0.6f, x1 = 0.6f, y0 = 1.1f, y1 = 2.3f;  // the window in the +z wall
    const auto room = [&](bool closed) {
        Scene scene;
        const int white = addMaterial(scene, glm::vec3(0.8f), 0.8f, 0.0f, "white");
        addSlabRoom(scene, white);
        const float o = 0.5f * kRoomWidth + t, z = 0.5f * kRoomWidth;
        addBoxNode(scene, "window left", {-z, t, z}, {x0, t + h, o}, white);
        addBoxNode(scene, "window right", {x1, t, z}, {z, t + h, o}, white);
        addBoxNode(scene, "window below", {x0, t, z}, {x1, y0, o}, white);
        addBoxNode(scene, "window above", {x0, y1, z}, {x1, t + h, o}, white);
        if (closed) addBoxNode(scene, "window plug", {x0, y0, z}, {x1, y1, o}, white);
        addLightNode(scene, directionalLight(50.0f), {0.0f, 8.0f, 0.0f}, glm::normalize(glm::vec3(0.2f, -0.55f, -0.8f)));
        scene.updateWorldTransforms();
        return scene;
    };
    const CameraView inside = lookAt({1.2f, 1.5f, 1.2f}, {-1.6f, 1.0f, -1.8f}, 1.0f, 1.4f);
    const RenderSettings settings = defaultSettings(64, 48);
    const float open = luminance(meanOf(renderFrom(room(false), inside, settings), 0.0f, 0.0f, 1.0f, 1.0f));
    ASSERT_NE(renderer_->voxels(), nullptr);
    ASSERT_GT(t / renderer_->voxels()->voxelSize(), 2.5f) << "slabs must be more than two voxels thick";
    const float closed = luminance(meanOf(renderFrom(room(true), inside, settings), 0.0f, 0.0f, 1.0f, 1.0f));
    std::printf("room of touching slabs at 64³: open %.5f, closed %.6f (%.2f %%)\n", open, closed, 100.0f * closed / open);
    ASSERT_GT(open, 0.01f) << "the open room must be lit";
    EXPECT_LT(closed, 0.01f * open) << "light along the closed room's edges";
}

// A furnace built as rooms are built: the closed room of touching slabs above and a box standing
// on its floor, every face glowing with radiance e and Lambertian of albedo ρ = 0.8 (no specular
// lobe), no light, no sky. Every surface then holds e / (1 − ρ) = 5e, so each pixel reads 5× its
// emission alone: a closed form for the default tracer (voxel rays, every bounce) in a room's
// geometry, where the closed emissive box of planes has none of a room's junctions. A share of
// rays lost in each bounce is lost again in every later one (five bounces' worth here). Measured
// (64³, the defaults): 0.991 of 5e; 0.966 while the voxels along the inner edges, whose buried
// faces (a wall's bottom on the floor slab's top) cancelled their normals, stayed two-sided and
// started a side of their rays in the buried row (SolidVoxelsPass, buried_faces.comp.glsl).
// Bar: within 2.5 % of 5e.
TEST_F(GiAccuracy, FurnaceOfTouchingSlabsHoldsTheSeriesLimit) {
    constexpr float t = kSlab, h = kRoomHeight;
    constexpr float albedo = 0.8f;
    Scene scene;
    const int glowing = addMaterial(scene, glm::vec3(albedo), 0.8f, 0.0f, "glowing");
    Material& material = scene.materials[std::size_t(glowing)];
    material.emissiveFactor = glm::vec3(1.0f);
    material.specularFactor = 0.0f;
    addSlabRoom(scene, glowing);
    const float o = 0.5f * kRoomWidth + t, z = 0.5f * kRoomWidth;
    addBoxNode(scene, "wall +z", {-z, t, z}, {z, t + h, o}, glowing);
    addBoxNode(scene, "block", {-1.2f, t, -1.0f}, {-0.4f, t + 0.8f, -0.2f}, glowing);  // standing on the floor
    scene.updateWorldTransforms();
    const CameraView inside = lookAt({1.2f, 1.5f, 1.2f}, {-1.6f, 1.0f, -1.8f}, 1.0f, 1.4f);
    RenderSettings settings = defaultSettings(64, 48);
    settings.sky.mode = SkyMode::None;
    const HdrImage lit = renderFrom(scene, inside, settings);
    ASSERT_NE(renderer_->voxels(), nullptr);
    ASSERT_GT(t / renderer_->voxels()->voxelSize(), 2.5f) << "slabs must be more than two voxels thick";
    settings.gi.enabled = false;
    const HdrImage emission = renderFrom(scene, inside, settings);
    const float ratio =
        luminance(meanOf(lit, 0.0f, 0.0f, 1.0f, 1.0f)) / luminance(meanOf(emission, 0.0f, 0.0f, 1.0f, 1.0f));
    const float exact = 1.0f / (1.0f - albedo);
    std::printf("furnace of touching slabs at 64³: %.4f × the emission (exact %.1f): %.4f of it\n", ratio, exact,
                ratio / exact);
    EXPECT_NEAR(ratio / exact, 1.0f, 0.025f);
}

// A wall one quad thin, lit on one side by the sun; a second, smaller quad behind it faces the
// wall's dark side and is in its shadow. Only the lit side radiates, away from the receiver, so
// the receiver's indirect light is 0. Isotropic voxels glow on both sides; the directional ones
// do not seen face-on, but a one-voxel wall seen edge-on still shows its light to both sides
// (docs/GI.md, "Known limits"): measured 26 % of the wall's radiance against 43 % with the
// isotropic volume (anisotropicVoxels off, no footprint bound, one bounce): 0.62×.
// The goal (no glow) is not met; the bar keeps what the directional voxels gain: at most ¾ of the
// isotropic glow.
TEST_F(GiAccuracy, ThinWallLitOnOneSideGlowsLessOnTheOther) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f), 1.0f, 0.0f, "white");
    // The plane's normal +Y turned to +X: the wall faces the light (at +X), the receiver faces
    // the wall's back. The camera stands between them, looking at the receiver.
    const glm::quat toPlusX = glm::angleAxis(-glm::half_pi<float>(), glm::vec3(0, 0, 1));
    addMeshNode(scene, makePlaneMesh("wall", 2.0f, white), {0.0f, 0.0f, 0.0f}, toPlusX);
    addMeshNode(scene, makePlaneMesh("receiver", 1.0f, white), {-0.6f, 0.0f, 0.0f}, toPlusX);
    addLightNode(scene, directionalLight(5.0f), {3.0f, 0.0f, 0.0f}, glm::vec3(-1.0f, 0.0f, 0.0f));
    scene.updateWorldTransforms();
    const float wallRadiance = 0.8f / glm::pi<float>() * 5.0f;
    const CameraView behind = lookAt({-0.1f, 0.3f, 0.3f}, {-0.6f, 0.0f, 0.0f}, 1.0f, 0.9f);
    RenderSettings settings = giSettings(64, View::IndirectDiffuse, 48);
    settings.gi.bounces = 1;
    const float received = luminance(meanOf(renderFrom(scene, behind, settings), 0.35f, 0.35f, 0.65f, 0.65f));
    settings.gi.mode = GiMode::Fast;  // isotropic voxels, unbounded cones
    const float isotropic = luminance(meanOf(renderFrom(scene, behind, settings), 0.35f, 0.35f, 0.65f, 0.65f));
    std::printf("thin wall: lit side %.3f, receiver behind it %.4f (%.1f %%), isotropic voxels %.4f (%.1f %%)\n",
                wallRadiance, received, 100.0f * received / wallRadiance, isotropic, 100.0f * isotropic / wallRadiance);
    ASSERT_GT(isotropic, 0.1f * wallRadiance) << "the isotropic volume must show the glow (else the test is vacuous)";
    EXPECT_LT(received, 0.75f * isotropic) << "the wall's dark side glows";
}

// The Cornell box against the reference path tracer with the same light paths (one bounce both),
// over the regions the accuracy benchmark uses (reference/AccuracyRegions.h: first hits of the
// reference at the pixel centres, so the masks do not depend on the VCT). 96², 64³, 64 spp.
struct CornellMeasurement {
    std::vector<reference::NamedRegion> regions;
    std::vector<float> truthIndirect, truthFinal;
    reference::PixelMask surfaces, directlyLit;
};

class CornellAccuracy : public GiAccuracy {
protected:
    static constexpr int kSize = 96;
    CornellMeasurement measureReference(const Scene& scene, int bounces = 1) {
        CornellMeasurement m;
        Log quiet;
        quiet.setSink(nullptr);
        const reference::ReferenceScene rs(scene, quiet);
        const CameraView camera = cameraFor(scene, giSettings(64, View::Final, kSize));
        reference::ReferenceSettings referenceSettings;
        referenceSettings.bounces = bounces;
        reference::PathTracer tracer(rs, camera, kSize, kSize, referenceSettings);
        tracer.addSamples(64);
        const RenderSettings viewSettings;
        const std::vector<float> id = tracer.image().viewRgb(View::IndirectDiffuse, viewSettings);
        const std::vector<float> is = tracer.image().viewRgb(View::IndirectSpecular, viewSettings);
        m.truthIndirect.resize(id.size());
        for (std::size_t i = 0; i < id.size(); ++i) m.truthIndirect[i] = id[i] + is[i];
        m.truthFinal = tracer.image().viewRgb(View::Final, viewSettings);
        const std::vector<reference::FirstHit> hits = reference::traceFirstHits(rs, camera, kSize, kSize);
        m.regions = reference::cornellBoxRegions(scene, hits, kSize, kSize);
        m.surfaces = reference::surfaceMask(hits);
        m.directlyLit = reference::directlyLitMask(hits);
        return m;
    }
    // L_ID + L_IS of the VCT with `bounces` bounces, in GI mode `mode`.
    // `voxelRays` > 0: the voxels' own light (the cached irradiance, bounces) by rays (GiSettings::voxelRays).
    std::vector<float> vctIndirect(const Scene& scene, int voxels, int bounces = 1, GiMode mode = GiMode::Accurate,
                                   int voxelRays = 0) {
        RenderSettings settings = giSettings(voxels, View::IndirectDiffuse, kSize);
        settings.gi.mode = mode;
        settings.gi.bounces = bounces;
        settings.gi.voxelRays = voxelRays;
        return renderIndirect(scene, settings);
    }
    // L_ID + L_IS with the renderer's defaults (RenderSettings as constructed: the cached mode, two
    // bounces, 32 voxel rays) but for the size, GI on and the voxel resolution: what a user gets.
    std::vector<float> defaultsIndirect(const Scene& scene, int voxels) {
        const RenderSettings settings = defaultSettings(voxels, kSize);
        EXPECT_EQ(settings.gi.bounces, kAllBounces);
        EXPECT_EQ(settings.gi.voxelRays, 32);
        EXPECT_TRUE(settings.gi.voxelIrradiance()) << "the cached mode";
        return renderIndirect(scene, settings);
    }
    static double lum(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
    // The bar: each of the four regions lit only indirectly within ±20 % of the reference.
    static void expectRegionsMatchTheReference(const CornellMeasurement& truth, const std::vector<float>& vct) {
        int checked = 0;
        for (const reference::NamedRegion& region : truth.regions) {
            if (region.pixels() < 10) continue;
            const double t = lum(reference::maskedMean(truth.truthIndirect, region.mask));
            const double v = lum(reference::maskedMean(vct, region.mask));
            std::printf("%s (%zu px): reference %.4f, VCT %.4f (%.2f)\n", region.name.c_str(), region.pixels(), t, v, v / t);
            EXPECT_NEAR(v / t, 1.0, 0.20) << region.name;
            ++checked;
        }
        EXPECT_EQ(checked, 4) << "ceiling, back wall, shadowed floor by the green wall and by the red wall";
    }
    // The bleeding bar: R/G on the shadowed floor by the red wall and G/R by the green wall
    // within ±20 % of the reference's.
    static void expectBleedingMatchesTheReference(const CornellMeasurement& truth, const std::vector<float>& vct) {
        int checked = 0;
        for (const reference::NamedRegion& region : truth.regions) {
            const bool red = region.name == "shadowed floor by red wall", green = region.name == "shadowed floor by green wall";
            if (!red && !green) continue;
            const glm::dvec3 t = reference::maskedMean(truth.truthIndirect, region.mask);
            const glm::dvec3 v = reference::maskedMean(vct, region.mask);
            const double truthRatio = red ? t.r / t.g : t.g / t.r, vctRatio = red ? v.r / v.g : v.g / v.r;
            std::printf("%s %s: reference %.2f, VCT %.2f\n", region.name.c_str(), red ? "R/G" : "G/R", truthRatio, vctRatio);
            EXPECT_NEAR(vctRatio / truthRatio, 1.0, 0.20) << region.name << (red ? ": R/G" : ": G/R");
            ++checked;
        }
        EXPECT_EQ(checked, 2) << "both shadowed floors";
    }
    // The Cornell box's named regions in the fixture's view of `scene` (traced first hits).
    std::vector<reference::NamedRegion> regionsOf(const Scene& scene) {
        Log quiet;
        quiet.setSink(nullptr);
        const reference::ReferenceScene rs(scene, quiet);
        const CameraView camera = cameraFor(scene, giSettings(64, View::Final, kSize));
        return reference::cornellBoxRegions(scene, reference::traceFirstHits(rs, camera, kSize, kSize), kSize, kSize);
    }

    // Renders L_ID of the Cornell box and of its mirror image in x (assets/gi/cornell_mirrored.gltf)
    // with `settings`, expects every region's mean within ±20 % of its mirror image's, and returns
    // the RMSE between the image and the mirrored image flipped back, over the surfaces, relative
    // to the mean. `label` starts the printed lines.
    double expectMirrorImageRegions(const RenderSettings& settings, const char* label) {
        const Scene original = loadCornellBox();
        const Scene mirrored = loadGltf(sourceDir() / "assets" / "gi" / "cornell_mirrored.gltf", log_);
        const HdrImage a = render(original, settings), b = render(mirrored, settings);
        std::vector<float> flipped(b.rgb.size());  // b mirrored about the image's centre column
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                for (int c = 0; c < 3; ++c)
                    flipped[static_cast<std::size_t>((y * kSize + x) * 3 + c)] =
                        b.rgb[static_cast<std::size_t>((y * kSize + (kSize - 1 - x)) * 3 + c)];
        Log quiet;
        quiet.setSink(nullptr);
        const reference::ReferenceScene rs(original, quiet);
        const std::vector<reference::FirstHit> hits = reference::traceFirstHits(rs, cameraFor(original, settings), kSize, kSize);
        int checked = 0;
        for (const reference::NamedRegion& region : reference::cornellBoxRegions(original, hits, kSize, kSize)) {
            if (region.pixels() < 10) continue;
            const double u = lum(reference::maskedMean(a.rgb, region.mask)), v = lum(reference::maskedMean(flipped, region.mask));
            std::printf("%s%s (%zu px): Cornell box %.4f, mirrored %.4f (%.3f)\n", label, region.name.c_str(),
                        region.pixels(), u, v, v / u);
            EXPECT_NEAR(v / u, 1.0, 0.20) << label << region.name;
            ++checked;
        }
        EXPECT_EQ(checked, 4);
        const reference::PixelMask surfaces = reference::surfaceMask(hits);
        double squares = 0.0, sum = 0.0;
        std::size_t count = 0;
        for (std::size_t p = 0; p < surfaces.size(); ++p) {
            if (!surfaces[p]) continue;
            const double u = lum(glm::dvec3(a.rgb[3 * p], a.rgb[3 * p + 1], a.rgb[3 * p + 2]));
            const double v = lum(glm::dvec3(flipped[3 * p], flipped[3 * p + 1], flipped[3 * p + 2]));
            squares += (u - v) * (u - v);
            sum += u;
            ++count;
        }
        const double relativeRmse = std::sqrt(squares / static_cast<double>(count)) / (sum / static_cast<double>(count));
        std::printf("%sL_ID RMSE against the mirror image: %.1f %% of the mean\n", label, 100.0 * relativeRmse);
        return relativeRmse;
    }
};

// The directional volumes (their ±axis faces, the gap between them, the directional emission) treat
// −x and +x alike: the Cornell box and its mirror image in x (assets/gi/cornell_mirrored.gltf, made
// by make-gi-suite) get mirror-image indirect light. Anisotropic voxels with unbounded cones: the
// footprint-bounded cones of the accurate mode see along their axes, and the six-cone set is not
// mirror-symmetric (mirrored, it is the set turned by 36°), so there the regions differ by design
// (docs/GI.md, "Footprint-bounded cones"); wide cones mostly average that out. Measured (64³, 96²):
// region means 0.89 (the short block's shadow, 25 px), 0.98, 1.00, 1.01 of their mirror images',
// the L_ID image 10.5 % RMSE (of its mean) from its mirror image; the rest is the set's turn and the
// voxel grid, not quite symmetric about x = 0. With a defect that treats one face of an axis unlike
// the other, injected into the shaders for this measurement: −x cones reading the +x face
// (cone.glsl faceOffsets.x = 0): 0.55 and 1.29, 21.7 %; the −x face composited and emitting as the
// +x one (mipmap_directional.comp.glsl travel.x = +1): 0.57 and 1.12, 19.9 %. Bars halfway: every
// region within ±20 %, the image within 15 % RMSE.
TEST_F(CornellAccuracy, DirectionalVolumesAreMirrorSymmetric) {
    RenderSettings settings = giSettings(64, View::IndirectDiffuse, kSize);
    settings.gi.coneFootprintPerHeight = 0.0f;
    settings.gi.bounces = 1;
    EXPECT_LT(expectMirrorImageRegions(settings, ""), 0.15);
}

// The accurate mode (footprint-bounded cones) gives the Cornell box and its mirror image in x mirror-
// image indirect light. Its bounded cones see along their axes; with one fixed six-cone set (the
// mirror image of the set is the set turned by 36°) the red-wall nook got 0.25 of the reference in
// the Cornell box and 1.11 in the mirrored box, ratio 4.4 (docs/GI.md, "Footprint-bounded cones").
// The stratified cone sets (cone_strata.glsl, ConeStrataFilterPass) integrate each region over
// LIT_CONE_STRATA² cells, so the result does not depend on the set's orientation. Bars as
// DirectionalVolumesAreMirrorSymmetric's (the defects it guards against scored 0.55-0.57 and
// 20-22 %): every region within ±20 % of its mirror image's. Measured (64³, 96²): 0.92-1.07;
// with the fixed set 0.73-3.55 (the nook 3.55, the back wall 0.73): it fails there.
TEST_F(CornellAccuracy, AccurateModeIsMirrorSymmetric) {
    RenderSettings settings = giSettings(64, View::IndirectDiffuse, kSize);
    settings.gi.bounces = 1;
    // The RMSE is printed, not asserted: the pattern of the cone sets is not mirrored with the
    // image, so silhouettes and edges (where the strata filter keeps part of its window) differ
    // pixel by pixel; measured 14.2 % (the fixed set: 68.8 %; the unbounded mode: 10.5 %, above).
    expectMirrorImageRegions(settings, "accurate: ");
}

// The mean indirect radiance of each region lit only indirectly within ±20 % of the reference.
// With isotropic voxels (benchmark at 64³, docs/GI.md, "Known limits"): ceiling 0.19, back wall
// 0.38, shadowed floor by the green wall 1.01, by the red wall 1.72. With the fixed six-cone set of
// the accurate mode: 0.93, 0.92, 1.00 and 0.25 (the red-wall nook, not asserted with that set);
// with the stratified cone sets (benchmark, 128²): 1.09, 1.08, 0.94, 0.80 and this test (96²) 1.09,
// 1.09, 1.01, 0.82 when first measured; this test reads 1.05, 0.99, 1.02, 0.86 with the grid's
// ¼-voxel shift in y and z, 1.14, 1.10, 1.01, 0.81 without it.
TEST_F(CornellAccuracy, IndirectOnlyRegionsMatchTheReference) {
    const Scene scene = loadCornellBox();
    expectRegionsMatchTheReference(measureReference(scene), vctIndirect(scene, 64));
}

// The same bars for the cached mode (the default: the accurate cones traced per voxel, filtered
// over the cone sets, gathered per pixel), at the default voxel resolution, 128³. Measured (this
// test, 96²): ceiling 1.04, back wall 0.93, floor by the green wall 0.95, nook 0.81 (the
// weakest). At 64³ its nook is 0.75 (benchmark 0.77; with all 16 sets traced per voxel and no
// filter 0.81): below the bar there, so 64³ is not claimed (docs/GI.md, "Voxel irradiance cache").
TEST_F(CornellAccuracy, CachedModeRegionsMatchTheReferenceAt128) {
    const Scene scene = loadCornellBox();
    expectRegionsMatchTheReference(measureReference(scene), vctIndirect(scene, 128, 1, GiMode::Cached));
}

// Multiple bounces: with two bounces against the two-bounce reference, the same ±20 %
// bars on the Cornell regions. The bounce pass of the accurate mode traces the stratified cone
// sets from each voxel (bounce.comp.glsl, cone_strata.glsl voxelConeSetIndex). Measured (this
// test, 64³, 96², reference 64 spp): ceiling 1.09, back wall 1.17, floor by the green wall 0.99,
// nook 0.62 (docs/GI.md, "Stratified cone sets"); benchmark 64³ / 128³ (128², 128 spp): ceiling
// 1.09 / 0.96, back wall 1.15 / 0.96, floor by the green wall 0.94 / 0.93 (the fixed set's bounce:
// 1.09 / 0.95, 1.02 / 0.85, 0.94 / 0.92). The red-wall nook gets 0.61-0.64 of its two-bounce light
// with either (not met: docs/GI.md, "Known limits"), so it is printed, not asserted.
TEST_F(CornellAccuracy, TwoBounceRegionsMatchTheTwoBounceReference) {
    const Scene scene = loadCornellBox();
    const CornellMeasurement truth = measureReference(scene, 2);
    const std::vector<float> vct = vctIndirect(scene, 64, 2);
    int checked = 0;
    for (const reference::NamedRegion& region : truth.regions) {
        if (region.pixels() < 10) continue;
        const double t = lum(reference::maskedMean(truth.truthIndirect, region.mask));
        const double v = lum(reference::maskedMean(vct, region.mask));
        std::printf("two bounces: %s (%zu px): reference %.4f, VCT %.4f (%.2f)\n", region.name.c_str(), region.pixels(), t,
                    v, v / t);
        if (region.name.find("red wall") != std::string::npos) continue;
        EXPECT_NEAR(v / t, 1.0, 0.20) << region.name;
        ++checked;
    }
    EXPECT_EQ(checked, 3) << "ceiling, back wall, shadowed floor by the green wall";
}

// The two-bounce bars in the cached mode with voxel rays (GiSettings::voxelRays 32):
// every region within ±20 % of the two-bounce reference, the red-wall nook included, and the colour
// bleeding ratios within ±20 % of the reference's. The cones miss the nook and both ratios (the
// benchmark at 96², 1024 spp, 64³ / 128³: nook 0.59 / 0.60, R/G 2.99 / 3.06 against 1.99, G/R 2.66 /
// 2.64 against 2.16); the rays: ceiling 1.11 / 1.03, back wall 1.10 / 1.02, floor by the green wall
// 0.90 / 0.92, nook 0.89 / 0.94, R/G 2.11 / 2.14, G/R 2.40 / 2.35 (docs/GI.md, "Voxel rays").
// With voxelRays 0 this test fails (nook, R/G, G/R). 64³, ~10 s.
TEST_F(CornellAccuracy, VoxelRaysMeetTheTwoBounceBars) {
    const Scene scene = loadCornellBox();
    const CornellMeasurement truth = measureReference(scene, 2);
    const std::vector<float> vct = vctIndirect(scene, 64, 2, GiMode::Cached, 32);
    expectRegionsMatchTheReference(truth, vct);
    expectBleedingMatchesTheReference(truth, vct);
}

// The same bars with the renderer's defaults (RenderSettings as constructed: the cached mode, every
// bounce, 32 voxel rays) at the default voxel resolution, 128³, against the reference with every
// bounce: what a user gets. Fails if a default goes back to the cones (nook 0.60, R/G 3.06 against
// 1.99 in the two-bounce benchmark at 96²) or to a bounce count (two bounces against every bounce,
// the final image at 128², 512 spp: mean 0.825 of the reference's, against 0.959 with every
// bounce). Measured (this test): see the printout. ~20 s.
TEST_F(CornellAccuracy, DefaultsMeetTheBarsAt128) {
    const Scene scene = loadCornellBox();
    const CornellMeasurement truth = measureReference(scene, reference::kAllBounces);
    const std::vector<float> vct = defaultsIndirect(scene, 128);
    expectRegionsMatchTheReference(truth, vct);
    expectBleedingMatchesTheReference(truth, vct);
}

// The Cornell room with walls one voxel thick at 128³ and half a voxel at 64³, under a sun on its
// roof (assets/gi/thin_walls.gltf): every wall voxel holds both faces, and the sunlit outside face
// of the roof and the walls shares its voxels with the inside face. Such a voxel sends each face's
// light to that face's side only (voxel.glsl, "Sides"); while it sent the sunlit face's light both
// ways, the room's indirect light read 6.2× the reference at 64³ and the floor by the green wall
// 1.74× at 128³ (G/R 3.45 against 2.29), from the table's run (tools/gi-accuracy.sh). With the
// defaults at 128³ the Cornell box's bars hold (every region and both bleeding ratios within ±20 %);
// at 64³, where the walls are half a voxel, the ceiling and the back wall (the nook reads about 1.9:
// docs/GI.md, "Known limits"). ~25 s.
TEST_F(CornellAccuracy, ThinWallsLetNoSunlightIn) {
    const Scene scene = loadGltf(sourceDir() / "assets" / "gi" / "thin_walls.gltf", log_);
    const CornellMeasurement truth = measureReference(scene, reference::kAllBounces);
    expectRegionsMatchTheReference(truth, defaultsIndirect(scene, 128));
    expectBleedingMatchesTheReference(truth, defaultsIndirect(scene, 128));
    const std::vector<float> coarse = defaultsIndirect(scene, 64);
    int checked = 0;
    for (const reference::NamedRegion& region : truth.regions) {
        const double t = lum(reference::maskedMean(truth.truthIndirect, region.mask));
        const double v = lum(reference::maskedMean(coarse, region.mask));
        std::printf("64³, walls half a voxel: %s (%zu px): reference %.4f, VCT %.4f (%.2f)\n", region.name.c_str(),
                    region.pixels(), t, v, v / t);
        if (region.name != "ceiling" && region.name != "back wall above blocks") continue;
        EXPECT_NEAR(v / t, 1.0, 0.20) << "64³: " << region.name;
        ++checked;
    }
    EXPECT_EQ(checked, 2) << "the ceiling and the back wall";
}

// RMSE of the final image (the VCT scaled so that its mean over directly lit pixels
// matches the reference's) below half of GI-off's RMSE. Both one bounce. Measured at 64³: 0.60 of
// GI-off's with the isotropic volume, 0.59 with the fixed six-cone set of the accurate
// mode (0.45 with the rejected five sub-cones per cone, at 6× the cone trace), 0.41 with the
// stratified cone sets (docs/GI.md, "Stratified cone sets").
TEST_F(CornellAccuracy, FinalImageErrorIsLessThanHalfOfGiOff) {
    const Scene scene = loadCornellBox();
    const CornellMeasurement truth = measureReference(scene);
    const auto rmse = [&](bool gi) {
        RenderSettings settings = giSettings(64, View::Final, kSize);
        settings.gi.enabled = gi;
        settings.gi.bounces = 1;
        const HdrImage image = render(scene, settings);
        const double k = lum(reference::maskedMean(truth.truthFinal, truth.directlyLit)) /
                         std::max(lum(reference::maskedMean(image.rgb, truth.directlyLit)), 1e-12);
        double squares = 0.0;
        int count = 0;
        for (std::size_t p = 0; p < truth.surfaces.size(); ++p) {
            if (!truth.surfaces[p]) continue;
            const double v = lum(glm::dvec3(image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]));
            const double t = lum(glm::dvec3(truth.truthFinal[3 * p], truth.truthFinal[3 * p + 1], truth.truthFinal[3 * p + 2]));
            squares += (k * v - t) * (k * v - t);
            ++count;
        }
        return std::sqrt(squares / std::max(count, 1));
    };
    const double on = rmse(true), off = rmse(false);
    std::printf("final RMSE: GI on %.4f, GI off %.4f (%.2f)\n", on, off, on / off);
    EXPECT_LT(on, 0.5 * off);
}

// The accurate mode's indirect light must not depend on the voxel resolution: each
// region lit only indirectly changes by at most 10 % from 64³ to 128³ (no reference needed: both
// are VCT). On an unshifted grid at 64³ the Cornell box's lit block tops (18 and 36 voxels above the
// floor) lie on the faces between two voxels, and voxelize.frag.glsl puts them into the voxel above:
// the ceiling and the back wall read 8-11 % brighter than with the tops inside their voxel.
// VoxelVolume::fitTo shifts the grid by ¼ voxel in y and z (docs/GI.md, "Surfaces on voxel faces").
// Measured here (96², 128³ ÷ 64³): without the shift 0.876 (ceiling), 1.088 (nook), 0.996 (floor by
// the green wall), 0.850 (back wall): it fails; with it 0.942, 1.040, 0.989, 0.939.
TEST_F(CornellAccuracy, IndirectRegionsChangeLittleFrom64To128Voxels) {
    const Scene scene = loadCornellBox();
    const std::vector<float> low = vctIndirect(scene, 64), high = vctIndirect(scene, 128);
    int checked = 0;
    for (const reference::NamedRegion& region : regionsOf(scene)) {
        if (region.pixels() < 10) continue;
        const double a = lum(reference::maskedMean(low, region.mask)), b = lum(reference::maskedMean(high, region.mask));
        std::printf("%s (%zu px): 64³ %.4f, 128³ %.4f (%.3f)\n", region.name.c_str(), region.pixels(), a, b, b / a);
        EXPECT_NEAR(b / a, 1.0, 0.10) << region.name << ": 64³ → 128³";
        ++checked;
    }
    EXPECT_EQ(checked, 4) << "ceiling, back wall, shadowed floor by the green wall and by the red wall";
}

// The grid's alignment: the Cornell box's indirect light must not depend on where the
// voxel faces fall. Two tiny planes outside the box (one under the floor, one over the ceiling,
// where no light reaches) stretch the scene's bounds in y to 2.4 m, so a voxel is 4 cm (64³; the
// box is 50 voxels tall, the block tops 15 and 30 voxels above the floor). Moving both planes
// down together moves the grid against the box and keeps the voxel size: with fitTo as it is
// (2¼ voxels below the bounds) 0.19 m under the floor puts the floor, both block tops (the block
// sides' top edges) and the ceiling on voxel faces, 0.21 m half a voxel off them; the depths are
// found from the grid's placement, so the test holds if fitTo's padding or shift changes. Same
// voxel size, same scene, only the alignment differs. With the edges on faces the conservative
// rasterization writes or skips the rows the block sides only touch by sub-pixel snapping, unless
// voxelize.geom.glsl's kTouchMargin covers them: in the benchmark at 64³, ceiling and back wall
// read 1.14 and 1.09 of the reference on faces against 1.03-1.06 and 0.97-0.98 off them (8-12 %
// apart); with the margin 1.03-1.08 and 0.98-0.99 over four offsets (at most 5 % apart). Measured
// here (96², on faces ÷ half a voxel off): with the margin ceiling 1.053, back wall 1.014; without
// it 1.131 and 1.137. Bar ±8 %: above the margin's spread (5 % in the benchmark, 5.3 % here) by a
// third, so that another rasterizer's rounding does not trip it, and 5 points below the failure it
// catches. The two floor regions are printed, not asserted (25-33 px; the floor by the green wall
// reads 1.07 with the margin and 1.01 without, the nook 1.014 and 1.036: neither is the edges').
// With fitTo's ¼ shift dropped (x and z on faces as well) it fails the other way, ceiling 0.908:
// the margin is not the whole cure, which is why the shift stays. docs/GI.md, "Surfaces on voxel
// faces".
TEST_F(CornellAccuracy, IndirectRegionsDoNotDependOnTheGridAlignment) {
    const Scene original = loadCornellBox();
    const float span = 0.4f;  // the bounds grow from 2 m to 2.4 m in y: 60 → 50 voxels over the box
    const auto withMarkers = [&](float below) {
        Scene scene = loadCornellBox();
        addMeshNode(scene, makePlaneMesh("grid marker below", 1e-3f, 0), {0.0f, -below, -0.99f});
        addMeshNode(scene, makePlaneMesh("grid marker above", 1e-3f, 0), {0.0f, 2.0f + span - below, -0.99f});
        scene.updateWorldTransforms();
        return scene;
    };
    // Where the floor falls with the markers 0.2 m under it: the depths below move it by whole
    // metres ÷ voxel size from there (the voxel size does not change), whatever fitTo's padding and shift.
    VoxelVolume probe;
    probe.ensure(64, false, log_);
    ASSERT_EQ(probe.resolution(), 64);
    probe.fitTo(withMarkers(0.2f).worldBounds());
    const float voxel = probe.voxelSize(), floorAt = -probe.minCorner().y / voxel;
    const float fraction = floorAt - std::floor(floorAt);
    const auto renderAt = [&](float below, float expectedFraction) {
        std::vector<float> image = vctIndirect(withMarkers(below), 64);
        const VoxelVolume& volume = *renderer_->voxels();
        const float floorInVoxels = -volume.minCorner().y / volume.voxelSize();
        std::printf("grid alignment: voxel %.4f m, floor at %.3f voxels, block tops at %.3f and %.3f\n",
                    volume.voxelSize(), floorInVoxels, floorInVoxels + 0.6f / volume.voxelSize(),
                    floorInVoxels + 1.2f / volume.voxelSize());
        const float off = floorInVoxels - std::round(floorInVoxels - expectedFraction);
        EXPECT_NEAR(off, expectedFraction, 1e-3f) << "the floor's place in its voxel";
        return image;
    };
    const std::vector<float> onFaces = renderAt(0.2f - fraction * voxel, 0.0f),
                             offFaces = renderAt(0.2f + (0.5f - fraction) * voxel, 0.5f);
    int checked = 0;
    for (const reference::NamedRegion& region : regionsOf(original)) {
        if (region.pixels() < 10) continue;
        const double a = lum(reference::maskedMean(onFaces, region.mask)), b = lum(reference::maskedMean(offFaces, region.mask));
        std::printf("%s (%zu px): on faces %.4f, half a voxel off %.4f (%.3f)\n", region.name.c_str(), region.pixels(), a,
                    b, a / b);
        if (region.name != "ceiling" && region.name != "back wall above blocks") continue;
        EXPECT_NEAR(a / b, 1.0, 0.08) << region.name << ": on voxel faces ÷ half a voxel off";
        ++checked;
    }
    EXPECT_EQ(checked, 2) << "ceiling, back wall";
}

// Not met yet (run with --gtest_also_run_disabled_tests; a known gap: docs/GI.md, "Known limits").
// With the fixed six-cone set: the red-wall nook at 0.25-0.33 of the reference, R/G there 5.3-5.5 (ref.
// 2.64), G/R by the green wall 3.19 (ref. 2.46), the regions 13-16 % lower at 128³ than at 64³.
// With the stratified cone sets (this test, 96²): the nook 0.82 and G/R pass; R/G is still too red
// (benchmark 3.37 / 3.33 at 64³ / 128³) and the ceiling and back wall drop 13-14 % from 64³ to
// 128³ (1.09 → 0.95, 1.09 → 0.93 of the reference; 6 % with the grid's ¼-voxel shift:
// IndirectRegionsChangeLittleFrom64To128Voxels).
TEST_F(CornellAccuracy, DISABLED_ColourBleedingAndResolutionIndependence) {
    const Scene scene = loadCornellBox();
    const CornellMeasurement truth = measureReference(scene);
    const std::vector<float> low = vctIndirect(scene, 64), high = vctIndirect(scene, 128);
    for (const reference::NamedRegion& region : truth.regions) {
        if (region.pixels() < 10) continue;
        const glm::dvec3 t = reference::maskedMean(truth.truthIndirect, region.mask);
        const glm::dvec3 a = reference::maskedMean(low, region.mask), b = reference::maskedMean(high, region.mask);
        std::printf("%s: reference %.4f, 64³ %.4f, 128³ %.4f\n", region.name.c_str(), lum(t), lum(a), lum(b));
        EXPECT_NEAR(lum(a) / lum(t), 1.0, 0.20) << region.name;
        EXPECT_NEAR(lum(b) / lum(a), 1.0, 0.10) << region.name << ": 64³ → 128³";
        const bool red = region.name == "shadowed floor by red wall", green = region.name == "shadowed floor by green wall";
        if (red) {
            EXPECT_NEAR((a.r / a.g) / (t.r / t.g), 1.0, 0.20) << "R/G by the red wall";
        }
        if (green) {
            EXPECT_NEAR((a.g / a.r) / (t.g / t.r), 1.0, 0.20) << "G/R by the green wall";
        }
    }
}

// Switching the accurate mode on in a running renderer (the editor's checkbox) without any scene
// change: the directional mip chains, built only while anisotropic voxels are on, must be built
// then, so the image equals a fresh renderer's; they are not allocated in the fast mode and are
// freed when the mode is switched off, and built again when it comes back. A renderer that skipped
// them would trace empty directional volumes (no indirect light). Bar: 0.1 % of the mean, i.e. the
// same image.
TEST_F(GiAccuracy, SwitchingTheAccurateModeOnBuildsTheDirectionalChains) {
    const Scene scene = loadCornellBox();
    RenderSettings accurate = giSettings(64, View::IndirectDiffuse, 48);
    accurate.gi.bounces = 1;
    RenderSettings plain = accurate;
    plain.gi.mode = GiMode::Fast;
    render(scene, plain);
    // The fast mode does not allocate the directional volumes (0.6-1.3 GiB at 512³).
    ASSERT_NE(renderer_->voxels(), nullptr);
    EXPECT_FALSE(static_cast<bool>(renderer_->voxels()->directional(0))) << "directional volumes allocated in the fast mode";
    const std::size_t plainBytes = renderer_->voxels()->radianceBytes();
    // The same renderer and scene (no setScene: that would re-voxelize), only the settings change.
    renderer_->render(scene, cameraFor(scene, accurate), accurate);
    const HdrImage switched{accurate.output.width, accurate.output.height, renderer_->readHdrRgb()};
    EXPECT_TRUE(static_cast<bool>(renderer_->voxels()->directional(0)));
    EXPECT_GT(renderer_->voxels()->radianceBytes(), plainBytes);
    // Switched off again: their memory goes back.
    renderer_->render(scene, cameraFor(scene, plain), plain);
    EXPECT_FALSE(static_cast<bool>(renderer_->voxels()->directional(0))) << "directional volumes kept after the accurate mode was switched off";
    EXPECT_EQ(renderer_->voxels()->radianceBytes(), plainBytes);
    // ... and switching on once more makes and builds them again.
    renderer_->render(scene, cameraFor(scene, accurate), accurate);
    const HdrImage switchedAgain{accurate.output.width, accurate.output.height, renderer_->readHdrRgb()};
    renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
    const HdrImage fresh = render(scene, accurate);
    double difference = 0.0, differenceAgain = 0.0, total = 0.0;
    for (std::size_t i = 0; i < fresh.rgb.size(); ++i) {
        difference += std::abs(double(switched.rgb[i]) - fresh.rgb[i]);
        differenceAgain += std::abs(double(switchedAgain.rgb[i]) - fresh.rgb[i]);
        total += fresh.rgb[i];
    }
    ASSERT_GT(total, 0.0) << "the indirect light must not be black (else the test is vacuous)";
    std::printf("accurate mode switched on vs fresh: mean difference %.4f %% of the mean (on again: %.4f %%)\n",
                100.0 * difference / total, 100.0 * differenceAgain / total);
    EXPECT_LT(difference / total, 0.001);
    EXPECT_LT(differenceAgain / total, 0.001);
}

// Temporal accumulation in the accurate mode, still camera, indirect scale 1 (so no pixel jitter:
// only the cone set's rotation could change between frames). Footprint-bounded cones see along
// their axes, and turning the set every frame, as the fast mode does, makes the result depend
// on the frame (a still camera's L_ID changed 9.6 % from frame to frame; the cornell_inside path
// flickered 5.4 %, 0.4 % with the set fixed). Bar: 0.5 % mean change between
// frames 2 and 3 (with the set fixed they are the same image up to the history blend's rounding).
TEST_F(GiAccuracy, AccurateModeIsStableUnderTemporalAccumulation) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = giSettings(64, View::IndirectDiffuse, 48);
    settings.indirect.temporalAccumulation = true;
    settings.indirect.scale = 1;
    settings.gi.bounces = 1;
    // Whole sets: this test is about the sets' rotation. Cone subsets change the traced pair every
    // frame by design (frame 2 -> 3: 4.7 % with them); their convergence and late frame-to-frame
    // change are IndirectResolve.AccurateConeSubsetsConvergeToTheWholeSets.
    settings.indirect.temporalConeSubsets = false;
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);
    renderer_->render(scene, camera, settings);
    const HdrImage second{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    renderer_->render(scene, camera, settings);
    const HdrImage third{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    double change = 0.0, total = 0.0;
    for (std::size_t i = 0; i < third.rgb.size(); ++i) {
        change += std::abs(double(third.rgb[i]) - second.rgb[i]);
        total += third.rgb[i];
    }
    ASSERT_GT(total, 0.0) << "the indirect light must not be black (else the test is vacuous)";
    std::printf("accurate mode, temporal, still camera: L_ID change frame 2 -> 3 %.3f %%\n", 100.0 * change / total);
    EXPECT_LT(change / total, 0.005);
}

// A closed box whose six inner faces emit E and reflect albedo a, no lights. After b bounces the
// volume holds E·(1 + a + … + a^(b−1)): each bounce's cones see a uniform field (the furnace),
// so a bounce adds exactly a × the previous radiance. That holds for the voxels of the closed box,
// so the means are over the voxels that overlap the box's inside, not over every opaque voxel:
// the planes end on voxel faces in x (the grid is not shifted in x: the box spans x = 2.000 to
// 62.000 voxels), and the conservative rasterization covers the rows a triangle only touches, so
// the four planes along x reach one column past the box at each end (columns 1 and 62; column 62
// also holds the part of the +x plane that rounded to the voxel beyond its face). Their cones see
// the dark outside: 974 of 21930 voxels, 3-bounce mean 1.62 against 1.71 inside. Over every opaque
// voxel the 3-bounce ratio read 1.6965 with voxelize.geom.glsl's kTouchMargin (1.7013 without),
// over the box's voxels 1.7035 (1.7018): docs/GI.md, "Bounces" and "Surfaces on voxel faces".
// Every bounce (kAllBounces) sums the series, E / (1 − a) = 2 E for the ideal transfer. Two bars:
// the passes must stop within 1 % of the limit of the series the first three bounces measure
// (each adds r = 0.474 of the one before, not ½: the cones' transfer; limit 1 + 0.477 / (1 − r)
// in units of E)
// — they stop once the light still missing is estimated below ½ % —, and the sum within 6 % of
// 2 E: the 3 % per-bounce bar compounded over every bounce (measured 0.951 of 2 E, 0.998 of the
// measured series' limit).
TEST_F(GiAccuracy, BouncesAddUpInAClosedEmissiveBox) {
    Scene scene;
    const float albedo = 0.5f;
    const int material = addMaterial(scene, glm::vec3(albedo), 1.0f, 0.0f, "glowing");
    scene.materials[std::size_t(material)].emissiveFactor = glm::vec3(1.0f);
    const float half = 1.0f;
    // Six planes facing inwards (the plane's normal is +Y).
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis)
        for (const float side : {-1.0f, 1.0f}) {
            const glm::vec3 inward = -side * axes[axis];
            const glm::quat rotation(glm::vec3(0, 1, 0), inward);
            addMeshNode(scene, makePlaneMesh("face", 2.0f * half, material), side * half * axes[axis], rotation);
        }
    scene.updateWorldTransforms();
    const CameraView camera = lookAt({0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, -1.0f});
    std::vector<float> means, opaqueMeans;  // the furnace's voxels; every opaque voxel (printed)
    for (const int bounces : {1, 2, 3, kAllBounces}) {
        RenderSettings settings = giSettings(64, View::Final, 32);
        settings.gi.bounces = bounces;
        renderFrom(scene, camera, settings);
        ASSERT_NE(renderer_->voxels(), nullptr);
        const VoxelVolume& volume = *renderer_->voxels();
        const std::vector<glm::vec4> voxels = readRadianceVoxels(volume, 0);
        const int n = volume.resolution();
        // The box [−half, half]³ in voxel coordinates (voxel i spans [i, i + 1)). A voxel belongs to
        // the furnace when it overlaps the box's inside by more than a hair in every axis: one that
        // only touches the box from outside (an edge row) does not, whichever way the face rounds.
        const glm::vec3 lo = (glm::vec3(-half) - volume.minCorner()) / volume.voxelSize();
        const glm::vec3 hi = (glm::vec3(half) - volume.minCorner()) / volume.voxelSize();
        constexpr float kHair = 0.01f;  // voxels
        double sum = 0.0, opaqueSum = 0.0;
        int count = 0, outside = 0;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const glm::vec4& v = voxels[static_cast<std::size_t>(x) +
                                                static_cast<std::size_t>(n) * (y + static_cast<std::size_t>(n) * z)];
                    if (v.a <= 0.5f) continue;
                    opaqueSum += v.g;
                    const glm::vec3 i(x, y, z);
                    if (glm::all(glm::greaterThan(i + 1.0f, lo + kHair)) && glm::all(glm::lessThan(i, hi - kHair)))
                        sum += v.g, ++count;
                    else
                        ++outside;
                }
        means.push_back(float(sum / std::max(count, 1)));
        opaqueMeans.push_back(float(opaqueSum / std::max(count + outside, 1)));
        if (bounces == 1) std::printf("closed box: %d voxels inside, %d opaque voxels outside\n", count, outside);
    }
    std::printf("closed box: mean voxel radiance after 1, 2, 3 bounces: %.4f %.4f %.4f (ratios %.4f, %.4f)\n", means[0],
                means[1], means[2], means[1] / means[0], means[2] / means[0]);
    std::printf("closed box, every opaque voxel: %.4f %.4f %.4f (ratios %.4f, %.4f)\n", opaqueMeans[0], opaqueMeans[1],
                opaqueMeans[2], opaqueMeans[1] / opaqueMeans[0], opaqueMeans[2] / opaqueMeans[0]);
    ASSERT_GT(means[0], 0.5f);
    // 3 %: the 8-bit albedo (0.502) and the cones' 5 % stop opacity, which the tracer renormalizes.
    EXPECT_NEAR(means[1] / means[0], 1.0f + albedo, 0.03f * (1.0f + albedo));
    EXPECT_NEAR(means[2] / means[0], 1.0f + albedo + albedo * albedo, 0.03f * (1.0f + albedo + albedo * albedo));
    const double first = means[1] - means[0], second = means[2] - means[1];
    const double limit = means[0] + first / (1.0 - second / first);
    std::printf(
        "closed box, every bounce: %.4f (ratio %.4f; the ideal series' sum %.4f; the measured series' "
        "limit %.4f)\n",
        means[3], means[3] / means[0], 1.0 / (1.0 - albedo), limit / means[0]);
    EXPECT_NEAR(means[3] / limit, 1.0, 0.01) << "every bounce stopped short of (or past) its own limit";
    EXPECT_NEAR(means[3] / means[0], 1.0f / (1.0f - albedo), 0.06f / (1.0f - albedo));
}

// The cached mode's voxel irradiance (GiSettings::voxelIrradiance(), docs/GI.md, "The gather")
// in the benchmark's sealed room (assets/gi/sealed_room.gltf, its camera, 128², 128³, as
// lit-gi-accuracy): its gather must keep to voxels facing as the pixel does. With (normal
// agreement)² the inside floor's gather read the walls' voxels and let in 1.86×
// the accurate mode's light (8.98e-3 against 4.83e-3 of the ground's radiance); with the 16th power
// 1.00× (4.85e-3), and 0.88× here since rough L_IS comes from the gather too. Bar: no more than
// 1.1× the accurate mode. ~3 s.
TEST_F(GiAccuracy, VoxelIrradianceLeaksNoMoreThanTheAccurateMode) {
    const Scene scene = loadGltf(sourceDir() / "assets" / "gi" / "sealed_room.gltf", log_);
    ASSERT_FALSE(scene.cameras.empty());
    const CameraView inside = sceneCameraView(scene, 0, 1.0f);
    RenderSettings settings = giSettings(128, View::Final, 128);
    const float accurate = luminance(meanOf(renderFrom(scene, inside, settings), 0.0f, 0.0f, 1.0f, 1.0f));
    settings.gi.mode = GiMode::Cached;
    const float gathered = luminance(meanOf(renderFrom(scene, inside, settings), 0.0f, 0.0f, 1.0f, 1.0f));
    std::printf("sealed room at 128³, inside mean: accurate %.3e, voxel irradiance %.3e (%.2f×) W/(sr·m²)\n", accurate,
                gathered, gathered / accurate);
    ASSERT_GT(accurate, 0.0f) << "the accurate mode's leak is the yardstick; 0 would make the test vacuous";
    EXPECT_LE(gathered, 1.1f * accurate);
}

// The voxel irradiance traced over frames (GiBudget::updateVoxels): after a light edit the
// image must show the old light in no voxel once the update has gone round the list, ⌈occupied ÷
// per frame⌉ frames after the last edit: the same image as a renderer that traced every voxel with
// the new light at once; a frame earlier it must still differ (else the test would not see a stale
// voxel). Cornell box, 64³, L_ID, no temporal accumulation (its history would blur the frames
// together). ~2 s.
TEST_F(GiAccuracy, VoxelIrradianceSpreadOverFramesLeavesNoTraceOfTheOldLight) {
    Scene scene = loadCornellBox();
    RenderSettings settings = giSettings(64, View::IndirectDiffuse, 48);
    settings.gi.mode = GiMode::Cached;
    settings.indirect.temporalAccumulation = false;
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);  // all voxels at once (the default, 0)
    const std::uint32_t occupied = renderer_->stats().occupiedVoxels;
    ASSERT_GT(occupied, 1000u);
    constexpr int kFrames = 4;
    const GiBudget budget{static_cast<std::uint32_t>((occupied + kFrames - 1) / kFrames), 0};
    ASSERT_FALSE(scene.lights.empty());
    // A first edit, half done when the second comes: the second's update starts where the first's
    // stands (round robin), so it wraps round the list's end.
    scene.lights[0].intensity *= 0.25f;
    ++scene.lightRevision;
    for (int i = 0; i < kFrames / 2; ++i) renderer_->render(scene, camera, settings, budget);
    scene.lights[0].intensity *= 16.0f;
    scene.lights[0].color = glm::vec3(1.0f, 0.5f, 0.25f);
    ++scene.lightRevision;
    for (int i = 0; i < kFrames - 1; ++i) renderer_->render(scene, camera, settings, budget);
    const HdrImage early{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    renderer_->render(scene, camera, settings, budget);
    const HdrImage converged{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    const HdrImage fresh = allAtOnceInAFreshRenderer(scene, camera, settings);
    const double before = relativeDifference(early, fresh), after = relativeDifference(converged, fresh);
    std::printf(
        "voxel irradiance over %d frames (%u of %u voxels each): L_ID vs all at once after %d frames %.3f %%, "
        "after %d %.5f %%\n",
        kFrames, budget.updateVoxels, occupied, kFrames - 1, 100.0 * before, kFrames, 100.0 * after);
    EXPECT_GT(before, 0.01) << "a frame early some voxels must still hold the old light";
    EXPECT_LE(after, 1e-5);
}

// Bounces 2..N spread over frames as the voxel irradiance is (the cached mode with
// GiBudget::updateVoxels below the list): after a light edit, each bounce takes ⌈occupied ÷ per frame⌉
// frames, then the irradiance as many, and the image is then a renderer's that did all of it in one
// frame; a frame earlier it still differs. Without the spreading every frame of a light drag in the
// editor paid whole bounces (Cornell 128³ with 32 voxel rays: 1.5 s a bounce on llvmpipe). A light
// edit replays the voxel rays' recorded hits, kReplayVoxelsPerFrameFactor times the setting's voxels
// a frame; after a voxelization the bounce records them at the setting's pace, and the irradiance
// then replays them. Cornell box, 64³, two bounces, L_ID, no temporal accumulation. ~4 s.
TEST_F(GiAccuracy, BouncesSpreadOverFramesEndWhereOneFrameEnds) {
    Scene scene = loadCornellBox();
    RenderSettings settings = twoBouncesWithRays();
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);  // everything in the first frame (the default, 0)
    const std::uint32_t occupied = renderer_->stats().occupiedVoxels;
    ASSERT_GT(occupied, 1000u);
    constexpr int kFrames = 3;  // per pass over the list: the bounce's, then the irradiance's
    const GiBudget budget = replayedOver(occupied, kFrames);
    ASSERT_FALSE(scene.lights.empty());
    scene.lights[0].intensity *= 4.0f;
    scene.lights[0].color = glm::vec3(1.0f, 0.5f, 0.25f);
    ++scene.lightRevision;
    // The progress the editor's overlay shows (FrameStats::giUpdateDone, giUpdateStage) rises
    // through the bounce and then the irradiance and reaches 1 with the last frame.
    float progress = 0.0f;
    for (int i = 0; i < 2 * kFrames - 1; ++i) {
        renderer_->render(scene, camera, settings, budget);
        const FrameStats& stats = renderer_->stats();
        EXPECT_GT(stats.giUpdateDone, progress) << "frame " << i;
        EXPECT_LT(stats.giUpdateDone, 1.0f) << "frame " << i;
        EXPECT_EQ(stats.giUpdateStage, i < kFrames - 1 ? "bounce 2" : "irradiance") << "frame " << i;
        progress = stats.giUpdateDone;
    }
    const HdrImage early{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    renderer_->render(scene, camera, settings, budget);
    EXPECT_EQ(renderer_->stats().giUpdateDone, 1.0f);
    EXPECT_EQ(renderer_->stats().giUpdateStage, "") << "no refinement asked for";
    const HdrImage done{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    const HdrImage fresh = allAtOnceInAFreshRenderer(scene, camera, settings);
    const double before = relativeDifference(early, fresh), after = relativeDifference(done, fresh);
    std::printf(
        "two bounces over %d + %d frames (%d × %u of %u voxels each, replayed): L_ID vs all at once after %d "
        "frames %.3f %%, after %d %.5f %%\n",
        kFrames, kFrames, kReplayVoxelsPerFrameFactor, budget.updateVoxels, occupied, 2 * kFrames - 1, 100.0 * before,
        2 * kFrames, 100.0 * after);
    EXPECT_GT(before, 0.01) << "a frame early some voxels must still hold the old light";
    EXPECT_LE(after, 1e-5);

    // A voxelization: the bounce marches and records the hits at the setting's pace, the
    // irradiance replays them at the factor's.
    ++scene.geometryRevision;
    const std::uint32_t perFrame = budget.updateVoxels;
    const int bounceFrames = static_cast<int>((occupied + perFrame - 1) / perFrame);
    int frames = 0;
    do {
        renderer_->render(scene, camera, settings, budget);
        ++frames;
        if (frames == bounceFrames - 1) {
            EXPECT_EQ(renderer_->stats().giUpdateStage, "bounce 2");  // its last frame is next
        }
    } while (renderer_->stats().giUpdateDone < 1.0f && frames < 100);
    std::printf("after a voxelization: %d frames (the bounce %d, recording)\n", frames, bounceFrames);
    EXPECT_EQ(frames, bounceFrames + kFrames);
    const HdrImage revoxelized{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    EXPECT_LE(relativeDifference(revoxelized, fresh), 1e-5);
}

// Every bounce in a room lit through a window (the sun room, 64³, L_ID): bounces after an update's
// first gather the change of the bounce before over one ray in GiSettings::laterBounceRayStride
// (bounce.comp.glsl). That is exact in expectation; the image differs from gathering the light
// over every ray by the subsets' sampling only: measured 0.994 in the mean and 0.63 % per pixel
// with stride 4, against 0.990 and 0.97 % when the change was taken from two half-float sums (the
// later bounces' light was lost where it fell below their rounding). The subsets' error depends on
// the light they gather: 0.998 and 0.40 % before two-sided voxels sent each side its own light
// (voxel.glsl, "Sides"); with them strides 2 and 4 read 0.994, 8 0.991 and 3 0.998, the
// power-of-two strides' subsets sharing their azimuth sectors. Bar: 1 % in the mean. ~3 s.
TEST_F(GiAccuracy, LaterBouncesGatheringTheirChangeEndNearGatheringTheLight) {
    const Scene scene = loadGltf(sourceDir() / "tests" / "data" / "blender" / "sun_room" / "sun_room.gltf", log_);
    RenderSettings settings = cachedAt64();
    settings.gi.bounces = kAllBounces;
    settings.gi.voxelRays = 32;
    settings.indirect.temporalAccumulation = false;
    settings.output.width = 80;
    settings.output.height = 50;
    const CameraView camera = cameraFor(scene, settings);
    settings.gi.laterBounceRayStride = 1;
    const HdrImage whole = allAtOnceInAFreshRenderer(scene, camera, settings);
    settings.gi.laterBounceRayStride = 4;
    const HdrImage changes = allAtOnceInAFreshRenderer(scene, camera, settings);
    const double wholeMean = whole.mean(0, 0, 1, 1).x + whole.mean(0, 0, 1, 1).y + whole.mean(0, 0, 1, 1).z;
    const double changesMean = changes.mean(0, 0, 1, 1).x + changes.mean(0, 0, 1, 1).y + changes.mean(0, 0, 1, 1).z;
    const double difference = relativeDifference(changes, whole);
    std::printf("sun room, every bounce, 64³: L_ID with the changes gathered over 1 ray in 4 ÷ over every ray: mean "
                "%.4f, per pixel %.3f %%\n",
                changesMean / wholeMean, 100.0 * difference);
    ASSERT_GT(wholeMean, 0.0);
    EXPECT_GT(difference, 1e-5) << "the later bounces must have gathered their changes over the subsets";
    EXPECT_NEAR(changesMean / wholeMean, 1.0, 0.01);
    EXPECT_LE(difference, 0.02);
}

// The sun room's rough gold sphere (roughness 0.35) stands in the sun patch on a floor 0.3 m thick,
// 3 voxels at 64³: its lower half reflects the sunlit floor through specular cones that meet the
// floor at a slant, and those read the directional faces that see the floor edge-on. The floor's
// other side lies right behind its top, so those faces leave it out (mipmap_directional.comp.glsl,
// "backed"). While they kept it opaque and dark, the sphere's L_IS read 0.75 of the reference's
// here; now 0.97. Bar: ±20 %, the sun room's per-surface bar. Reference: every bounce, 256 spp at
// the pixel centres; the sphere's pixels one pixel in from its outline. ~5 s.
TEST_F(GiAccuracy, GrazingConesSeeABackedFloorsLight) {
    const Scene scene = loadGltf(sourceDir() / "tests" / "data" / "blender" / "sun_room" / "sun_room.gltf", log_);
    RenderSettings settings;  // the defaults: the cached mode, every bounce
    settings.gi.voxelResolution = 64;
    settings.output.width = 160;
    settings.output.height = 100;
    settings.debug.view = View::IndirectSpecular;
    const CameraView camera = cameraFor(scene, settings);
    Log quiet;
    quiet.setSink(nullptr);
    const reference::ReferenceScene rs(scene, quiet);
    const int width = settings.output.width, height = settings.output.height;
    const std::vector<reference::FirstHit> hits = reference::traceFirstHits(rs, camera, width, height);
    const reference::PixelMask sphere =
        reference::erodeEdges(reference::nodeMask(scene, hits, "gold_sphere"), hits, width, height, 1);
    const std::vector<float> truth =
        tracedAtPixelCentres(rs, camera, width, height, reference::kAllBounces, 256).viewRgb(View::IndirectSpecular, settings);
    const HdrImage vct = render(scene, settings);
    double truthSum = 0.0, vctSum = 0.0;
    std::size_t pixels = 0;
    for (std::size_t i = 0; i < sphere.size(); ++i) {
        if (!sphere[i]) continue;
        truthSum += luminance({truth[3 * i], truth[3 * i + 1], truth[3 * i + 2]});
        vctSum += luminance({vct.rgb[3 * i], vct.rgb[3 * i + 1], vct.rgb[3 * i + 2]});
        ++pixels;
    }
    ASSERT_GT(pixels, 300u) << "the sphere must be in view";
    ASSERT_GT(truthSum, 0.0);
    std::printf("sun room, 64³: the gold sphere's L_IS ÷ the reference's over %zu pixels: %.3f\n", pixels,
                vctSum / truthSum);
    EXPECT_NEAR(vctSum / truthSum, 1.0, 0.2);
}

// Every bounce with RGBA8 radiance stops when its light settles, as with RGBA16F: the change is
// measured between the values the volume stores (bounce.comp.glsl, asStored). Measuring the
// unrounded new light against the rounded old one read the rounding as a steady change, and every
// update ran the 64-bounce cap (the Cornell box here: 64 against RGBA16F's 7; Sponza at 256³, a
// 48 s light edit). ~2 s.
TEST_F(GiAccuracy, Rgba8BouncesStopWhenTheirLightSettles) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = everyBounceWithRays();
    render(scene, settings);
    const int halfFloatBounces = renderer_->stats().giBounces;
    settings.gi.radianceRgba8 = true;
    renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
    const HdrImage rgba8 = render(scene, settings);
    const int rgba8Bounces = renderer_->stats().giBounces;
    std::printf("Cornell box, every bounce, 64³: converged after %d bounces with RGBA8 radiance, %d with RGBA16F\n",
                rgba8Bounces, halfFloatBounces);
    ASSERT_GT(halfFloatBounces, 2);
    EXPECT_LT(rgba8Bounces, kMaxConvergingBounces);
    EXPECT_LE(rgba8Bounces, halfFloatBounces + 4);
    EXPECT_GT(rgba8.mean(0, 0, 1, 1).x, 0.0f) << "the RGBA8 volume must hold the bounced light";
}

// Every bounce spread over frames (the editor's light edit) ends where one frame ends, with the
// later bounces gathering their changes: the spread passes take the same subsets. Cornell box, 64³,
// 3 frames a pass at the replay pace. ~4 s.
TEST_F(GiAccuracy, EveryBounceSpreadOverFramesEndsWhereOneFrameEnds) {
    Scene scene = loadCornellBox();
    const RenderSettings settings = everyBounceWithRays();
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);
    const std::uint32_t occupied = renderer_->stats().occupiedVoxels;
    ASSERT_GT(occupied, 1000u);
    const GiBudget budget = replayedOver(occupied, 3);
    ASSERT_FALSE(scene.lights.empty());
    scene.lights[0].intensity *= 4.0f;
    scene.lights[0].color = glm::vec3(1.0f, 0.5f, 0.25f);
    ++scene.lightRevision;
    int frames = 0;
    do {
        renderer_->render(scene, camera, settings, budget);
        ++frames;
    } while (renderer_->stats().giUpdateDone < 1.0f && frames < 200);
    const HdrImage spread{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    const HdrImage fresh = allAtOnceInAFreshRenderer(scene, camera, settings);
    const double after = relativeDifference(spread, fresh);
    std::printf("every bounce over %d frames: L_ID vs all at once %.6f %%\n", frames, 100.0 * after);
    EXPECT_GT(frames, 9) << "at least three bounces of three frames each";
    EXPECT_LE(after, 1e-5);
}

// A light dragged in the editor: an edit every frame. With two bounces (the default) a spread
// update that started again at each edit would never end its bounce, the irradiance would never run
// and the indirect light would stand still until the drag stopped (L_ID during the drag 0.000 %
// from before it, measured). A light edit lets a running update run on, the voxels not
// traced yet taking the new direct light, and another update follows: the indirect light follows
// the drag a few frames behind, and once the light stops the image is a fresh renderer's. Cornell
// box, 64³, two bounces with voxel rays, 2 frames a pass at the replay pace. ~3 s.
TEST_F(GiAccuracy, LightDragUpdatesTheIndirectLightWhileItLasts) {
    Scene scene = loadCornellBox();
    RenderSettings settings = twoBouncesWithRays();
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);  // everything in the first frame; the rays' hits recorded
    const std::uint32_t occupied = renderer_->stats().occupiedVoxels;
    ASSERT_GT(occupied, 1000u);
    const HdrImage before{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    const GiBudget budget = replayedOver(occupied, 2);  // 2 frames a pass over the list
    ASSERT_FALSE(scene.lights.empty());
    const glm::vec3 white = scene.lights[0].color, orange(1.0f, 0.5f, 0.25f);
    constexpr int kDragFrames = 12;
    double during = 0.0;
    for (int i = 1; i <= kDragFrames; ++i) {
        scene.lights[0].color = glm::mix(white, orange, static_cast<float>(i) / kDragFrames);
        ++scene.lightRevision;
        renderer_->render(scene, camera, settings, budget);
        EXPECT_LT(renderer_->stats().giUpdateDone, 1.0f) << "drag frame " << i;
        if (i == kDragFrames / 2)
            during = relativeDifference(
                HdrImage{settings.output.width, settings.output.height, renderer_->readHdrRgb()}, before);
    }
    int frames = 0;
    while (renderer_->stats().giUpdateDone < 1.0f && frames < 100) {
        renderer_->render(scene, camera, settings, budget);
        ++frames;
    }
    const HdrImage settled{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    const HdrImage fresh = allAtOnceInAFreshRenderer(scene, camera, settings);
    const double after = relativeDifference(settled, fresh), change = relativeDifference(fresh, before);
    std::printf("light drag over %d frames: L_ID after %d frames %.3f %% from before the drag; settled %d frames "
                "after it, %.6f %% from a fresh renderer (the drag changed it %.2f %%)\n",
                kDragFrames, kDragFrames / 2, 100.0 * during, frames, 100.0 * after, 100.0 * change);
    // Half-way through the drag the light went half the way; the indirect light lags an update (4
    // frames here): it shows the light of the first two frames (5.1 % of 38.5 % measured; 0 when
    // each edit restarts the update).
    EXPECT_GT(during, 0.1 * change) << "the indirect light must follow the drag";
    EXPECT_LE(frames, 2 * 2 * 2) << "at most the update under way and one more";
    EXPECT_LE(after, 1e-5);
}

// A light edit while every bounce's update runs (spread; the second edit as bounce 3 starts): the
// bounce after the edit gathers the light whole, and so does the next, whose change holds the step
// of the direct light (gathered over a subset it read 20 % more change and stopped the update two
// bounces early: 3.6 % from a fresh renderer's light; 0.2 % so, 0.35 % gathering every ray in every
// bounce). The update under way then ends on the new light before the one that follows it.
// Cornell box, 64³, 3 frames a pass. ~4 s.
TEST_F(GiAccuracy, ALightEditDuringAChangeBounceEndsOnTheNewLight) {
    Scene scene = loadCornellBox();
    const RenderSettings settings = everyBounceWithRays();
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);
    const GiBudget budget = replayedOver(renderer_->stats().occupiedVoxels, 3);
    ASSERT_FALSE(scene.lights.empty());
    scene.lights[0].intensity *= 4.0f;
    ++scene.lightRevision;
    int frames = 0;
    while (renderer_->stats().giUpdateStage != "bounce 3" && frames < 50) {
        renderer_->render(scene, camera, settings, budget);
        ++frames;
    }
    ASSERT_EQ(renderer_->stats().giUpdateStage, "bounce 3");
    scene.lights[0].color = glm::vec3(1.0f, 0.5f, 0.25f);  // the bounce's first share is traced
    ++scene.lightRevision;
    frames = 0;
    do {
        renderer_->render(scene, camera, settings, budget);
        ++frames;
    } while (!renderer_->stats().giUpdateCompleted && frames < 100);
    const HdrImage ended{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    const HdrImage fresh = allAtOnceInAFreshRenderer(scene, camera, settings);
    const double off = relativeDifference(ended, fresh);
    std::printf("light edited in bounce 3: the update under way ended after %d frames %.3f %% from a fresh "
                "renderer's light\n",
                frames, 100.0 * off);
    EXPECT_LE(off, 0.02);
}

// The cached mode's voxel irradiance is traced with the cone settings (footprint bound, aperture,
// step, trace distance, anisotropic voxels): changing one must trace it again, as a renderer
// started with the new value does. If only bounces > 1 re-traced on such a change, the cached mode
// would keep showing the old settings' light (measured here: 35.9 % of the mean L_ID away from a
// fresh renderer's, against 0 once re-traced). Cornell box, 64³, L_ID. ~2 s.
TEST_F(GiAccuracy, CachedModeTracesTheVoxelIrradianceAgainWhenTheConeSettingsChange) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = cachedAt64();
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    const HdrImage before = renderFrom(scene, camera, settings);
    settings.gi.coneFootprintPerHeight = 0.5f;
    settings.gi.maxTraceDistance = 0.5f;
    const auto [fresh, stale] = againstFreshRenderer(scene, camera, settings);
    const double settingEffect = relativeDifference(before, fresh);
    std::printf("cached mode, footprint 0.25 -> 0.5 and trace distance 1 -> 0.5: L_ID before vs fresh %.3f %%, "
                "after the change vs fresh %.5f %%\n",
                100.0 * settingEffect, 100.0 * stale);
    ASSERT_GT(settingEffect, 0.01) << "the change must alter the light, else the test sees nothing";
    EXPECT_LE(stale, 1e-5);
}

// Switching voxel rays on in a running renderer (GiSettings::voxelRays, the editor's slider)
// must trace the voxel irradiance again with rays, as a renderer started with them does; and a
// different ray count again. Cornell box, 64³, L_ID. ~3 s.
TEST_F(GiAccuracy, CachedModeTracesTheVoxelIrradianceAgainWhenTheVoxelRaysChange) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = cachedAt64();
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    const HdrImage cones = renderFrom(scene, camera, settings);
    for (const int rays : {32, 8}) {
        settings.gi.voxelRays = rays;
        const auto [fresh, stale] = againstFreshRenderer(scene, camera, settings);
        const double settingEffect = relativeDifference(cones, fresh);
        std::printf("cached mode, %d voxel rays: L_ID against the cones' %.3f %%, after the change vs fresh %.5f %%\n", rays,
                    100.0 * settingEffect, 100.0 * stale);
        ASSERT_GT(settingEffect, 0.01) << "rays must change the light, else the test sees nothing";
        EXPECT_LE(stale, 1e-5) << rays << " rays";
    }
}

// The cached mode's refinement (GiBudget::refineVoxels): after the edit's trace (one
// cone set per voxel) 15 more rounds over the voxels, each tracing the next set and averaging it
// in, must leave every voxel with the mean of all 16 sets: the image of the shader variant that
// traces all 16 at once (bounce.comp.glsl with LIT_IRRADIANCE_ALL_SETS 1), both through the same
// voxel filter. Measured (64³, 64², L_ID, mean |difference| ÷ mean): one set per voxel 3.31 %;
// after the 15 rounds 0.27 % (the running mean's rounding in RGBA16F). With the blend
// weight left at 1 (each round replacing the last) it reads 3.11 % and fails. ~8 s.
TEST_F(GiAccuracy, CachedModeRefinementConvergesToAllConeSetsPerVoxel) {
    namespace fs = std::filesystem;
    const Scene scene = loadCornellBox();
    // The cones, and the voxel rays (the default: their sets are offsets of the rays' pattern).
    for (const int rays : {0, 32}) {
        RenderSettings settings = giSettings(64, View::IndirectDiffuse, 64);
        settings.gi.mode = GiMode::Cached;
        settings.gi.voxelRays = rays;
        const GiBudget refining{GiBudget::kAll, 1u << 30};  // every round at once
        renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
        renderer_->setScene(scene);
        const CameraView camera = cameraFor(scene, settings);
        renderer_->render(scene, camera, settings);  // the update alone: one set per voxel
        const HdrImage oneSet{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
        for (int round = 1; round < 16; ++round) renderer_->render(scene, camera, settings, refining);
        const HdrImage refined{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
        renderer_->render(scene, camera, settings, refining);  // nothing left to refine: the same image
        const HdrImage after{settings.output.width, settings.output.height, renderer_->readHdrRgb()};

        // The all-sets variant.
        const BounceShaderVariant variant(sourceDir() / "shaders", "lit_all_sets", "#define LIT_IRRADIANCE_ALL_SETS 1");
        RenderSettings allSetsSettings = settings;
        HdrImage allSets;
        {
            Renderer allSetsRenderer(variant.root, log_);
            allSetsRenderer.setScene(scene);
            allSetsRenderer.render(scene, camera, allSetsSettings);
            allSets = HdrImage{settings.output.width, settings.output.height, allSetsRenderer.readHdrRgb()};
        }

        const double before = relativeDifference(oneSet, allSets), converged = relativeDifference(refined, allSets);
        std::printf("cached mode (%d voxel rays) against all 16 sets per voxel: one set %.3f %%, after 15 refinement "
                    "rounds %.3f %%, a frame later %.5f %% from the refined image\n",
                    rays, 100.0 * before, 100.0 * converged, 100.0 * relativeDifference(after, refined));
        ASSERT_GT(before, 0.01) << "one set per voxel must differ from all 16, else the test sees nothing";
        EXPECT_LE(converged, 0.2 * before) << rays << " voxel rays";
        EXPECT_LE(relativeDifference(after, refined), 1e-6) << "the refinement must stop after 15 rounds";
    }
}

// The voxel rays' hit cache (RayHitCache): the first trace after a voxelization
// records every ray's hit, and the traces after a light edit replay them instead of marching. The
// replayed light must be the marched light exactly: after a light edit; after a move, which
// voxelizes only the changed boxes and marches again only the rays of voxels inside them and the
// rays that cross them before their hits (VoxelChangeTracker, RayHitCache::markChanged; replaying
// the other rays of a voxel the box covers read 1.6 % of L_ID off); and after a move with that
// off, which records
// every hit afresh. Each time the image equals that of the variant that always marches
// (LIT_RAY_HIT_CACHE 0). Without the cache a light edit costs a
// re-voxelization's trace (Sponza 256³: ratio 0.88-1.02, the bar ≤ ¼); with it 0.18-0.23
// (docs/PERFORMANCE.md, "GI update"). Cornell box, 64³, the defaults (two bounces, 32 rays), L_ID.
// ~6 s.
TEST_F(GiAccuracy, VoxelRayHitCacheReplaysTheMarchedLight) {
    Scene scene = loadCornellBox();
    RenderSettings settings = twoBouncesWithRays();
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    const HdrImage before = renderFrom(scene, camera, settings);
    const BounceShaderVariant marching(sourceDir() / "shaders", "lit_ray_hits_off", "#define LIT_RAY_HIT_CACHE 0");
    const auto againstMarching = [&](const char* what, int expectedBoxes) {
        renderer_->render(scene, camera, settings);
        EXPECT_EQ(renderer_->stats().voxelizedBoxes, expectedBoxes) << what;
        const HdrImage cached{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
        Renderer reference(marching.root, log_);
        reference.setScene(scene);
        reference.render(scene, camera, settings);
        const HdrImage marched{settings.output.width, settings.output.height, reference.readHdrRgb()};
        const double difference = relativeDifference(cached, marched), change = relativeDifference(cached, before);
        std::printf("voxel ray hit cache, %s: L_ID against always marching %.6f %%, against before the edits %.2f %%\n", what,
                    100.0 * difference, 100.0 * change);
        EXPECT_GT(change, 0.01) << what << ": the edit must change the light, else the test sees nothing";
        EXPECT_LE(difference, 1e-6) << what;
    };
    ASSERT_FALSE(scene.lights.empty());
    scene.lights[0].intensity *= 2.0f;
    scene.lights[0].color = glm::vec3(1.0f, 0.6f, 0.3f);
    ++scene.lightRevision;
    againstMarching("light edit (hits replayed)", 0);
    const auto moveTallBox = [&](glm::vec3 by) {
        for (Node& node : scene.nodes)
            if (node.name == "tall_box") node.translation += by;
        scene.updateWorldTransforms();
        ++scene.geometryRevision;
    };
    // Move the tall box: the voxels change, so must the hits of the rays that cross them.
    moveTallBox(glm::vec3(0.25f, 0.0f, 0.15f));
    againstMarching("the tall box moved (its boxes voxelized, the rays crossing them marched)", 1);
    moveTallBox(glm::vec3(-0.1f, 0.0f, 0.2f));
    againstMarching("moved again (a second epoch of changed boxes)", 1);
    settings.gi.voxelizeChangesOnly = false;
    moveTallBox(glm::vec3(0.0f, 0.0f, -0.3f));
    againstMarching("moved with changes only off (the whole volume voxelized, every hit recorded)", 0);
}

// The cached mode's low-resolution trace is two programs (ConeTracePass::executeReduced): a gather
// without cone code that marks the texels whose specular lobe needs cones, and a lobe pass over
// those (on llvmpipe the untaken cone code cost the gather 40 % of its time). The split must not
// change the image: against a variant whose gather marks every texel with a specular lobe, so that
// the lobe pass (one program doing it all) computes them all, L_IS and the final image are the same.
// A Cornell box whose walls are 0.25-0.5 rough (lobes between the per-pixel fallback's 0.3 and the
// gathered irradiance's width: the lobe pass's texels), 64³, 96². If the lobe pass did not run, the
// marked texels would hold no L_IS. ~2 s.
TEST_F(GiAccuracy, CachedTraceLobePassEqualsOneProgramForEveryTexel) {
    Scene scene = loadCornellBox();
    for (Material& material : scene.materials)
        material.roughness = material.name == "red" ? 0.5f : (material.name == "green" ? 0.25f : 0.35f);
    RenderSettings settings = cachedAt64();
    settings.output.width = settings.output.height = 96;
    const ShaderVariant everyTexel(sourceDir() / "shaders", "indirect_trace.frag.glsl", "lit_lobes_every_texel",
                                   "#define LIT_LOBES_FOR_EVERY_TEXEL 1");
    for (const View view : {View::IndirectSpecular, View::Final}) {
        settings.debug.view = view;
        renderer_->setScene(scene);
        const CameraView camera = cameraFor(scene, settings);
        const HdrImage split = renderFrom(scene, camera, settings);
        Renderer oneProgram(everyTexel.root, log_);
        oneProgram.setScene(scene);
        oneProgram.render(scene, camera, settings);
        const HdrImage all{settings.output.width, settings.output.height, oneProgram.readHdrRgb()};
        double mean = 0.0;
        for (const float c : all.rgb) mean += c;
        mean /= static_cast<double>(all.rgb.size());
        const double difference = relativeDifference(split, all);
        std::printf("%s: split trace against the lobe pass for every texel %.6f %% (mean %.5f)\n",
                    std::string(toString(view)).c_str(), 100.0 * difference, mean);
        EXPECT_GT(mean, 0.0) << toString(view);
        EXPECT_LE(difference, 1e-6) << toString(view);
    }
}

}  // namespace
}  // namespace lit::test
