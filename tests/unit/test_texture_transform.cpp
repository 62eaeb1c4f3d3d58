// KHR_texture_transform (scene/TextureTransform.h): the matrix the extension's reference shader
// builds, read from a texture reference's extension text, and the reference path tracer sampling
// through it (the rasterizer's side: tests/gl/test_shared_textures.cpp).

#include <gtest/gtest.h>

#include "Log.h"
#include "reference/ReferenceScene.h"
#include "scene/SceneBuilder.h"
#include "scene/TextureTransform.h"

#include <numbers>

namespace lit {
namespace {

void expectNear(glm::vec2 actual, glm::vec2 expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-5f);
    EXPECT_NEAR(actual.y, expected.y, 1e-5f);
}

TEST(TextureTransform, WithoutTheExtensionItIsTheIdentity) {
    for (const char* text : {"", "{}", R"({"EXT_other": {}})", "not json", R"({"KHR_texture_transform": 3})"})
        EXPECT_EQ(textureTransformOf(text), TextureTransform{}) << text;
    expectNear(TextureTransform{}.apply({0.3f, 0.7f}), {0.3f, 0.7f});
}

TEST(TextureTransform, OffsetScaleAndRotationAreTheExtensionsMatrix) {
    const float quarter = static_cast<float>(std::numbers::pi / 2);
    expectNear(textureTransformOf(R"({"KHR_texture_transform": {"offset": [0.5, 0]}})").apply({0.25f, 0.5f}),
               {0.75f, 0.5f});
    expectNear(textureTransformOf(R"({"KHR_texture_transform": {"scale": [2, 3]}})").apply({0.5f, 0.5f}), {1.0f, 1.5f});
    // mat3(cos, sin, 0, −sin, cos, 0, 0, 0, 1) · (1, 0, 1): u' = cos = 0, v' = sin = 1.
    const TextureTransform rotated = textureTransformOf(R"({"KHR_texture_transform": {"rotation": 1.5707963}})");
    EXPECT_NEAR(rotated.rotation, quarter, 1e-6f);
    expectNear(rotated.apply({1.0f, 0.0f}), {0.0f, 1.0f});
    expectNear(rotated.apply({0.0f, 1.0f}), {-1.0f, 0.0f});
    // Translation · rotation · scale: scaled first, translated last.
    const TextureTransform all = textureTransformOf(
        R"({"KHR_texture_transform": {"offset": [0.1, 0.2], "rotation": 1.5707963, "scale": [2, 1], "texCoord": 1}})");
    expectNear(all.apply({1.0f, 0.0f}), {0.1f, 2.2f});
    EXPECT_EQ(all.texCoord, 1);
}

TEST(TextureTransform, ValuesOfTheWrongShapeKeepTheirDefaults) {
    const TextureTransform t =
        textureTransformOf(R"({"KHR_texture_transform": {"offset": [1], "scale": "big", "rotation": [1]}})");
    EXPECT_EQ(t, TextureTransform{});
}

TEST(TextureTransform, EachMaterialSlotHasItsOwn) {
    Material m;
    m.textureExtensions[1] = R"({"KHR_texture_transform": {"offset": [0.5, 0.25]}})";
    m.textureExtensions[4] = R"({"KHR_texture_transform": {"scale": [4, 4]}})";
    const std::array<TextureTransform, 5> transforms = materialTextureTransforms(m);
    EXPECT_EQ(transforms[0], TextureTransform{});
    EXPECT_EQ(transforms[1].offset, glm::vec2(0.5f, 0.25f));
    EXPECT_EQ(transforms[4].scale, glm::vec2(4.0f));
}

// The reference samples the base colour through the slot's transform: a 2×1 red | green image,
// at u = 0.25 red, and green once the offset moves it by half the image.
TEST(TextureTransform, TheReferenceSamplesThroughTheTransform) {
    Scene scene;
    Image image;
    image.width = 2;
    image.height = 1;
    image.rgba = {255, 0, 0, 255, 0, 255, 0, 255};
    scene.images.push_back(image);
    Texture texture;
    texture.image = 0;
    texture.magFilter = texture.minFilter = 9728;
    scene.textures.push_back(texture);
    for (const char* extensions : {"", R"({"KHR_texture_transform": {"offset": [0.5, 0]}})"}) {
        const int material = addMaterial(scene, glm::vec3(1.0f));
        scene.materials[static_cast<std::size_t>(material)].baseColorTexture = 0;
        scene.materials[static_cast<std::size_t>(material)].textureExtensions[0] = extensions;
        addMeshNode(scene, makePlaneMesh("square", 1.0f, material), glm::vec3(static_cast<float>(material), 0, 0));
    }
    scene.updateWorldTransforms();
    Log log;
    log.setSink(nullptr);
    const reference::ReferenceScene tracer(scene, log);
    reference::SurfaceHit plain, shifted;
    plain.geometricNormal = shifted.geometricNormal = {0, 1, 0};
    tracer.resolveMaterial(0, {0.25f, 0.5f}, {0, 1, 0}, {1, 0, 0, 1}, true, plain);
    tracer.resolveMaterial(1, {0.25f, 0.5f}, {0, 1, 0}, {1, 0, 0, 1}, true, shifted);
    EXPECT_EQ(plain.baseColor, glm::vec3(1, 0, 0));
    EXPECT_EQ(shifted.baseColor, glm::vec3(0, 1, 0));
}

}  // namespace
}  // namespace lit
