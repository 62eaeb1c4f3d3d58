// glTF export (renderer/scene/GltfWriter.cpp): scenes saved with saveGltf and read back with
// loadGltf must come back with every field, and a failed save must leave old files as they were.

#include <gtest/gtest.h>

#include "TempDir.h"
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "Log.h"
#include "animation/CameraPath.h"
#include "animation/CameraPathIO.h"
#include "image/ImageIO.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/SceneBuilder.h"

namespace lit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr float kTolerance = 1e-6f;

// A folder of its own per test, removed afterwards.
struct TempDir : lit::testing::TempDir {
    TempDir() : lit::testing::TempDir("lit_gltf_writer") {}
};

using testing::filesIn;
using testing::readFile;

json readJson(const fs::path& path) {
    std::ifstream in(path);
    return json::parse(in);
}

// A generated image with a recognisable pattern (no uri: it must be embedded).
Image patternImage(const std::string& name, int width, int height, int seed) {
    Image image;
    image.name = name;
    image.width = width;
    image.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c)
                image.rgba.push_back(static_cast<std::uint8_t>((x * 37 + y * 91 + c * 53 + seed * 17) % 256));
    return image;
}

CameraPath threeKeyPath() {
    return CameraPath({{0.0f, {0.0f, 1.0f, 5.0f}, glm::angleAxis(0.1f, glm::vec3(0, 1, 0)), 0.7f},
                       {1.5f, {2.0f, 1.5f, 4.0f}, glm::angleAxis(0.6f, glm::normalize(glm::vec3(0.2f, 1, 0))), 0.6f},
                       {4.0f, {3.0f, 2.0f, 1.0f}, glm::angleAxis(1.2f, glm::vec3(0, 1, 0)), 0.9f}},
                      {false, true, false});
}

