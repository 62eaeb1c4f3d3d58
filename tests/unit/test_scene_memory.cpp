// The memory accounting every front end checks a scene against (scene/SceneMemory.h): each image
// counts once however many textures use it, the render settings add their volumes and targets,
// and a scene over the limit gets one message with the figures and the limit's source.

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "RenderSettings.h"
#include "gi/RayHitCache.h"
#include "gi/VoxelVolume.h"
#include "scene/Scene.h"
#include "scene/SceneBuilder.h"
#include <shared.h>
#include "scene/SceneMemory.h"

namespace lit {
namespace {

// Restores $LIT_MAX_RENDER_MB after a test that sets it.
class RenderLimitVariable {
public:
    RenderLimitVariable() {
        if (const char* value = std::getenv("LIT_MAX_RENDER_MB")) saved_ = value;
    }
    ~RenderLimitVariable() {
        if (saved_) setenv("LIT_MAX_RENDER_MB", saved_->c_str(), 1);
        else unsetenv("LIT_MAX_RENDER_MB");
    }
    RenderLimitVariable(const RenderLimitVariable&) = delete;
    RenderLimitVariable& operator=(const RenderLimitVariable&) = delete;

private:
    std::optional<std::string> saved_;
};

Scene sceneWithSharedImage(int textures, int side) {
    Scene scene;
    Image image;
    image.width = image.height = side;
    image.rgba.assign(static_cast<std::size_t>(side) * static_cast<std::size_t>(side) * 4, 200);
    scene.images.push_back(image);
    for (int t = 0; t < textures; ++t) {
        Texture texture;
        texture.image = 0;
        texture.wrapS = t % 2 ? 33071 : 10497;
        scene.textures.push_back(texture);
    }
    return scene;
}

TEST(SceneMemory, TextureBytesSumTheWholeMipChain) {
    EXPECT_EQ(textureBytesWithMips(1, 1), 4u);
    EXPECT_EQ(textureBytesWithMips(4, 4), 4u * (16 + 4 + 1));
    EXPECT_EQ(textureBytesWithMips(3, 1), 4u * (3 + 1));
    EXPECT_EQ(textureBytesWithMips(256, 256), 4u * 87381);  // 65536 + 16384 + ... + 1
    EXPECT_EQ(textureBytesWithMips(0, 16), 0u);
}

TEST(SceneMemory, AnImageCountsOnceHoweverManyTexturesShareIt) {
    const SceneMemory one = estimateSceneMemory(sceneWithSharedImage(1, 64), {});
    const SceneMemory many = estimateSceneMemory(sceneWithSharedImage(100'000, 64), {});
    EXPECT_EQ(one.decodedImages, 64u * 64 * 4);
    EXPECT_EQ(one.textures, textureBytesWithMips(64, 64));
    EXPECT_EQ(many.textures, one.textures);
    EXPECT_EQ(many.decodedImages, one.decodedImages);
    EXPECT_EQ(many.total(), one.total());
}

TEST(SceneMemory, AnImageNoTextureUsesIsDecodedButNotUploaded) {
    Scene scene = sceneWithSharedImage(0, 32);
    const SceneMemory memory = estimateSceneMemory(scene, {});
    EXPECT_EQ(memory.decodedImages, 32u * 32 * 4);
    EXPECT_EQ(memory.textures, 0u);
}

TEST(SceneMemory, GeometryCountsTheSceneAndItsGlBuffers) {
    Scene scene;
    Mesh mesh;
    Primitive primitive;
    primitive.vertices.resize(1000);
    primitive.indices.resize(3000);
    mesh.primitives.push_back(primitive);
    scene.meshes.push_back(mesh);
    EXPECT_EQ(estimateSceneMemory(scene, {}).geometry, 2u * (1000 * 56 + 3000 * 4));  // 56-byte vertices
}

TEST(SceneMemory, RenderSettingsAddVoxelsRayHitsAndTargets) {
    RenderSettings settings;
    settings.output.width = 640;
    settings.output.height = 360;
    settings.gi.voxelResolution = 64;
    settings.gi.voxelRays = 16;
    settings.gi.bounces = kAllBounces;
    settings.gi.nearLevels = 0;
    const RenderFootprint footprint = RenderFootprint::of(settings);
    const SceneMemory memory = estimateSceneMemory(Scene{}, footprint);
    EXPECT_EQ(memory.targets, 640u * 360 * 80);
    EXPECT_EQ(memory.voxels, voxelVolumeBytes(64, false, true));
    EXPECT_EQ(memory.rayHits, 64u * 64 * 64 * 2 * 16 * 4);  // every voxel, both sides, 16 rays
    settings.gi.nearLevels = 2;  // two more volumes like it, each with its ray hits
    const SceneMemory near = estimateSceneMemory(Scene{}, RenderFootprint::of(settings));
    EXPECT_EQ(near.voxels, 3 * memory.voxels);
    EXPECT_EQ(near.rayHits, 3 * memory.rayHits);
    settings.gi.nearLevels = 0;
    settings.gi.voxelResolution = 512;
    EXPECT_EQ(estimateSceneMemory(Scene{}, RenderFootprint::of(settings)).rayHits, RayHitCache::kMaxBytes)
        << "the cache allocates no more than its cap";
    settings.gi.enabled = false;
    const SceneMemory noGi = estimateSceneMemory(Scene{}, RenderFootprint::of(settings));
    EXPECT_EQ(noGi.voxels, 0u);
    EXPECT_EQ(noGi.rayHits, 0u);
}

TEST(SceneMemory, ShadowMapsCountEachLightsLayersAndTheSheetsColour) {
    Scene scene;
    const int white = addMaterial(scene, glm::vec3(0.8f), 0.9f, 0.0f, "white");
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), white), glm::vec3(0.0f));
    EXPECT_EQ(shadowCastersOf(scene), (ShadowCasters{.maps2d = 1, .directional = 1}))
        << "no light: the renderer's default sun";
    Light sun, spot, point, quiet;
    sun.type = LightType::Directional;
    spot.type = LightType::Spot;
    point.type = quiet.type = LightType::Point;
    quiet.castsShadow = false;
    for (const Light* light : {&sun, &spot, &point, &point, &quiet}) addLightNode(scene, *light, glm::vec3(0, 3, 0), glm::vec3(0, -1, 0));
    EXPECT_EQ(shadowCastersOf(scene), (ShadowCasters{.maps2d = 2, .cubes = 2, .directional = 1}));
    scene.materials[static_cast<std::size_t>(white)].transmission = 0.5f;
    EXPECT_TRUE(shadowCastersOf(scene).sheets);

