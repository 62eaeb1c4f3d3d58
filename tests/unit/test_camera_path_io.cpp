// Camera paths on disk (renderer/animation/CameraPathIO.cpp): JSON and glTF round trips, the
// glTF animation Blender sees, atomic writes, and each bad-file case with its message.

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "Log.h"
#include "animation/CameraPathIO.h"
#include "scene/GltfLoader.h"

namespace lit {
namespace {

namespace fs = std::filesystem;

glm::quat yawPitch(float yawDegrees, float pitchDegrees = 0.0f) {
    return glm::angleAxis(glm::radians(yawDegrees), glm::vec3(0.0f, 1.0f, 0.0f)) *
           glm::angleAxis(glm::radians(pitchDegrees), glm::vec3(1.0f, 0.0f, 0.0f));
}

CameraPath samplePath(CameraPathOptions options = {false, true, true}) {
    return CameraPath({{0.0f, {0.0f, 1.0f, 3.4f}, yawPitch(0.0f), 0.69f},
                       {1.5f, {1.2f, 1.3f, 3.0f}, yawPitch(20.0f, -5.0f), 0.6f},
                       {4.0f, {-1.0f, 0.9f, 3.1f}, yawPitch(-15.0f, 3.0f), 0.75f}},
                      options);
}

void expectSameKeys(const CameraPath& a, const CameraPath& b, float tolerance = 1e-6f) {
    ASSERT_EQ(a.keys().size(), b.keys().size());
    EXPECT_EQ(a.options(), b.options());
    for (std::size_t i = 0; i < a.keys().size(); ++i) {
        const CameraKey& x = a.keys()[i];
        const CameraKey& y = b.keys()[i];
        EXPECT_NEAR(x.time, y.time, tolerance) << "key " << i;
        EXPECT_NEAR(glm::length(x.position - y.position), 0.0f, tolerance) << "key " << i;
        EXPECT_NEAR(std::abs(glm::dot(x.rotation, y.rotation)), 1.0f, tolerance) << "key " << i;
        EXPECT_NEAR(x.yfov, y.yfov, tolerance) << "key " << i;
    }
}

// A fresh scratch folder per test (each test runs in its own process, possibly in parallel).
fs::path scratch() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::temp_directory_path() / ("lit_path_io_" + std::string(info->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::set<std::string> filesIn(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
    return names;
}

fs::path cornellBoxCopy(const fs::path& dir) {
    const fs::path assets = fs::path(LIT_SOURCE_DIR) / "assets";
    fs::copy_file(assets / "cornell_box.gltf", dir / "cornell_box.gltf");
    fs::copy_file(assets / "cornell_box.bin", dir / "cornell_box.bin");
    return dir / "cornell_box.gltf";
}

tinygltf::Model loadModel(const fs::path& file) {
    tinygltf::Model model;
    tinygltf::TinyGLTF parser;
    std::string err, warn;
    const bool ok = file.extension() == ".glb" ? parser.LoadBinaryFromFile(&model, &err, &warn, file.string())
                                               : parser.LoadASCIIFromFile(&model, &err, &warn, file.string());
    EXPECT_TRUE(ok) << err;
    return model;
}

// A scene with one camera node, nothing else: enough for an animation.
tinygltf::Model cameraOnlyModel() {
    tinygltf::Model model;
    tinygltf::Camera camera;
    camera.type = "perspective";
    camera.perspective.yfov = 0.7;
    camera.perspective.znear = 0.1;
    camera.perspective.zfar = 100.0;
    model.cameras.push_back(camera);
    tinygltf::Node node;
    node.name = "cam";
    node.camera = 0;
    model.nodes.push_back(node);
    model.scenes.emplace_back();
    model.scenes[0].nodes = {0};
    model.defaultScene = 0;
    return model;
}

std::string jsonError(const std::string& text) {
    try {
        cameraPathFromJson(text);
    } catch (const CameraPathError& e) {
        return e.what();
    }
    return "";
}

std::string readError(const tinygltf::Model& model, const std::string& name) {
    try {
        readCameraPathAnimation(model, name);
    } catch (const CameraPathError& e) {
        return e.what();
    }
    return "";
}

// ---- JSON ------------------------------------------------------------------------------------

TEST(CameraPathJson, RoundTripIsExact) {
    for (const CameraPathOptions options : {CameraPathOptions{}, CameraPathOptions{true, false, true}}) {
        const CameraPath path = samplePath(options);
        const CameraPath back = cameraPathFromJson(cameraPathToJson(path));
        expectSameKeys(path, back, 0.0f);  // floats are written as their shortest exact decimal
        EXPECT_EQ(path.keys(), back.keys());
    }
}

TEST(CameraPathJson, FormatIsTheDocumentedOne) {
    const nlohmann::json j = nlohmann::json::parse(cameraPathToJson(samplePath()));
    EXPECT_EQ(j.at("version"), 1);
    EXPECT_EQ(j.at("constantSpeed"), true);
    EXPECT_EQ(j.at("easeInOut"), true);
    EXPECT_EQ(j.at("loop"), false);
    ASSERT_EQ(j.at("keys").size(), 3u);
    const nlohmann::json& key = j.at("keys")[1];
    EXPECT_EQ(key.at("time"), 1.5);
    EXPECT_EQ(key.at("yfov"), 0.6);  // shortest decimal, not 0.60000002384...
    ASSERT_EQ(key.at("rotation").size(), 4u);
    // glTF order: x, y, z, w.
    const glm::quat q = yawPitch(20.0f, -5.0f);
    EXPECT_NEAR(key.at("rotation")[3].get<double>(), q.w, 1e-7);
    EXPECT_NEAR(key.at("rotation")[1].get<double>(), q.y, 1e-7);
}

TEST(CameraPathJson, FileRoundTripIsAtomic) {
    const fs::path dir = scratch();
    const fs::path file = dir / "sub" / "orbit.path.json";
    saveCameraPathJson(file, samplePath());
    expectSameKeys(samplePath(), loadCameraPathJson(file), 0.0f);
    // Overwrite with another path: the rename leaves no temporary behind.
    saveCameraPathJson(file, CameraPath({{0.0f, {1, 2, 3}, {1, 0, 0, 0}, 0.5f}}));
    EXPECT_EQ(filesIn(dir / "sub"), std::set<std::string>{"orbit.path.json"});
    EXPECT_EQ(loadCameraPathJson(file).keys().size(), 1u);
}

TEST(CameraPathJson, EmptyAndMinimalFiles) {
    EXPECT_TRUE(cameraPathFromJson(R"({"version": 1, "keys": []})").empty());
    const CameraPath one = cameraPathFromJson(
        R"({"version": 1, "keys": [{"time": 0, "position": [1, 2, 3], "rotation": [0, 0, 0, 1], "yfov": 0.8}]})");
    ASSERT_EQ(one.keys().size(), 1u);
    EXPECT_EQ(one.options(), CameraPathOptions{});  // options default to false
    EXPECT_EQ(one.keys()[0].position, glm::vec3(1, 2, 3));
}

TEST(CameraPathJson, BadFilesAreRejectedWithTheirProblem) {
    const std::string key0 = R"({"time": 0, "position": [0, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})";
    const auto file = [&](const std::string& key1, const std::string& head = R"("version": 1)") {
        return "{" + head + R"(, "keys": [)" + key0 + ", " + key1 + "]}";
    };
    const std::string good1 = R"({"time": 1, "position": [1, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})";
    EXPECT_EQ(jsonError(file(good1)), "");

    EXPECT_EQ(jsonError(file(good1, R"("version": 2)")), "unknown version 2 (this build of Lit reads version 1)");
    EXPECT_EQ(jsonError(file(good1, R"("version": "1")")), "'version' must be an integer, got \"1\"");
    EXPECT_EQ(jsonError(file(good1, R"("loop": true)")), "missing field 'version'");
    EXPECT_EQ(jsonError(R"({"version": 1})"), "missing field 'keys'");
    EXPECT_EQ(jsonError(R"({"version": 1, "keys": {}})"), "'keys' must be an array, got {}");
    EXPECT_EQ(jsonError(file(good1, R"("version": 1, "loop": 1)")), "'loop' must be true or false, got 1");
    EXPECT_EQ(jsonError(file(good1, R"("version": 1, "constantspeed": true)")), "unknown field 'constantspeed'");
    EXPECT_EQ(jsonError("[1, 2]"), "not a camera path: the JSON is not an object");
    EXPECT_EQ(jsonError(R"({"version": 1, "keys": [)").rfind("not valid JSON: parse error at line 1", 0), 0u);
    // JSON has no NaN or infinity: such files are not JSON; overflowing numbers are caught too.
    EXPECT_EQ(jsonError(file(R"({"time": NaN, "position": [1, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})"))
                  .rfind("not valid JSON: ", 0),
              0u);
    EXPECT_EQ(jsonError(file(R"({"time": 1e999, "position": [1, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})")),
              "not valid JSON: number overflow parsing '1e999'");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "position": [1e39, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})")),
              "key 1: position has a value too large for a float: 1e+39");

    EXPECT_EQ(jsonError(file(R"({"position": [1, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})")),
              "key 1: missing field 'time'");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "rotation": [0, 0, 0, 1], "yfov": 0.8})")),
              "key 1: missing field 'position'");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "position": [1, 0, 0], "yfov": 0.8})")), "key 1: missing field 'rotation'");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "position": [1, 0, 0], "rotation": [0, 0, 0, 1]})")),
              "key 1: missing field 'yfov'");
    EXPECT_EQ(jsonError(file(R"({"time": "1", "position": [1, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})")),
              "key 1: 'time' must be a number, got \"1\"");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "position": [1, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})")),
              "key 1: 'position' must be an array of 3 numbers, got [1,0]");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "position": [1, 0, 0], "rotation": [0, 0, 1], "yfov": 0.8})")),
              "key 1: 'rotation' must be an array of 4 numbers, got [0,0,1]");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "position": [1, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8, "fov": 1})")),
              "key 1: unknown field 'fov'");
    EXPECT_EQ(jsonError(file("7")), "key 1: must be an object, got 7");
    EXPECT_EQ(jsonError(file(R"({"time": 0, "position": [1, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 0.8})")),
              "key 1: time 0 is not after key 0's time 0");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "position": [1, 0, 0], "rotation": [0, 0, 0, 2], "yfov": 0.8})")),
              "key 1: rotation [0, 0, 0, 2] is not a unit quaternion (length 2)");
    EXPECT_EQ(jsonError(file(R"({"time": 1, "position": [1, 0, 0], "rotation": [0, 0, 0, 1], "yfov": 4})")),
              "key 1: yfov 4 is not between 0 and pi radians");
}