// Every kind of thing the writer has to carry, with values that differ from the defaults.
Scene everythingScene() {
    Scene scene;
    scene.name = "everything";
    scene.images.push_back(patternImage("albedo", 4, 3, 1));
    scene.images.push_back(patternImage("orm", 2, 5, 2));
    scene.images.push_back(patternImage("normal", 3, 3, 3));
    scene.textures.push_back(Texture{0, 10497, 10497, 9987, 9729});
    scene.textures.push_back(Texture{1, 33071, 33648, 9728, 9728});  // clamp / mirror, nearest
    scene.textures.push_back(Texture{2, 33648, 33071, 9985, 9729});

    addMaterial(scene, {0.8f, 0.7f, 0.6f}, 0.9f, 0.0f, "textured");
    scene.materials[0].baseColorTexture = 0;

    Material every;
    every.name = "every field";
    every.baseColorFactor = {0.2f, 0.4f, 0.6f, 0.8f};
    every.baseColorTexture = 0;
    every.metallic = 0.3f;
    every.roughness = 0.45f;
    every.metallicRoughnessTexture = 1;
    every.normalTexture = 2;
    every.normalScale = 0.5f;
    every.emissiveFactor = {1.0f, 0.5f, 0.25f};
    every.emissiveStrength = 4.0f;
    every.emissiveTexture = 0;
    every.occlusionTexture = 1;
    every.occlusionStrength = 0.6f;
    every.alphaMode = AlphaMode::Mask;
    every.alphaCutoff = 0.3f;
    every.doubleSided = true;
    scene.materials.push_back(every);
    addMaterial(scene, {0.1f, 0.9f, 0.1f}, 0.2f, 1.0f, "blend");
    scene.materials[2].alphaMode = AlphaMode::Blend;

    // A nested hierarchy: parent → child (box) → grandchild (plane), plus a root box.
    scene.meshes.push_back(makeBoxMesh("box", {1.0f, 2.0f, 0.5f}, 0));
    scene.meshes.push_back(makePlaneMesh("plane", 3.0f, 1, 2));
    scene.meshes.push_back(makeBoxMesh("blend box", {0.3f, 0.3f, 0.3f}, 2));
    Node parent;
    parent.name = "parent";
    parent.translation = {1.0f, -2.0f, 3.5f};
    parent.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
    parent.scale = {2.0f, 0.5f, 1.5f};
    parent.children = {1};
    Node child;
    child.name = "child";
    child.parent = 0;
    child.mesh = 0;
    child.translation = {-0.25f, 0.5f, 0.0f};
    child.rotation = glm::angleAxis(-1.1f, glm::vec3(0.0f, 0.0f, 1.0f));
    child.children = {2};
    Node grandchild;
    grandchild.name = "grandchild";
    grandchild.parent = 1;
    grandchild.mesh = 1;
    grandchild.scale = {0.5f, 0.5f, 0.5f};
    Node blendBox;
    blendBox.name = "blend box";
    blendBox.mesh = 2;
    blendBox.translation = {0.0f, 0.0f, -2.0f};
    scene.nodes = {parent, child, grandchild, blendBox};
    scene.roots = {0, 3};

    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.color = {1.0f, 0.9f, 0.7f};
    sun.intensity = 3.5f;
    sun.castsShadow = false;
    addLightNode(scene, sun, {0.0f, 10.0f, 0.0f}, {0.3f, -1.0f, 0.2f});
    Light bulb;
    bulb.name = "bulb";
    bulb.type = LightType::Point;
    bulb.color = {0.2f, 0.4f, 1.0f};
    bulb.intensity = 42.0f;
    bulb.range = 12.5f;
    bulb.castsShadow = false;
    addLightNode(scene, bulb, {1.0f, 2.0f, 3.0f}, {0.0f, -1.0f, 0.0f});
    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    spot.color = {1.0f, 0.1f, 0.1f};
    spot.intensity = 250.0f;
    spot.range = 30.0f;
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.6f;
    spot.castsShadow = false;
    addLightNode(scene, spot, {-1.0f, 3.0f, 0.5f}, {0.1f, -1.0f, -0.3f});
    Light shadowed = bulb;
    shadowed.name = "shadowed";
    shadowed.castsShadow = true;
    addLightNode(scene, shadowed, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f});

    Camera camera;
    camera.name = "main camera";
    camera.yfov = 0.6f;
    camera.aspectRatio = 1.5f;
    camera.znear = 0.1f;
    camera.zfar = 250.0f;
    addCameraNode(scene, camera, {0.0f, 2.0f, 8.0f}, {0.0f, 0.0f, 0.0f});
    Camera fitted;  // zfar and aspect 0: "fitted" / "the output's aspect"
    fitted.name = "fitted";
    fitted.yfov = 1.1f;
    fitted.znear = 0.02f;
    addCameraNode(scene, fitted, {5.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    scene.updateWorldTransforms();
    return scene;
}

void expectVec(const glm::vec2& a, const glm::vec2& b, const std::string& what) {
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(a[i], b[i], kTolerance) << what << "[" << i << "]";
}
void expectVec(const glm::vec3& a, const glm::vec3& b, const std::string& what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], kTolerance) << what << "[" << i << "]";
}
void expectVec(const glm::vec4& a, const glm::vec4& b, const std::string& what) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], kTolerance) << what << "[" << i << "]";
}