    RenderSettings settings;
    settings.shadows.mapSize = 512;
    // Two 2D layers and two cubes of six faces: 4 bytes of depth and 8 of colour per texel; the
    // sun's four cascades: 4 bytes of depth.
    EXPECT_EQ(estimateSceneMemory(scene, RenderFootprint::of(settings)).shadowMaps,
              512u * 512 * (2 + 12) * (4 + 8) + 512u * 512 * 4 * 4);
    settings.shadows.cascades = 2;
    EXPECT_EQ(estimateSceneMemory(scene, RenderFootprint::of(settings)).shadowMaps,
              512u * 512 * (2 + 12) * (4 + 8) + 512u * 512 * 2 * 4);
    settings.shadows.enabled = false;
    EXPECT_EQ(estimateSceneMemory(scene, RenderFootprint::of(settings)).shadowMaps, 0u);
}

TEST(SceneMemory, ShadowMapsStopAtTheLayersTheRendererHas) {
    EXPECT_EQ(shadowMapBytes({.maps2d = 100, .cubes = 100}, 1024),
              1024u * 1024 * (LIT_MAX_SHADOW_2D + 6 * LIT_MAX_SHADOW_CUBE) * 4);
    EXPECT_EQ(shadowMapBytes({.maps2d = 3}, 0), 0u) << "shadows off";
}

TEST(SceneMemory, OverTheLimitNamesTheFiguresLargestFirstAndTheLimit) {
    SceneMemory memory;
    memory.textures = 21'000'000'000;
    memory.decodedImages = 300'000'000;
    memory.geometry = 100'000'000;
    EXPECT_EQ(overMemoryLimit(memory, {8'000'000'000, "LIT_MAX_RENDER_MB"}).value_or("fits"),
              "scene needs 21.4 GB of memory (textures 21.0 GB, decoded images 0.3 GB, geometry 0.1 GB), over the "
              "limit of 8.0 GB (LIT_MAX_RENDER_MB)");
    EXPECT_FALSE(overMemoryLimit(memory, {21'400'000'000, "x"}));
    EXPECT_TRUE(overMemoryLimit(memory, {21'399'999'999, "x"}));
    EXPECT_FALSE(overMemoryLimit(memory, {0, "none"})) << "0 is no limit";
}

TEST(SceneMemory, TheLimitComesFromLitMaxRenderMbOrTheDefault) {
    const RenderLimitVariable restore;
    unsetenv("LIT_MAX_RENDER_MB");
    EXPECT_EQ(renderMemoryLimit().bytes, kDefaultSceneMemoryLimit);
    setenv("LIT_MAX_RENDER_MB", "250", 1);
    EXPECT_EQ(renderMemoryLimit().bytes, 250'000'000u);
    EXPECT_EQ(renderMemoryLimit().source, "LIT_MAX_RENDER_MB");
    for (const char* bad : {"", "0", "abc", "12MB", "-5"}) {
        setenv("LIT_MAX_RENDER_MB", bad, 1);
        EXPECT_EQ(renderMemoryLimit().bytes, kDefaultSceneMemoryLimit) << "'" << bad << "'";
    }
}

}  // namespace
}  // namespace lit