TEST(CameraPathJson, FileErrorsNameTheFile) {
    const fs::path dir = scratch();
    try {
        loadCameraPathJson(dir / "missing.json");
        FAIL() << "a missing file loaded";
    } catch (const CameraPathError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "missing.json").string() + ": no such file");
    }
    std::ofstream(dir / "bad.json") << R"({"version": 3, "keys": []})";
    try {
        loadCameraPathJson(dir / "bad.json");
        FAIL() << "a bad file loaded";
    } catch (const CameraPathError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "bad.json").string() + ": unknown version 3 (this build of Lit reads version 1)");
    }
}

TEST(CameraPathJson, CornellBoxSamplePathKeepsTheBoxInView) {
    const CameraPath path = loadCameraPathJson(fs::path(LIT_SOURCE_DIR) / "assets" / "cornell_box.path.json");
    ASSERT_EQ(path.keys().size(), 4u);
    EXPECT_TRUE(path.options().loop);
    EXPECT_FLOAT_EQ(path.duration(), 12.0f);
    const glm::vec3 centre(0.0f, 1.0f, 0.0f);
    for (const double t : path.frameTimes(10.0)) {
        const CameraPose pose = *path.evaluate(t);
        const glm::vec3 forward = pose.rotation * glm::vec3(0.0f, 0.0f, -1.0f);
        // Outside the open side, between the side walls, looking at the centre within 2°.
        EXPECT_GT(pose.position.z, 3.5f) << t;
        EXPECT_LT(std::abs(pose.position.x), 1.0f) << t;
        EXPECT_GT(glm::dot(forward, glm::normalize(centre - pose.position)), std::cos(glm::radians(2.0f))) << t;
    }
}