// Field by field; the loader's only additions are world transforms, bounds and image srgb flags.
void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.name, b.name);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        const Node &x = a.nodes[i], &y = b.nodes[i];
        const std::string what = "node " + std::to_string(i) + " " + x.name;
        EXPECT_EQ(x.name, y.name) << what;
        EXPECT_EQ(x.parent, y.parent) << what;
        EXPECT_EQ(x.children, y.children) << what;
        EXPECT_EQ(x.mesh, y.mesh) << what;
        EXPECT_EQ(x.light, y.light) << what;
        EXPECT_EQ(x.camera, y.camera) << what;
        expectVec(x.translation, y.translation, what + " translation");
        // q and −q are the same rotation.
        const float sign = glm::dot(x.rotation, y.rotation) < 0.0f ? -1.0f : 1.0f;
        expectVec(glm::vec4(x.rotation.x, x.rotation.y, x.rotation.z, x.rotation.w),
                  sign * glm::vec4(y.rotation.x, y.rotation.y, y.rotation.z, y.rotation.w), what + " rotation");
        expectVec(x.scale, y.scale, what + " scale");
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(x.world[c][r], y.world[c][r], 1e-5f) << what << " world";
    }
    EXPECT_EQ(a.roots, b.roots);

    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t m = 0; m < a.meshes.size(); ++m) {
        EXPECT_EQ(a.meshes[m].name, b.meshes[m].name);
        ASSERT_EQ(a.meshes[m].primitives.size(), b.meshes[m].primitives.size()) << a.meshes[m].name;
        for (std::size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
            const Primitive &x = a.meshes[m].primitives[p], &y = b.meshes[m].primitives[p];
            const std::string what = a.meshes[m].name + " primitive " + std::to_string(p);
            EXPECT_EQ(x.material, y.material) << what;
            EXPECT_EQ(x.indices, y.indices) << what;
            ASSERT_EQ(x.vertices.size(), y.vertices.size()) << what;
            for (std::size_t v = 0; v < x.vertices.size(); ++v) {
                const std::string vertex = what + " vertex " + std::to_string(v);
                expectVec(x.vertices[v].position, y.vertices[v].position, vertex + " position");
                expectVec(x.vertices[v].normal, y.vertices[v].normal, vertex + " normal");
                expectVec(x.vertices[v].uv, y.vertices[v].uv, vertex + " uv");
                expectVec(x.vertices[v].tangent, y.vertices[v].tangent, vertex + " tangent");
            }
            expectVec(x.bounds.min, y.bounds.min, what + " bounds min");
            expectVec(x.bounds.max, y.bounds.max, what + " bounds max");
        }
    }

    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        const Material &x = a.materials[i], &y = b.materials[i];
        const std::string what = "material " + x.name;
        EXPECT_EQ(x.name, y.name);
        expectVec(x.baseColorFactor, y.baseColorFactor, what + " baseColorFactor");
        EXPECT_EQ(x.baseColorTexture, y.baseColorTexture) << what;
        EXPECT_NEAR(x.metallic, y.metallic, kTolerance) << what;
        EXPECT_NEAR(x.roughness, y.roughness, kTolerance) << what;
        EXPECT_EQ(x.metallicRoughnessTexture, y.metallicRoughnessTexture) << what;
        EXPECT_EQ(x.normalTexture, y.normalTexture) << what;
        EXPECT_NEAR(x.normalScale, y.normalScale, kTolerance) << what;
        expectVec(x.emissiveFactor, y.emissiveFactor, what + " emissiveFactor");
        EXPECT_NEAR(x.emissiveStrength, y.emissiveStrength, kTolerance) << what;
        EXPECT_EQ(x.emissiveTexture, y.emissiveTexture) << what;
        EXPECT_EQ(x.occlusionTexture, y.occlusionTexture) << what;
        EXPECT_NEAR(x.occlusionStrength, y.occlusionStrength, kTolerance) << what;
        EXPECT_EQ(x.alphaMode, y.alphaMode) << what;
        EXPECT_NEAR(x.alphaCutoff, y.alphaCutoff, kTolerance) << what;
        EXPECT_EQ(x.doubleSided, y.doubleSided) << what;
    }

    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (std::size_t i = 0; i < a.textures.size(); ++i) {
        EXPECT_EQ(a.textures[i].image, b.textures[i].image) << "texture " << i;
        EXPECT_EQ(a.textures[i].wrapS, b.textures[i].wrapS) << "texture " << i;
        EXPECT_EQ(a.textures[i].wrapT, b.textures[i].wrapT) << "texture " << i;
        EXPECT_EQ(a.textures[i].minFilter, b.textures[i].minFilter) << "texture " << i;
        EXPECT_EQ(a.textures[i].magFilter, b.textures[i].magFilter) << "texture " << i;
    }
    ASSERT_EQ(a.images.size(), b.images.size());
    for (std::size_t i = 0; i < a.images.size(); ++i) {
        EXPECT_EQ(a.images[i].name, b.images[i].name) << "image " << i;
        EXPECT_EQ(a.images[i].width, b.images[i].width) << "image " << i;
        EXPECT_EQ(a.images[i].height, b.images[i].height) << "image " << i;
        EXPECT_TRUE(a.images[i].rgba == b.images[i].rgba) << "image " << i << " pixels differ";
    }

    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        const Light &x = a.lights[i], &y = b.lights[i];
        const std::string what = "light " + x.name;
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.type, y.type) << what;
        expectVec(x.color, y.color, what + " color");
        EXPECT_NEAR(x.intensity, y.intensity, kTolerance) << what;
        EXPECT_NEAR(x.range, y.range, kTolerance) << what;
        if (x.type == LightType::Spot) {
            EXPECT_NEAR(x.innerConeAngle, y.innerConeAngle, kTolerance) << what;
            EXPECT_NEAR(x.outerConeAngle, y.outerConeAngle, kTolerance) << what;
        }
        EXPECT_EQ(x.castsShadow, y.castsShadow) << what;
    }

    ASSERT_EQ(a.cameras.size(), b.cameras.size());
    for (std::size_t i = 0; i < a.cameras.size(); ++i) {
        const Camera &x = a.cameras[i], &y = b.cameras[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_NEAR(x.yfov, y.yfov, kTolerance) << x.name;
        EXPECT_NEAR(x.aspectRatio, y.aspectRatio, kTolerance) << x.name;
        EXPECT_NEAR(x.znear, y.znear, kTolerance) << x.name;
        EXPECT_NEAR(x.zfar, y.zfar, kTolerance) << x.name;
    }
}

