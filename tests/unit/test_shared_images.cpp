// Files whose many textures share a few images (tests/support/SharedImageScene.h): the loader
// decodes each image once and counts it once, refuses a file over the memory limit before it
// decodes anything (with the figures in the message), and a save writes every texture, sampler
// and image back. The GL side (one GL texture per image) is tests/gl/test_shared_textures.cpp.

#include <gtest/gtest.h>

#include "../support/SharedImageScene.h"
#include "TempDir.h"

#include "Log.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/SceneMemory.h"
#include "QuietLog.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace lit {
namespace {

using json = nlohmann::json;

using lit::testing::QuietLog;

struct TempDir : lit::testing::TempDir {
    TempDir() : lit::testing::TempDir("lit_shared_images") {}
};

#define EXPECT_CONTAINS(text, phrase) EXPECT_NE((text).find(phrase), std::string::npos) << (text)

TEST(SharedImages, AHundredThousandTexturesOfOneImageHoldOneImage) {
    TempDir dir;
    const auto path = lit::testing::writeSharedImageScene(dir.path(), "many", {100'000, 1, 4, 10});
    QuietLog log;
    const Scene scene = loadGltf(path, log);
    ASSERT_EQ(scene.textures.size(), 100'000u);
    ASSERT_EQ(scene.images.size(), 1u);
    for (const Texture& texture : scene.textures) ASSERT_EQ(texture.image, 0);
    const SceneMemory memory = estimateSceneMemory(scene, {});
    EXPECT_EQ(memory.decodedImages, 4u * 4 * 4) << "one image's pixels";
    EXPECT_EQ(memory.textures, textureBytesWithMips(4, 4)) << "one image's GL texture";
}

TEST(SharedImages, AThousandAndThreeTexturesOfThreeImagesHoldThreeImages) {
    TempDir dir;
    const auto path = lit::testing::writeSharedImageScene(dir.path(), "three", {1003, 3, 8, 20});
    QuietLog log;
    const Scene scene = loadGltf(path, log);
    ASSERT_EQ(scene.textures.size(), 1003u);
    ASSERT_EQ(scene.images.size(), 3u);
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        EXPECT_EQ(scene.textures[t].image, static_cast<int>(t % 3));
        EXPECT_EQ(scene.textures[t].wrapS, t % 2 ? 33071 : 10497);
    }
    for (const Image& image : scene.images) EXPECT_EQ(image.sameAs, -1);
    EXPECT_EQ(estimateSceneMemory(scene, {}).textures, 3 * textureBytesWithMips(8, 8));
}

TEST(SharedImages, AFileOverTheLimitIsRefusedBeforeDecodingWithItsFigures) {
    TempDir dir;
    // Three 256² images: 0.8 MB decoded, 1.0 MB as GL textures with mips, against 1.5 MB.
    const auto path = lit::testing::writeSharedImageScene(dir.path(), "budget", {1003, 3, 256, 3});
    GltfLoadOptions options;
    options.limits.memoryBudgetBytes = 1'500'000;
    options.limits.memoryBudgetSource = "the test's limit";
    std::vector<std::string> stages;
    options.progress = [&](const LoadProgress& progress) { stages.push_back(progress.stage); };
    QuietLog log;
    std::string message;
    try {
        loadGltf(path, log, options);
        ADD_FAILURE() << "a file over the limit loaded";
    } catch (const SceneLoadError& error) {
        message = error.what();
    }
    EXPECT_CONTAINS(message, "budget.gltf: scene needs 1.8 MB of memory (textures 1.0 MB, decoded images 0.8 MB");
    EXPECT_CONTAINS(message, "over the limit of 1.5 MB (the test's limit)");
    EXPECT_CONTAINS(message, "3 distinct images, the largest image 0 alone 0.3 MB with mipmaps");
    for (const std::string& stage : stages) EXPECT_NE(stage, "images") << "images were decoded before the refusal";

    // With room for the textures, the same file loads.
    options.limits.memoryBudgetBytes = 2'000'000;
    stages.clear();
    EXPECT_EQ(loadGltf(path, log, options).images.size(), 3u);
    EXPECT_NE(std::find(stages.begin(), stages.end(), "images"), stages.end());
}

TEST(SharedImages, TheRenderSettingsPartCountsAgainstTheLoadersLimit) {
    TempDir dir;
    const auto path = lit::testing::writeSharedImageScene(dir.path(), "voxels", {2, 1, 4, 1});
    GltfLoadOptions options;
    options.limits.memoryBudgetBytes = 100'000'000;
    options.limits.memoryBudgetSource = "LIT_MAX_RENDER_MB";
    options.limits.render.voxelResolution = 256;  // ~1.3 GB of volumes
    QuietLog log;
    try {
        loadGltf(path, log, options);
        ADD_FAILURE() << "a render over the limit was accepted";
    } catch (const SceneLoadError& error) {
        const std::string message = error.what();
        EXPECT_CONTAINS(message, "(voxel volumes ");
        EXPECT_CONTAINS(message, "over the limit of 100.0 MB (LIT_MAX_RENDER_MB)");
    }
    options.limits.render.voxelResolution = 64;
    EXPECT_EQ(loadGltf(path, log, options).textures.size(), 2u);
}

TEST(SharedImages, ASaveWritesEveryTextureSamplerAndImage) {
    TempDir dir;
    const auto path = lit::testing::writeSharedImageScene(dir.path(), "save", {1003, 3, 8, 20});
    QuietLog log;
    const Scene scene = loadGltf(path, log);
    const auto saved = dir / "saved.gltf";
    saveGltf(scene, saved);
    const json source = json::parse(lit::testing::readText(path));
    const json written = json::parse(lit::testing::readText(saved));
    ASSERT_EQ(written["textures"].size(), 1003u);
    ASSERT_EQ(written["images"].size(), 3u);
    ASSERT_EQ(written["samplers"].size(), 2u);
    for (std::size_t t = 0; t < 1003; ++t) {
        const json& texture = written["textures"][t];
        EXPECT_EQ(texture["source"], source["textures"][t]["source"]) << "texture " << t;
        EXPECT_EQ(written["samplers"][texture["sampler"].get<std::size_t>()],
                  source["samplers"][source["textures"][t]["sampler"].get<std::size_t>()])
            << "texture " << t;
    }
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(written["images"][i]["uri"], source["images"][i]["uri"]);
    const Scene again = loadGltf(saved, log);
    EXPECT_EQ(again.textures.size(), 1003u);
    EXPECT_EQ(again.images.size(), 3u);
    EXPECT_EQ(estimateSceneMemory(again, {}).textures, 3 * textureBytesWithMips(8, 8));
}

}  // namespace
}  // namespace lit