// ---- glTF in memory --------------------------------------------------------------------------

TEST(CameraPathGltf, InMemoryRoundTripUsesTheExtras) {
    tinygltf::Model model = cameraOnlyModel();
    const CameraPath path = samplePath();
    writeCameraPathAnimation(model, path, "fly");
    expectSameKeys(path, readCameraPathAnimation(model, "fly"), 0.0f);
    EXPECT_EQ(cameraAnimationNames(model), std::vector<std::string>{"fly"});

    // What Blender sees: one LINEAR translation and one LINEAR rotation channel on the camera node,
    // sampled at 30 Hz over the 4 s path, end included.
    ASSERT_EQ(model.animations.size(), 1u);
    const tinygltf::Animation& animation = model.animations[0];
    ASSERT_EQ(animation.channels.size(), 2u);
    EXPECT_EQ(animation.channels[0].target_path, "translation");
    EXPECT_EQ(animation.channels[1].target_path, "rotation");
    for (const auto& channel : animation.channels) EXPECT_EQ(channel.target_node, 0);
    for (const auto& sampler : animation.samplers) EXPECT_EQ(sampler.interpolation, "LINEAR");
    const tinygltf::Accessor& times = model.accessors[static_cast<std::size_t>(animation.samplers[0].input)];
    EXPECT_EQ(times.count, 121u);
    EXPECT_DOUBLE_EQ(times.minValues.at(0), 0.0);
    EXPECT_DOUBLE_EQ(times.maxValues.at(0), 4.0);
}