void expectSamePath(const CameraPath& a, const CameraPath& b) {
    EXPECT_EQ(a.options(), b.options());
    ASSERT_EQ(a.keys().size(), b.keys().size());
    for (std::size_t i = 0; i < a.keys().size(); ++i) {
        const CameraKey &x = a.keys()[i], &y = b.keys()[i];
        EXPECT_NEAR(x.time, y.time, kTolerance) << "key " << i;
        expectVec(x.position, y.position, "key " + std::to_string(i) + " position");
        expectVec(glm::vec4(x.rotation.x, x.rotation.y, x.rotation.z, x.rotation.w),
                  glm::vec4(y.rotation.x, y.rotation.y, y.rotation.z, y.rotation.w),
                  "key " + std::to_string(i) + " rotation");
        EXPECT_NEAR(x.yfov, y.yfov, kTolerance) << "key " << i;
    }
}

std::string saveError(const Scene& scene, const fs::path& file, const GltfSaveOptions& options = {}) {
    try {
        saveGltf(scene, file, options);
    } catch (const SceneSaveError& e) {
        return e.what();
    }
    return "(no error)";
}

// ---- round trips -----------------------------------------------------------------------------

TEST(GltfWriter, GltfRoundTripKeepsEveryField) {
    TempDir dir;
    const Scene scene = everythingScene();
    const CameraPath path = threeKeyPath();
    GltfSaveOptions options;
    options.cameraPath = &path;
    options.cameraPathName = "fly through";
    const fs::path file = dir / "everything.gltf";
    saveGltf(scene, file, options);

    // A .gltf and its one .bin, nothing else (no temporaries left behind).
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"everything.gltf", "everything.bin"}));
    const json doc = readJson(file);
    EXPECT_EQ(doc.at("asset").at("version"), "2.0");
    ASSERT_EQ(doc.at("buffers").size(), 1u);
    EXPECT_EQ(doc.at("buffers")[0].at("uri"), "everything.bin");
    EXPECT_EQ(doc.at("buffers")[0].at("byteLength").get<std::uintmax_t>(), fs::file_size(dir / "everything.bin"));
    const auto used = doc.at("extensionsUsed").get<std::vector<std::string>>();
    EXPECT_EQ(std::set<std::string>(used.begin(), used.end()),
              (std::set<std::string>{"KHR_lights_punctual", "KHR_materials_emissive_strength"}));
    EXPECT_FALSE(doc.contains("extensionsRequired"));
    // Generated images are embedded PNGs; an infinite far plane is written as no zfar.
    for (const json& image : doc.at("images")) {
        EXPECT_EQ(image.at("mimeType"), "image/png");
        EXPECT_TRUE(image.contains("bufferView"));
    }
    EXPECT_FALSE(doc.at("cameras")[1].at("perspective").contains("zfar"));
    EXPECT_FALSE(doc.at("cameras")[1].at("perspective").contains("aspectRatio"));
    EXPECT_EQ(doc.at("extensions").at("KHR_lights_punctual").at("lights")[3].count("extras"), 0u);

    Log log;
    const Scene loaded = loadGltf(file, log);
    EXPECT_EQ(log.countAtLeast(LogLevel::Warning), 0u);
    expectSameScene(scene, loaded);
    expectSamePath(path, loadCameraPathFromGltf(file, "fly through"));
}

