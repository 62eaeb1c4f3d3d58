// One GL texture per image, one sampler object per distinct sampler (scene/GpuScene.h): files
// whose many glTF textures share a few images (tests/support/SharedImageScene.h) upload each
// image once, and materials that share an image through different samplers render with their own.

#include "GlTestSupport.h"

#include "../support/SharedImageScene.h"
#include "scene/GpuScene.h"
#include "scene/SceneBuilder.h"
#include "scene/SceneMemory.h"

#include <glm/gtc/matrix_transform.hpp>
#include <shared.h>

#include <chrono>
#include <cstdio>

namespace lit::test {
namespace {

namespace fs = std::filesystem;

class SharedTextures : public GlFixture {
protected:
    fs::path folder() const {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        return outputDir() / "shared_textures" / info->name();
    }
};

// The required bound: a file of 100,000 textures sharing one small image loads and uploads in
// under 2 s (a GL texture per glTF texture would take minutes and gigabytes). About 0.5 s on
// llvmpipe with 2 busy cores; the bound is generous on purpose and is not a benchmark.
TEST_F(SharedTextures, AHundredThousandTexturesOfOneImageUploadOneImageInUnderTwoSeconds) {
    if (HasFatalFailure()) return;
    const fs::path path = lit::testing::writeSharedImageScene(folder(), "many", {100'000, 1, 16, 100});
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = loadGltf(path, log_);
    const GpuScene gpuScene(scene, log_);
    glFinish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("100,000 textures of one 16x16 image: loaded and uploaded in %.3f s\n", seconds);
    EXPECT_EQ(scene.textures.size(), 100'000u);
    EXPECT_EQ(gpuScene.imageTextureCount(), 1u);
    EXPECT_EQ(gpuScene.samplerCount(), 2u) << "the file's two samplers (repeat, clamp)";
    EXPECT_EQ(gpuScene.textureBytes(), textureBytesWithMips(16, 16)) << "one image's memory";
    EXPECT_LT(seconds, 2.0);
}

TEST_F(SharedTextures, AThousandAndThreeTexturesOfThreeImagesMakeThreeGlTextures) {
    if (HasFatalFailure()) return;
    const fs::path path = lit::testing::writeSharedImageScene(folder(), "three", {1003, 3, 32, 50});
    const Scene scene = loadGltf(path, log_);
    const GpuScene gpuScene(scene, log_);
    EXPECT_EQ(gpuScene.imageTextureCount(), 3u);
    EXPECT_EQ(gpuScene.samplerCount(), 2u);
    EXPECT_EQ(gpuScene.textureBytes(), 3 * textureBytesWithMips(32, 32));
    EXPECT_EQ(gpuScene.textureBytes(), estimateSceneMemory(scene, {}).textures)
        << "the budget counts what the upload makes";
    // Every texture the materials use is bound (none fell back to the white texture).
    for (const DrawItem& item : gpuScene.items())
        EXPECT_EQ(gpuScene.materialTextureMask(item) & LIT_MATERIAL_TEXTURE_BASE_COLOR,
                  unsigned(LIT_MATERIAL_TEXTURE_BASE_COLOR));
}

// Two squares side by side, u running 0..2 across each, their materials' base colour textures
// the same 2×1 image (red | green, nearest filtering) through a repeating and a clamping
// sampler. At u = 1.25 the repeating one shows red (u 0.25), the clamping one green (the last
// texel); at u = 0.25 both show red.
TEST_F(SharedTextures, MaterialsSharingAnImageSampleWithTheirOwnSampler) {
    if (HasFatalFailure()) return;
    Scene scene;
    Image image;
    image.name = "red green";
    image.width = 2;
    image.height = 1;
    image.rgba = {255, 0, 0, 255, 0, 255, 0, 255};
    scene.images.push_back(image);
    for (const int wrap : {10497, 33071}) {  // REPEAT, CLAMP_TO_EDGE
        Texture texture;
        texture.image = 0;
        texture.wrapS = texture.wrapT = wrap;
        texture.minFilter = texture.magFilter = 9728;  // NEAREST
        scene.textures.push_back(texture);
        const int material = addMaterial(scene, glm::vec3(1.0f));
        scene.materials[static_cast<std::size_t>(material)].baseColorTexture = material;
        Mesh square = makePlaneMesh("square", 1.0f, material);
        for (Vertex& v : square.primitives[0].vertices) v.uv = {2.0f * (v.position.x + 0.5f), v.position.z + 0.5f};
        addMeshNode(scene, std::move(square), {wrap == 10497 ? -0.6f : 0.6f, 0.0f, 0.0f});
    }
    scene.updateWorldTransforms();

    const GpuScene gpuScene(scene, log_);
    EXPECT_EQ(gpuScene.imageTextureCount(), 1u);
    EXPECT_EQ(gpuScene.samplerCount(), 2u);

    RenderSettings settings = smallSettings(128);
    settings.debug.view = View::Albedo;
    // Looking straight down from 3 m (local −Z turned to −Y).
    const glm::mat4 world = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 3.0f, 0.0f)),
                                        glm::radians(-90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    const CameraView camera = makeCameraView(world, 0.8f, 1.0f, 0.05f, 10.0f);
    renderer_->setScene(scene);
    renderer_->render(scene, camera, settings);
    const HdrImage picture{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
    const auto colourAt = [&](float x) {
        const glm::ivec2 p = projectToPixel(camera, {x, 0.0f, 0.0f}, picture.width, picture.height);
        return windowMean(picture, p.x, p.y, 1);
    };
    const glm::vec3 red(1.0f, 0.0f, 0.0f), green(0.0f, 1.0f, 0.0f);
    const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(0.05f))); };
    // x = −0.6 + (u/2 − 0.5) for the repeating square, +0.6 + ... for the clamping one.
    const glm::vec3 repeatAt025 = colourAt(-0.6f - 0.375f), repeatAt125 = colourAt(-0.6f + 0.125f);
    const glm::vec3 clampAt025 = colourAt(0.6f - 0.375f), clampAt125 = colourAt(0.6f + 0.125f);
    EXPECT_TRUE(near(repeatAt025, red)) << repeatAt025.r << " " << repeatAt025.g << " " << repeatAt025.b;
    EXPECT_TRUE(near(clampAt025, red)) << clampAt025.r << " " << clampAt025.g << " " << clampAt025.b;
    EXPECT_TRUE(near(repeatAt125, red)) << "repeat wraps u 1.25 to 0.25: " << repeatAt125.r << " " << repeatAt125.g;
    EXPECT_TRUE(near(clampAt125, green)) << "clamp holds the last texel: " << clampAt125.r << " " << clampAt125.g;
}

}  // namespace
}  // namespace lit::test