TEST(CameraPathGltf, ChannelsAloneGiveTheSameMotion) {
    // Without Lit's extras (an animation edited in Blender) the keys come from the channels: a
    // key per 30 Hz sample, so the reloaded path passes through the sampled poses.
    tinygltf::Model model = cameraOnlyModel();
    const CameraPath path = samplePath();
    writeCameraPathAnimation(model, path, "fly");
    model.animations[0].extras = tinygltf::Value();
    const CameraPath fromChannels = readCameraPathAnimation(model, "fly");
    ASSERT_EQ(fromChannels.keys().size(), 121u);
    EXPECT_EQ(fromChannels.options(), CameraPathOptions{});
    for (int i = 0; i <= 120; i += 7) {
        const double t = i / 30.0;
        const CameraPose a = *path.evaluate(t), b = *fromChannels.evaluate(t);
        EXPECT_NEAR(glm::length(a.position - b.position), 0.0f, 1e-5f) << "t = " << t;
        EXPECT_NEAR(std::abs(glm::dot(a.rotation, b.rotation)), 1.0f, 1e-6f) << "t = " << t;
        EXPECT_FLOAT_EQ(b.yfov, 0.7f);  // the camera's own yfov: glTF does not animate it
    }
    // Between samples the two differ by little (the samples are 1/30 s apart).
    for (const double t : {0.51, 1.77, 3.3}) {
        EXPECT_NEAR(glm::length(path.evaluate(t)->position - fromChannels.evaluate(t)->position), 0.0f, 2e-3f) << t;
    }
}

TEST(CameraPathGltf, ParentTransformIsTakenIntoAccount) {
    tinygltf::Model model = cameraOnlyModel();
    tinygltf::Node rig;
    rig.name = "rig";
    rig.translation = {5.0, 0.0, -2.0};
    rig.rotation = {0.0, std::sin(0.3), 0.0, std::cos(0.3)};
    rig.scale = {2.0, 2.0, 2.0};
    rig.children = {0};
    model.nodes.push_back(rig);
    model.scenes[0].nodes = {1};
    const CameraPath path = samplePath({});
    writeCameraPathAnimation(model, path, "fly");
    // The channels hold parent-space values; read back without extras they give world poses.
    model.animations[0].extras = tinygltf::Value();
    const CameraPath back = readCameraPathAnimation(model, "fly");
    for (const double t : {0.0, 1.5, 2.2, 4.0}) {
        EXPECT_NEAR(glm::length(path.evaluate(t)->position - back.evaluate(t)->position), 0.0f, 1e-4f) << t;
        EXPECT_NEAR(std::abs(glm::dot(path.evaluate(t)->rotation, back.evaluate(t)->rotation)), 1.0f, 1e-5f) << t;
    }
}