TEST(GltfWriter, GlbRoundTripKeepsEveryFieldInOneFile) {
    TempDir dir;
    const Scene scene = everythingScene();
    const CameraPath path = threeKeyPath();
    GltfSaveOptions options;
    options.cameraPath = &path;
    const fs::path file = dir / "everything.glb";
    saveGltf(scene, file, options);
    EXPECT_EQ(filesIn(dir.path()), std::set<std::string>{"everything.glb"});
    const std::vector<std::uint8_t> bytes = readFile(file);
    ASSERT_GE(bytes.size(), 12u);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "glTF");
    EXPECT_EQ(bytes.size() % 4, 0u);

    Log log;
    const Scene loaded = loadGltf(file, log);
    EXPECT_EQ(log.countAtLeast(LogLevel::Warning), 0u);
    expectSameScene(scene, loaded);
    expectSamePath(path, loadCameraPathFromGltf(file, kDefaultCameraAnimation));
}

TEST(GltfWriter, SavingAgainGivesTheSameScene) {
    // Load → save → load → save: the second save reads what the first wrote.
    TempDir dir;
    saveGltf(everythingScene(), dir / "first.gltf");
    Log log;
    const Scene first = loadGltf(dir / "first.gltf", log);
    saveGltf(first, dir / "second.glb");
    expectSameScene(first, loadGltf(dir / "second.glb", log));
}

// A scene with nothing in it (every node deleted in the editor) is saved as a file that loads:
// tinygltf writes a scene without nodes or name as null, which no loader reads back.
TEST(GltfWriter, AnEmptySceneSavesAsAFileThatLoads) {
    TempDir dir;
    for (const char* name : {"empty.gltf", "empty.glb"}) {
        saveGltf(Scene{}, dir / name);
        Log log;
        const Scene loaded = loadGltf(dir / name, log);
        EXPECT_TRUE(loaded.nodes.empty()) << name;
    }
    std::ifstream in(dir / "empty.gltf");
    const nlohmann::json json = nlohmann::json::parse(in);
    ASSERT_TRUE(json.contains("scenes"));
    EXPECT_TRUE(json["scenes"][0].is_object());
}

TEST(GltfWriter, CameraPathWithoutACameraAddsOne) {
    TempDir dir;
    Scene scene;
    addMaterial(scene, glm::vec3(0.5f));
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), 0), glm::vec3(0.0f));
    const CameraPath path = threeKeyPath();
    GltfSaveOptions options;
    options.cameraPath = &path;
    saveGltf(scene, dir / "box.gltf", options);
    Log log;
    const Scene loaded = loadGltf(dir / "box.gltf", log);
    ASSERT_EQ(loaded.cameras.size(), 1u);
    EXPECT_NE(loaded.nodeOfCamera(0), -1);
    expectSamePath(path, loadCameraPathFromGltf(dir / "box.gltf", kDefaultCameraAnimation));
}

TEST(GltfWriter, CornellBoxEditsSurviveTheRoundTrip) {
    TempDir dir;
    Log log;
    const fs::path source = fs::path(LIT_SOURCE_DIR) / "assets" / "cornell_box.gltf";
    const Scene original = loadGltf(source, log);
    Scene edited = original;
    ASSERT_FALSE(edited.lights.empty());
    ASSERT_GE(edited.materials.size(), 2u);
    ASSERT_GE(edited.nodes.size(), 6u);
    edited.lights[0].color = {1.0f, 0.5f, 0.25f};
    edited.materials[1].roughness = 0.123f;
    edited.nodes[5].translation += glm::vec3(0.1f, 0.2f, -0.3f);
    edited.updateWorldTransforms();

    const fs::path file = dir / "out" / "edited cornell.gltf";  // a new folder and a space in the name
    saveGltf(edited, file);
    EXPECT_TRUE(fs::exists(dir / "out" / "edited cornell.bin"));
    EXPECT_EQ(readJson(file).at("buffers")[0].at("uri"), "edited%20cornell.bin");
    const Scene loaded = loadGltf(file, log);
    expectVec(loaded.lights[0].color, {1.0f, 0.5f, 0.25f}, "light colour");
    EXPECT_NEAR(loaded.materials[1].roughness, 0.123f, kTolerance);
    expectVec(loaded.nodes[5].translation, original.nodes[5].translation + glm::vec3(0.1f, 0.2f, -0.3f),
              "node translation");
    EXPECT_EQ(loaded.meshes.size(), original.meshes.size());
    EXPECT_EQ(loaded.triangleCount(), original.triangleCount());
    expectSameScene(edited, loaded);
    // The source is untouched.
    EXPECT_EQ(loadGltf(source, log).lights[0].color, original.lights[0].color);
}

TEST(GltfWriter, ImagesFromFilesAreReferencedFromTheNewFolder) {
    TempDir dir;
    // A scene in src/ whose image 0 came from "src/my textures/albedo 1.png" and whose image 1
    // came from a file that is gone; saved into out/deeper/.
    Scene scene = everythingScene();
    scene.sourcePath = dir / "src" / "scene.gltf";
    writePng(dir / "src" / "my textures" / "albedo 1.png", scene.images[0].width, scene.images[0].height,
             scene.images[0].rgba, /*flipVertically=*/false);
    scene.images[0].uri = "my%20textures/albedo%201.png";
    scene.images[1].uri = "missing.png";

    const fs::path file = dir / "out" / "deeper" / "saved.gltf";
    saveGltf(scene, file);
    const json doc = readJson(file);
    EXPECT_EQ(doc.at("images")[0].at("uri"), "../../src/my%20textures/albedo%201.png");
    EXPECT_FALSE(doc.at("images")[0].contains("bufferView"));
    EXPECT_FALSE(doc.at("images")[1].contains("uri"));  // embedded instead
    EXPECT_EQ(doc.at("images")[1].at("mimeType"), "image/png");
    EXPECT_EQ(filesIn(dir / "out" / "deeper"), (std::set<std::string>{"saved.gltf", "saved.bin"}));

    Log log;
    const Scene loaded = loadGltf(file, log);
    EXPECT_EQ(log.countAtLeast(LogLevel::Warning), 0u);
    ASSERT_EQ(loaded.images.size(), scene.images.size());
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(loaded.images[i].width, scene.images[i].width) << i;
        EXPECT_TRUE(loaded.images[i].rgba == scene.images[i].rgba) << "image " << i;
    }

    // Saved beside the texture's folder, the reference is a plain relative path again.
    saveGltf(loaded, dir / "src" / "beside.glb");
    const Scene beside = loadGltf(dir / "src" / "beside.glb", log);
    EXPECT_EQ(log.countAtLeast(LogLevel::Warning), 0u);
    EXPECT_EQ(beside.images[0].uri, "my%20textures/albedo%201.png");
    EXPECT_TRUE(beside.images[0].rgba == scene.images[0].rgba);
}

// ---- failures --------------------------------------------------------------------------------

TEST(GltfWriterErrors, TargetIsAFolderOrUnderAFile) {
    TempDir dir;
    const Scene scene = everythingScene();
    fs::create_directories(dir / "taken.gltf");
    const std::string folder = saveError(scene, dir / "taken.gltf");
    EXPECT_EQ(folder, (dir / "taken.gltf").string() + ": is a folder, not a file");

    std::ofstream(dir / "plain.txt") << "a file, not a folder";
    const std::string underFile = saveError(scene, dir / "plain.txt" / "scene.glb");
    EXPECT_EQ(underFile.rfind((dir / "plain.txt" / "scene.glb").string() + ": ", 0), 0u) << underFile;
    EXPECT_NE(underFile.find("is a file, not a folder"), std::string::npos) << underFile;

    EXPECT_EQ(saveError(scene, dir / "scene.obj"),
              (dir / "scene.obj").string() + ": cannot save as '.obj'; the file name must end in .gltf or .glb");
    // Nothing was left behind.
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"taken.gltf", "plain.txt"}));
    EXPECT_TRUE(fs::is_empty(dir / "taken.gltf"));
}