TEST(CameraPathGltf, SavingAgainReusesTheAnimationsData) {
    tinygltf::Model model = cameraOnlyModel();
    writeCameraPathAnimation(model, samplePath(), "fly");
    const std::size_t buffers = model.buffers.size(), views = model.bufferViews.size(),
                      accessors = model.accessors.size();
    const CameraPath shorter({{0.0f, {0, 0, 0}, {1, 0, 0, 0}, 0.8f}, {1.0f, {1, 0, 0}, {1, 0, 0, 0}, 0.8f}});
    writeCameraPathAnimation(model, shorter, "fly");
    EXPECT_EQ(model.animations.size(), 1u);
    EXPECT_EQ(model.buffers.size(), buffers);
    EXPECT_EQ(model.bufferViews.size(), views);
    EXPECT_EQ(model.accessors.size(), accessors);
    expectSameKeys(shorter, readCameraPathAnimation(model, "fly"), 0.0f);
    EXPECT_EQ(model.accessors[static_cast<std::size_t>(model.animations[0].samplers[0].input)].count, 31u);
    // A second path gets an animation of its own.
    writeCameraPathAnimation(model, samplePath(), "other");
    EXPECT_EQ(cameraAnimationNames(model), (std::vector<std::string>{"fly", "other"}));
}

TEST(CameraPathGltf, SceneWithoutCameraGetsOne) {
    tinygltf::Model model;
    model.scenes.emplace_back();
    model.defaultScene = 0;
    writeCameraPathAnimation(model, samplePath(), "fly");
    ASSERT_EQ(model.cameras.size(), 1u);
    ASSERT_EQ(model.nodes.size(), 1u);
    EXPECT_EQ(model.nodes[0].camera, 0);
    EXPECT_EQ(model.scenes[0].nodes, std::vector<int>{0});
    EXPECT_NEAR(model.cameras[0].perspective.yfov, 0.69, 1e-6);
}

TEST(CameraPathGltf, BadAnimationsAreRejectedWithTheirProblem) {
    tinygltf::Model model = cameraOnlyModel();
    EXPECT_EQ(readError(model, "fly"), "no animation named 'fly'; the file has no camera animations");
    writeCameraPathAnimation(model, samplePath(), "fly");
    EXPECT_EQ(readError(model, "walk"), "no animation named 'walk'; its camera animations are: 'fly'");

    // Bad extras: the JSON messages, prefixed with where they are.
    tinygltf::Model badExtras = model;
    nlohmann::json extras = nlohmann::json::parse(cameraPathToJson(samplePath()));
    extras["version"] = 7;
    tinygltf::Value::Object object;
    object["litCameraPath"] = tinygltf::Value(
        tinygltf::Value::Object{{"version", tinygltf::Value(7)}, {"keys", tinygltf::Value(tinygltf::Value::Array{})}});
    badExtras.animations[0].extras = tinygltf::Value(object);
    EXPECT_EQ(readError(badExtras, "fly"),
              "animation 'fly': extras.litCameraPath: unknown version 7 (this build of Lit reads version 1)");

    // Channels only, with bad data.
    model.animations[0].extras = tinygltf::Value();
    const auto withFloat = [&](int accessor, std::size_t element, float value) {
        tinygltf::Model copy = model;
        const tinygltf::Accessor& a = copy.accessors[static_cast<std::size_t>(accessor)];
        const tinygltf::BufferView& v = copy.bufferViews[static_cast<std::size_t>(a.bufferView)];
        std::memcpy(copy.buffers[static_cast<std::size_t>(v.buffer)].data.data() + v.byteOffset + a.byteOffset +
                        element * sizeof(float),
                    &value, sizeof value);
        return copy;
    };
    const int times = model.animations[0].samplers[0].input;
    const int translations = model.animations[0].samplers[0].output;
    const int rotations = model.animations[0].samplers[1].output;
    EXPECT_EQ(readError(withFloat(times, 3, 0.05f), "fly"),
              "animation 'fly': sampler 0: keyframe time 3 (0.05 s) is not after keyframe 2 (0.0666667 s)");
    EXPECT_EQ(readError(withFloat(translations, 4, std::nanf("")), "fly"),
              "animation 'fly': sampler 0: output value 1 is not a finite number");
    EXPECT_EQ(readError(withFloat(rotations, 4 * 5 + 3, 3.0f), "fly"),
              "animation 'fly': sampler 1: rotation keyframe 5 is not a unit quaternion (length 3)");

    tinygltf::Model truncated = model;
    truncated.bufferViews[static_cast<std::size_t>(truncated.accessors[static_cast<std::size_t>(rotations)].bufferView)]
        .byteLength -= 4;
    EXPECT_EQ(readError(truncated, "fly"), "animation 'fly': sampler 1 output: accessor " + std::to_string(rotations) +
                                               " reads past the end of its buffer view or buffer");

    tinygltf::Model noCamera = model;
    noCamera.nodes[0].camera = -1;
    EXPECT_EQ(readError(noCamera, "fly"),
              "animation 'fly' does not animate a camera: no translation or rotation channel targets a node with a "
              "camera");

    tinygltf::Model cubic = model;
    cubic.animations[0].samplers[0].interpolation = "CUBICSPLINE";
    EXPECT_EQ(readError(cubic, "fly"),
              "animation 'fly': sampler 0: 121 output values for 121 keyframes (CUBICSPLINE needs 363)");
    tinygltf::Model unknown = model;
    unknown.animations[0].samplers[1].interpolation = "BOUNCE";
    EXPECT_EQ(readError(unknown, "fly"),
              "animation 'fly': sampler 1: interpolation 'BOUNCE' is not LINEAR, STEP or CUBICSPLINE");
}