TEST(GltfWriterErrors, AFailedSaveLeavesThePreviousFilesByteIdentical) {
    TempDir dir;
    const fs::path file = dir / "scene.gltf";
    Scene scene = everythingScene();
    saveGltf(scene, file);
    const std::vector<std::uint8_t> gltfBefore = readFile(file);
    const std::vector<std::uint8_t> binBefore = readFile(dir / "scene.bin");

    // The .bin's name is taken by a folder: the save fails partway (after the .bin's temporary).
    scene.lights[0].intensity = 99.0f;
    fs::rename(dir / "scene.bin", dir / "scene.bin.kept");
    fs::create_directories(dir / "scene.bin");
    const std::string error = saveError(scene, file);
    EXPECT_EQ(error.rfind(file.string() + ": ", 0), 0u) << error;
    EXPECT_NE(error.find((dir / "scene.bin").string() + ": is a folder, not a file"), std::string::npos) << error;
    EXPECT_EQ(readFile(file), gltfBefore);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"scene.gltf", "scene.bin", "scene.bin.kept"}));
    fs::remove(dir / "scene.bin");
    fs::rename(dir / "scene.bin.kept", dir / "scene.bin");
    EXPECT_EQ(readFile(dir / "scene.bin"), binBefore);

    // A scene that cannot be written (a dangling index) fails before any file is touched.
    scene.nodes[0].mesh = 17;
    EXPECT_EQ(saveError(scene, file),
              file.string() + ": node 0 ('parent') refers to mesh 17, which does not exist (the scene has 3)");
    EXPECT_EQ(readFile(file), gltfBefore);
    EXPECT_EQ(readFile(dir / "scene.bin"), binBefore);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"scene.gltf", "scene.bin"}));
}

TEST(GltfWriterErrors, BadScenesAreNamedPrecisely) {
    TempDir dir;
    const fs::path file = dir / "bad.glb";
    {
        Scene scene = everythingScene();
        scene.nodes[2].children = {0};  // grandchild → parent: a cycle
        EXPECT_EQ(saveError(scene, file),
                  file.string() + ": node 0 ('parent') is reached twice from the roots (a cycle, or a node with two "
                                  "parents)");
    }
    {
        Scene scene = everythingScene();
        scene.materials[1].normalTexture = 5;
        EXPECT_EQ(saveError(scene, file), file.string() +
                                              ": material 1 ('every field') refers to texture 5, which does not "
                                              "exist (the scene has 3)");
    }
    {
        Scene scene = everythingScene();
        scene.meshes[0].primitives[0].indices.back() = 1000;
        EXPECT_EQ(saveError(scene, file), file.string() +
                                              ": mesh 'box' primitive 0 has the index 1000, which is out of range "
                                              "(24 vertices)");
    }
    {
        Scene scene = everythingScene();
        scene.images[1].rgba.resize(3);
        const std::string error = saveError(scene, file);
        EXPECT_EQ(error.rfind(file.string() + ": image 1 ('orm') cannot be embedded: ", 0), 0u) << error;
    }
    {
        Scene scene = everythingScene();
        scene.lights[1].intensity = std::nanf("");
        EXPECT_EQ(saveError(scene, file),
                  file.string() + ": light 1 ('bulb')'s intensity is not a finite number");
    }
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

// ---- a real scene ----------------------------------------------------------------------------

TEST(GltfWriterRealScenes, SponzaRoundTrip) {
    const fs::path source = fs::path(LIT_SOURCE_DIR) / ".." / "shared" / "scenes" / "sponza" / "Sponza.gltf";
    if (!fs::exists(source)) GTEST_SKIP() << "Sponza not available at " << source << "; skipping its round trip";
    TempDir dir;
    Log log;
    const Scene original = loadGltf(source, log);
    const fs::path file = dir / "Sponza.gltf";
    saveGltf(original, file);
    // Images are referenced where they are (the JPEGs are not copied or re-encoded).
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"Sponza.gltf", "Sponza.bin"}));
    const Scene loaded = loadGltf(file, log);
    EXPECT_EQ(loaded.nodes.size(), original.nodes.size());
    EXPECT_EQ(loaded.meshes.size(), original.meshes.size());
    EXPECT_EQ(loaded.triangleCount(), original.triangleCount());
    EXPECT_EQ(loaded.materials.size(), original.materials.size());
    EXPECT_EQ(loaded.textures.size(), original.textures.size());
    EXPECT_EQ(loaded.images.size(), original.images.size());
    EXPECT_EQ(loaded.lights.size(), original.lights.size());
    EXPECT_EQ(loaded.cameras.size(), original.cameras.size());
    for (std::size_t i = 0; i < std::min(loaded.images.size(), original.images.size()); ++i) {
        EXPECT_EQ(loaded.images[i].width, original.images[i].width) << i;
        EXPECT_TRUE(loaded.images[i].rgba == original.images[i].rgba) << "image " << i;
    }
    const Aabb a = original.worldBounds(), b = loaded.worldBounds();
    expectVec(a.min, b.min, "world bounds min");
    expectVec(a.max, b.max, "world bounds max");
}

}  // namespace
}  // namespace lit