TEST(CameraPathGltf, WritingRejectsWhatCannotBeWritten) {
    tinygltf::Model model = cameraOnlyModel();
    model.nodes.emplace_back();
    model.nodes[1].name = "lamp";
    const auto writeError = [&](const CameraPath& path, int node) {
        try {
            writeCameraPathAnimation(model, path, "fly", node);
        } catch (const CameraPathError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(writeError(CameraPath(), -1), "cannot save a camera path with no keys as a glTF animation");
    EXPECT_EQ(writeError(samplePath(), 1), "node 1 'lamp' holds no camera");
    EXPECT_EQ(writeError(samplePath(), 9), "node 9 does not exist (the file has 2 nodes)");
    EXPECT_TRUE(model.animations.empty());  // nothing was half-written
}

// ---- glTF files ------------------------------------------------------------------------------

TEST(CameraPathGltfFile, CornellBoxRoundTripKeepsTheScene) {
    const fs::path dir = scratch();
    const fs::path scene = cornellBoxCopy(dir);
    const CameraPath path = samplePath();
    saveCameraPathToGltf(scene, path);
    expectSameKeys(path, loadCameraPathFromGltf(scene, "camera path"), 0.0f);
    EXPECT_EQ(cameraAnimationNames(scene), std::vector<std::string>{"camera path"});
    // The path's data sits in a buffer file of its own; no temporary folder is left behind.
    EXPECT_EQ(filesIn(dir),
              (std::set<std::string>{"cornell_box.gltf", "cornell_box.bin", "cornell_box_camera_path.bin"}));

    // The scene itself still loads as before.
    Log log;
    const Scene original = loadGltf(fs::path(LIT_SOURCE_DIR) / "assets" / "cornell_box.gltf", log);
    const Scene saved = loadGltf(scene, log);
    EXPECT_EQ(saved.nodes.size(), original.nodes.size());
    EXPECT_EQ(saved.meshes.size(), original.meshes.size());
    EXPECT_EQ(saved.lights.size(), original.lights.size());
    EXPECT_EQ(saved.cameras.size(), original.cameras.size());
    EXPECT_EQ(saved.triangleCount(), original.triangleCount());
    EXPECT_FLOAT_EQ(saved.lights.at(0).intensity, original.lights.at(0).intensity);
    EXPECT_EQ(saved.nodes.at(8).translation, original.nodes.at(8).translation);  // the still camera is untouched

    // Saving again replaces the animation in place.
    const CameraPath other({{0.0f, {0, 1, 4}, {1, 0, 0, 0}, 0.7f}, {2.0f, {0.5f, 1, 4}, {1, 0, 0, 0}, 0.7f}},
                           {true, false, false});
    saveCameraPathToGltf(scene, other);
    expectSameKeys(other, loadCameraPathFromGltf(scene, "camera path"), 0.0f);
    const tinygltf::Model model = loadModel(scene);
    EXPECT_EQ(model.animations.size(), 1u);
    EXPECT_EQ(model.buffers.size(), 2u);
    EXPECT_EQ(filesIn(dir).size(), 3u);
}

TEST(CameraPathGltfFile, GlbStaysOneFile) {
    const fs::path dir = scratch();
    // Make a .glb of the Cornell box with tinygltf itself.
    tinygltf::Model box = loadModel(cornellBoxCopy(dir));
    tinygltf::TinyGLTF writer;
    ASSERT_TRUE(writer.WriteGltfSceneToFile(&box, (dir / "box.glb").string(), true, true, false, true));
    fs::remove(dir / "cornell_box.gltf");
    fs::remove(dir / "cornell_box.bin");

    saveCameraPathToGltf(dir / "box.glb", samplePath(), "orbit");
    EXPECT_EQ(filesIn(dir), std::set<std::string>{"box.glb"});
    expectSameKeys(samplePath(), loadCameraPathFromGltf(dir / "box.glb", "orbit"), 0.0f);
    Log log;
    EXPECT_EQ(loadGltf(dir / "box.glb", log).meshes.size(), 7u);
}

TEST(CameraPathGltfFile, EmbeddedGltfStaysEmbedded) {
    const fs::path dir = scratch();
    tinygltf::Model box = loadModel(cornellBoxCopy(dir));
    tinygltf::TinyGLTF writer;
    ASSERT_TRUE(writer.WriteGltfSceneToFile(&box, (dir / "embedded.gltf").string(), true, true, true, false));
    fs::remove(dir / "cornell_box.gltf");
    fs::remove(dir / "cornell_box.bin");

    saveCameraPathToGltf(dir / "embedded.gltf", samplePath());
    EXPECT_EQ(filesIn(dir), std::set<std::string>{"embedded.gltf"});
    expectSameKeys(samplePath(), loadCameraPathFromGltf(dir / "embedded.gltf", "camera path"), 0.0f);
}

TEST(CameraPathGltfFile, ErrorsNameTheFileAndChangeNothing) {
    const fs::path dir = scratch();
    const fs::path scene = cornellBoxCopy(dir);
    const auto before = fs::last_write_time(scene);
    try {
        saveCameraPathToGltf(scene, samplePath(), "camera path", 3);  // node 3 is a wall
        FAIL() << "saved onto a node without a camera";
    } catch (const CameraPathError& e) {
        EXPECT_EQ(std::string(e.what()), scene.string() + ": node 3 'left_wall_red' holds no camera");
    }
    EXPECT_EQ(fs::last_write_time(scene), before);
    EXPECT_EQ(filesIn(dir), (std::set<std::string>{"cornell_box.gltf", "cornell_box.bin"}));

    try {
        loadCameraPathFromGltf(scene, "camera path");
        FAIL() << "loaded an animation the file does not have";
    } catch (const CameraPathError& e) {
        EXPECT_EQ(std::string(e.what()),
                  scene.string() + ": no animation named 'camera path'; the file has no camera animations");
    }
    try {
        loadCameraPathFromGltf(dir / "nothing.gltf", "camera path");
        FAIL() << "loaded a missing file";
    } catch (const CameraPathError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "nothing.gltf").string() + ": no such file");
    }
    std::ofstream(dir / "broken.gltf") << "{ not json";
    try {
        loadCameraPathFromGltf(dir / "broken.gltf", "camera path");
        FAIL() << "loaded a broken file";
    } catch (const CameraPathError& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir / "broken.gltf").string() + ": cannot load the glTF file: ", 0), 0u)
            << e.what();
    }
}

}  // namespace
}  // namespace lit
