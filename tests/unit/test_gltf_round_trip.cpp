// Lossless glTF round trip of what Lit does not draw: a file with skins, morph targets (one
// sparse), TEXCOORD_1, COLOR_0 of 3 bytes per vertex, JOINTS_0/WEIGHTS_0, a custom attribute, a
// primitive without normals (the loader unwelds it), a LINES primitive, a texture read through
// TEXCOORD_1, an orthographic camera and a morph weight animation is loaded, saved and read back
// with tinygltf; every value is compared with the source's, corner by corner (so unwelding and
// index types do not matter, values do). Each test takes a few milliseconds. The test files are
// fixtures in tests/data/gltf/round_trip, each described where it is copied for a test.

#include <gtest/gtest.h>

#include "GltfValidator.h"
#include "TempDir.h"

#include "Log.h"
#include "io/GltfFile.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "QuietLog.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace lit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

using lit::testing::QuietLog;

struct TempDir : lit::testing::TempDir {
    TempDir() : lit::testing::TempDir("lit_gltf_round_trip") {}
};

fs::path fixtureDir() { return fs::path(LIT_SOURCE_DIR) / "tests" / "data" / "gltf" / "round_trip"; }

// Copies fixture `name` and the buffers and image files it names into `dir`, where a test may
// change it and saves go beside it (so relative image URIs stay as the file has them); returns
// the copy.
fs::path copyFixture(const TempDir& dir, const std::string& name) {
    const json doc = json::parse(lit::testing::readText(fixtureDir() / name));
    std::vector<std::string> files = {name};
    for (const char* array : {"buffers", "images"})
        for (const json& object : doc.value(array, json::array()))
            if (const std::string uri = object.value("uri", ""); !uri.empty() && !uri.starts_with("data:"))
                files.push_back(uri);
    for (const std::string& file : files)
        fs::copy_file(fixtureDir() / file, dir / file, fs::copy_options::overwrite_existing);
    return dir / name;
}

// The test file of the comment at the top.
fs::path riggedFile(const TempDir& dir) { return copyFixture(dir, "rigged.gltf"); }

tinygltf::Model readModel(const fs::path& file) {
    tinygltf::Model model;
    tinygltf::TinyGLTF parser;
    std::string err, warn;
    const bool ok = file.extension() == ".glb" ? parser.LoadBinaryFromFile(&model, &err, &warn, file.string())
                                               : parser.LoadASCIIFromFile(&model, &err, &warn, file.string());
    if (!ok) throw std::runtime_error(file.string() + ": " + err);
    return model;
}

// Element i of an accessor as doubles (normalized integers as glTF defines them), sparse
// accessors expanded. Matrices: all 16 components.
std::vector<double> element(const tinygltf::Model& model, int accessorIndex, std::size_t i) {
    const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(accessorIndex));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    const auto decode = [&](const unsigned char* p) {
        std::vector<double> out;
        for (int c = 0; c < components; ++c) {
            const unsigned char* q = p + c * size;
            double v = 0;
            switch (a.componentType) {
                case 5120: {
                    const auto x = static_cast<std::int8_t>(q[0]);
                    v = a.normalized ? std::max(x / 127.0, -1.0) : x;
                    break;
                }
                case 5121:
                    v = a.normalized ? q[0] / 255.0 : q[0];
                    break;
                case 5122: {
                    std::int16_t x;
                    std::memcpy(&x, q, 2);
                    v = a.normalized ? std::max(x / 32767.0, -1.0) : x;
                    break;
                }
                case 5123: {
                    std::uint16_t x;
                    std::memcpy(&x, q, 2);
                    v = a.normalized ? x / 65535.0 : x;
                    break;
                }
                case 5125: {
                    std::uint32_t x;
                    std::memcpy(&x, q, 4);
                    v = x;
                    break;
                }
                case 5126: {
                    float x;
                    std::memcpy(&x, q, 4);
                    v = x;
                    break;
                }
                default:
                    ADD_FAILURE() << "component type " << a.componentType << " not expected in this test";
            }
            out.push_back(v);
        }
        return out;
    };
    const auto at = [&](int viewIndex, std::size_t byteOffset, std::size_t index, std::size_t elementSize) {
        const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(viewIndex));
        const std::size_t stride = view.byteStride ? view.byteStride : elementSize;
        return model.buffers.at(static_cast<std::size_t>(view.buffer)).data.data() + view.byteOffset + byteOffset +
               index * stride;
    };
    const std::size_t elementSize = static_cast<std::size_t>(components * size);
    if (a.sparse.isSparse) {
        for (int s = 0; s < a.sparse.count; ++s) {
            const int indexSize =
                tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.sparse.indices.componentType));
            // tinygltf says -1 for an unknown type (GCC 12 at -O3 saw that -1 reach memcpy as a size).
            if (indexSize < 1 || indexSize > static_cast<int>(sizeof(std::uint32_t)))
                throw std::runtime_error("sparse indices of component type " +
                                         std::to_string(a.sparse.indices.componentType));
            const unsigned char* p =
                at(a.sparse.indices.bufferView, static_cast<std::size_t>(a.sparse.indices.byteOffset),
                   static_cast<std::size_t>(s), static_cast<std::size_t>(indexSize));
            std::uint32_t target = 0;
            std::memcpy(&target, p, static_cast<std::size_t>(indexSize));
            if (target == i)
                return decode(at(a.sparse.values.bufferView, static_cast<std::size_t>(a.sparse.values.byteOffset),
                                 static_cast<std::size_t>(s), elementSize));
        }
    }
    if (a.bufferView < 0) return std::vector<double>(static_cast<std::size_t>(components), 0.0);
    return decode(at(a.bufferView, a.byteOffset, i, elementSize));
}

// An attribute's value at every corner of the primitive (the index list expanded), so a
// reindexed or unwelded primitive compares equal when every triangle has the same values.
std::vector<std::vector<double>> corners(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                         int accessor) {
    std::vector<std::size_t> order;
    if (primitive.indices >= 0) {
        const tinygltf::Accessor& indices = model.accessors.at(static_cast<std::size_t>(primitive.indices));
        for (std::size_t i = 0; i < indices.count; ++i)
            order.push_back(static_cast<std::size_t>(element(model, primitive.indices, i)[0]));
    } else {
        for (std::size_t i = 0; i < model.accessors.at(static_cast<std::size_t>(accessor)).count; ++i)
            order.push_back(i);
    }
    std::vector<std::vector<double>> out;
    for (std::size_t i : order) out.push_back(element(model, accessor, i));
    return out;
}

std::vector<std::vector<double>> elements(const tinygltf::Model& model, int accessor) {
    std::vector<std::vector<double>> out;
    for (std::size_t i = 0; i < model.accessors.at(static_cast<std::size_t>(accessor)).count; ++i)
        out.push_back(element(model, accessor, i));
    return out;
}

const tinygltf::Mesh& meshNamed(const tinygltf::Model& model, const std::string& name) {
    for (const tinygltf::Mesh& mesh : model.meshes)
        if (mesh.name == name) return mesh;
    throw std::runtime_error("no mesh " + name);
}

int nodeNamed(const tinygltf::Model& model, const std::string& name) {
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        if (model.nodes[i].name == name) return static_cast<int>(i);
    return -1;
}

std::vector<std::string> nodeNames(const tinygltf::Model& model, const std::vector<int>& nodes) {
    std::vector<std::string> out;
    for (int n : nodes) out.push_back(model.nodes.at(static_cast<std::size_t>(n)).name);
    return out;
}

// Every value of the source that Lit does not draw, compared with the saved file's.
void expectSameUndrawnData(const tinygltf::Model& source, const tinygltf::Model& saved) {
    for (const tinygltf::Mesh& in : source.meshes) {
        SCOPED_TRACE("mesh " + in.name);
        const tinygltf::Mesh& out = meshNamed(saved, in.name);
        ASSERT_EQ(out.primitives.size(), in.primitives.size());
        EXPECT_EQ(out.weights, in.weights);
        EXPECT_TRUE(out.extras == in.extras);  // Blender's targetNames
        for (std::size_t p = 0; p < in.primitives.size(); ++p) {
            const tinygltf::Primitive& a = in.primitives[p];
            const tinygltf::Primitive& b = out.primitives[p];
            EXPECT_EQ(b.mode == -1 ? 4 : b.mode, a.mode == -1 ? 4 : a.mode);
            for (const auto& [name, accessor] : a.attributes) {
                SCOPED_TRACE(name);
                ASSERT_TRUE(b.attributes.count(name)) << "the save dropped " << name;
                const tinygltf::Accessor& before = source.accessors[static_cast<std::size_t>(accessor)];
                const tinygltf::Accessor& after = saved.accessors[static_cast<std::size_t>(b.attributes.at(name))];
                if (name != "POSITION" && name != "NORMAL" && name != "TEXCOORD_0") {
                    EXPECT_EQ(after.componentType, before.componentType);  // not widened: same bytes
                    EXPECT_EQ(after.normalized, before.normalized);
                }
                EXPECT_EQ(after.type, before.type);
                EXPECT_EQ(corners(saved, b, b.attributes.at(name)), corners(source, a, accessor));
            }
            ASSERT_EQ(b.targets.size(), a.targets.size());
            for (std::size_t t = 0; t < a.targets.size(); ++t)
                for (const auto& [name, accessor] : a.targets[t]) {
                    SCOPED_TRACE("target " + std::to_string(t) + " " + name);
                    ASSERT_TRUE(b.targets[t].count(name));
                    EXPECT_EQ(corners(saved, b, b.targets[t].at(name)), corners(source, a, accessor));
                }
        }
    }
    ASSERT_EQ(saved.skins.size(), source.skins.size());
    for (std::size_t s = 0; s < source.skins.size(); ++s) {
        EXPECT_EQ(saved.skins[s].name, source.skins[s].name);
        EXPECT_EQ(nodeNames(saved, saved.skins[s].joints), nodeNames(source, source.skins[s].joints));
        EXPECT_EQ(nodeNames(saved, {saved.skins[s].skeleton}), nodeNames(source, {source.skins[s].skeleton}));
        EXPECT_EQ(elements(saved, saved.skins[s].inverseBindMatrices),
                  elements(source, source.skins[s].inverseBindMatrices));
    }
    for (const tinygltf::Node& in : source.nodes) {
        const int index = nodeNamed(saved, in.name);
        ASSERT_GE(index, 0) << in.name;
        const tinygltf::Node& out = saved.nodes[static_cast<std::size_t>(index)];
        EXPECT_EQ(out.weights, in.weights) << in.name;
        EXPECT_EQ(out.skin >= 0 ? saved.skins[static_cast<std::size_t>(out.skin)].name : "",
                  in.skin >= 0 ? source.skins[static_cast<std::size_t>(in.skin)].name : "")
            << in.name;
        EXPECT_EQ(out.camera >= 0, in.camera >= 0) << in.name;
    }
    ASSERT_EQ(saved.cameras.size(), source.cameras.size());
    for (std::size_t c = 0; c < source.cameras.size(); ++c) {
        EXPECT_EQ(saved.cameras[c].type, source.cameras[c].type);
        EXPECT_EQ(saved.cameras[c].orthographic, source.cameras[c].orthographic);
    }
    ASSERT_EQ(saved.materials.size(), source.materials.size());
    for (std::size_t m = 0; m < source.materials.size(); ++m) {
        const tinygltf::Material& a = source.materials[m];
        const tinygltf::Material& b = saved.materials[m];
        EXPECT_EQ(b.occlusionTexture.texCoord, a.occlusionTexture.texCoord);
        EXPECT_EQ(b.occlusionTexture.extensions, a.occlusionTexture.extensions);
        EXPECT_EQ(b.pbrMetallicRoughness.baseColorTexture.texCoord, a.pbrMetallicRoughness.baseColorTexture.texCoord);
    }
    ASSERT_EQ(saved.animations.size(), source.animations.size());
    for (std::size_t i = 0; i < source.animations.size(); ++i) {
        const tinygltf::Animation& a = source.animations[i];
        const tinygltf::Animation& b = saved.animations[i];
        ASSERT_EQ(b.channels.size(), a.channels.size());
        for (std::size_t c = 0; c < a.channels.size(); ++c) {
            EXPECT_EQ(b.channels[c].target_path, a.channels[c].target_path);
            EXPECT_EQ(saved.nodes.at(static_cast<std::size_t>(b.channels[c].target_node)).name,
                      source.nodes.at(static_cast<std::size_t>(a.channels[c].target_node)).name);
            const tinygltf::AnimationSampler& sa = a.samplers.at(static_cast<std::size_t>(a.channels[c].sampler));
            const tinygltf::AnimationSampler& sb = b.samplers.at(static_cast<std::size_t>(b.channels[c].sampler));
            EXPECT_EQ(elements(saved, sb.input), elements(source, sa.input));
            EXPECT_EQ(elements(saved, sb.output), elements(source, sa.output));
        }
    }
}

TEST(GltfRoundTrip, SkinsMorphTargetsAndExtraAttributesSurviveASave) {
    TempDir dir;
    QuietLog log;
    const fs::path source = riggedFile(dir);
    const Scene scene = loadGltf(source, log);
    ASSERT_EQ(scene.skins.size(), 1u);
    ASSERT_EQ(scene.meshes.at(2).otherPrimitives.size(), 1u);
    saveGltf(scene, dir / "saved.gltf");
    expectSameUndrawnData(readModel(source), readModel(dir / "saved.gltf"));
    // And once more from the saved file, as a .glb: nothing is lost on the second trip either.
    saveGltf(loadGltf(dir / "saved.gltf", log), dir / "again.glb");
    expectSameUndrawnData(readModel(source), readModel(dir / "again.glb"));
}

TEST(GltfRoundTrip, AnEditedNodeKeepsItsSkinAndWeights) {
    TempDir dir;
    QuietLog log;
    Scene scene = loadGltf(riggedFile(dir), log);
    for (Node& node : scene.nodes)
        if (node.name == "body") node.translation.x += 2.0f;
    saveGltf(scene, dir / "moved.gltf");
    const tinygltf::Model saved = readModel(dir / "moved.gltf");
    const tinygltf::Node& moved = saved.nodes.at(static_cast<std::size_t>(nodeNamed(saved, "body")));
    ASSERT_EQ(moved.translation.size(), 3u);
    EXPECT_EQ(moved.translation[0], 2.0);
    expectSameUndrawnData(readModel(dir / "rigged.gltf"), saved);
}

// When an edit rebuilds a primitive's vertices, kept per-vertex data no longer fits: the save
// leaves it out rather than writing a file whose attributes disagree in length.
TEST(GltfRoundTrip, RebuiltGeometryDropsOnlyItsOwnKeptAttributes) {
    TempDir dir;
    QuietLog log;
    Scene scene = loadGltf(riggedFile(dir), log);
    Primitive& quad = scene.meshes.at(0).primitives.at(0);
    quad.vertices.push_back(quad.vertices.back());
    saveGltf(scene, dir / "rebuilt.gltf");
    const tinygltf::Model saved = readModel(dir / "rebuilt.gltf");
    const tinygltf::Primitive& p = meshNamed(saved, "skinned quad").primitives.at(0);
    EXPECT_FALSE(p.attributes.count("COLOR_0"));
    EXPECT_TRUE(p.targets.empty());
    EXPECT_TRUE(meshNamed(saved, "skinned quad").weights.empty());  // weights need targets
    EXPECT_TRUE(meshNamed(saved, "flat").primitives.at(0).attributes.count("COLOR_0"));
}

// A skin whose joint node was deleted is left out, and the node that used it saves without one.
TEST(GltfRoundTrip, ASkinLosingAJointIsLeftOut) {
    TempDir dir;
    QuietLog log;
    Scene scene = loadGltf(riggedFile(dir), log);
    scene.skins.at(0).joints.at(1) = -1;  // what editor/SceneEdits.cpp's delete leaves
    saveGltf(scene, dir / "no_skin.gltf");
    const tinygltf::Model saved = readModel(dir / "no_skin.gltf");
    EXPECT_TRUE(saved.skins.empty());
    EXPECT_EQ(saved.nodes.at(static_cast<std::size_t>(nodeNamed(saved, "body"))).skin, -1);
}

// ---- What else a save must keep: several scenes, extras everywhere, embedded images byte for
// byte, sparse accessors. Each test has its own small file.

// A .gltf's JSON and its one .bin (the writer writes one buffer, "<stem>.bin").
struct RawGltf {
    json doc;
    std::vector<std::uint8_t> bin;
};

RawGltf readRaw(const fs::path& file) {
    RawGltf raw;
    raw.doc = json::parse(lit::testing::readText(file));
    const std::string uri = raw.doc.at("buffers").at(0).at("uri").get<std::string>();
    std::ifstream in(file.parent_path() / uri, std::ios::binary);
    raw.bin.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return raw;
}

// The bytes of buffer view `view` of a file with one buffer.
std::vector<std::uint8_t> viewBytes(const RawGltf& raw, int view) {
    const json& v = raw.doc.at("bufferViews").at(static_cast<std::size_t>(view));
    const std::size_t offset = v.value("byteOffset", std::size_t(0)), length = v.at("byteLength").get<std::size_t>();
    if (offset + length > raw.bin.size()) throw std::runtime_error("buffer view past the buffer");
    return {raw.bin.begin() + static_cast<std::ptrdiff_t>(offset),
            raw.bin.begin() + static_cast<std::ptrdiff_t>(offset + length)};
}

// Three scenes; the file shows the second. "detail" shares node "lamp" with it, and has extras.
fs::path scenesFile(const TempDir& dir) { return copyFixture(dir, "scenes.gltf"); }

TEST(GltfRoundTrip, EverySceneOfTheFileSurvivesASave) {
    TempDir dir;
    QuietLog log;
    const fs::path source = scenesFile(dir);
    const Scene scene = loadGltf(source, log);
    ASSERT_EQ(scene.otherScenes.size(), 2u);
    EXPECT_EQ(scene.sceneIndex, 1);
    saveGltf(scene, dir / "saved.gltf");
    const json before = json::parse(lit::testing::readText(source));
    const json after = json::parse(lit::testing::readText(dir / "saved.gltf"));
    EXPECT_EQ(after.at("scene"), 1);
    ASSERT_EQ(after.at("scenes").size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE("scene " + std::to_string(i));
        EXPECT_EQ(after["scenes"][i].value("name", ""), before["scenes"][i].value("name", ""));
        EXPECT_EQ(after["scenes"][i].value("extras", json()), before["scenes"][i].value("extras", json()));
        std::vector<std::string> namesBefore, namesAfter;
        for (const json& n : before["scenes"][i]["nodes"])
            namesBefore.push_back(before["nodes"][n.get<std::size_t>()]["name"]);
        for (const json& n : after["scenes"][i]["nodes"])
            namesAfter.push_back(after["nodes"][n.get<std::size_t>()]["name"]);
        EXPECT_EQ(namesAfter, namesBefore);
    }
    // Deleting a node another scene lists drops it from that scene only.
    Scene edited = scene;
    edited.nodes.at(2).parent = 0;  // "prop" under "ground": no longer a root anywhere
    edited.nodes.at(0).children.push_back(2);
    edited.roots = {0, 1};
    saveGltf(edited, dir / "reparented.gltf");
    const json reparented = json::parse(lit::testing::readText(dir / "reparented.gltf"));
    EXPECT_EQ(reparented["scenes"][2]["nodes"].size(), 1u);
}

// The node names of each scene of a saved file, by scene.
std::vector<std::vector<std::string>> sceneNodeNames(const json& doc) {
    std::vector<std::vector<std::string>> out;
    for (const json& scene : doc.at("scenes")) {
        out.emplace_back();
        for (const json& n : scene.value("nodes", json::array()))
            out.back().push_back(doc["nodes"][n.get<std::size_t>()]["name"]);
    }
    return out;
}

// The JSON of a .gltf, or of a .glb's JSON chunk.
json jsonOf(const fs::path& file) {
    if (file.extension() != ".glb") return json::parse(lit::testing::readText(file));
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < 20) throw std::runtime_error(file.string() + ": too short for a GLB");
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    if (20 + std::size_t(length) > bytes.size()) throw std::runtime_error(file.string() + ": JSON chunk past the end");
    return json::parse(bytes.begin() + 20, bytes.begin() + 20 + length);
}

// A scene whose nodes are not in the one Lit shows keeps them all: the loader keeps the nodes
// outside the shown scene (Scene::keptNodes) and a save writes every scene with all its nodes.
TEST(GltfRoundTrip, OtherScenesKeepTheirNodesOutsideTheShownOne) {
    TempDir dir;
    QuietLog log;
    const fs::path source = scenesFile(dir);
    json doc = json::parse(lit::testing::readText(source));
    doc["scene"] = 0;  // show "detail": only "lamp" is drawn
    std::ofstream(source) << doc.dump();
    const Scene scene = loadGltf(source, log);
    ASSERT_EQ(scene.nodes.size(), 1u);
    EXPECT_EQ(scene.nodes[0].name, "lamp");
    EXPECT_EQ(scene.keptNodes.size(), 2u);
    for (const char* ext : {".gltf", ".glb"}) {
        SCOPED_TRACE(ext);
        const fs::path saved = dir / (std::string("saved") + ext);
        saveGltf(scene, saved);
        EXPECT_EQ(sceneNodeNames(jsonOf(saved)), sceneNodeNames(doc));
        const fs::path again = dir / (std::string("again") + ext);
        saveGltf(loadGltf(saved, log), again);
        EXPECT_EQ(sceneNodeNames(jsonOf(again)), sceneNodeNames(doc));
    }
}

// A file whose second scene ("stage", not shown) holds a light, a camera, a skinned mesh with its
// joint and an animated node, and a node in no scene at all; the shown scene has "ground" (shared
// with "stage") and a sun whose light comes first in the file's lights.
fs::path hiddenNodesFile(const TempDir& dir) { return copyFixture(dir, "hidden.gltf"); }

// Everything hidden.gltf has outside the shown scene, found by name in a saved file.
void expectHiddenNodes(const json& doc) {
    const auto node = [&](const std::string& name) -> const json& {
        for (const json& n : doc.at("nodes"))
            if (n.value("name", "") == name) return n;
        throw std::runtime_error("no node '" + name + "'");
    };
    const auto names = [&](const json& indices) {
        std::vector<std::string> out;
        for (const json& i : indices) out.push_back(doc["nodes"][i.get<std::size_t>()]["name"]);
        std::sort(out.begin(), out.end());
        return out;
    };
    ASSERT_EQ(doc.at("nodes").size(), 8u);
    EXPECT_EQ(names(node("stage")["children"]), (std::vector<std::string>{"cam", "prop", "spot"}));
    EXPECT_EQ(node("stage")["translation"], json::array({0.0, 1.0, 0.0}));
    EXPECT_EQ(names(node("prop")["children"]), (std::vector<std::string>{"bone"}));
    const json& lights = doc["extensions"]["KHR_lights_punctual"]["lights"];
    EXPECT_EQ(lights[node("spot")["extensions"]["KHR_lights_punctual"]["light"].get<std::size_t>()]["name"],
              "spot lamp");
    EXPECT_EQ(doc["cameras"][node("cam")["camera"].get<std::size_t>()]["name"], "stage cam");
    EXPECT_EQ(doc["meshes"][node("prop")["mesh"].get<std::size_t>()]["name"], "skinned");
    const json& skin = doc["skins"][node("prop").at("skin").get<std::size_t>()];
    EXPECT_EQ(names(skin["joints"]), (std::vector<std::string>{"bone"}));
    EXPECT_EQ(doc["nodes"][skin["skeleton"].get<std::size_t>()]["name"], "bone");
    EXPECT_EQ(node("loose")["extras"], json({{"why", "orphan"}}));
    EXPECT_EQ(node("loose")["translation"], json::array({9.0, 9.0, 9.0}));
    std::vector<std::string> targets;
    for (const json& c : doc["animations"].at(0)["channels"])
        targets.push_back(doc["nodes"][c["target"]["node"].get<std::size_t>()]["name"]);
    std::sort(targets.begin(), targets.end());
    EXPECT_EQ(targets, (std::vector<std::string>{"ground", "prop"}));
    std::vector<std::vector<std::string>> scenes = sceneNodeNames(doc);
    ASSERT_EQ(scenes.size(), 2u);
    EXPECT_EQ(scenes[1], (std::vector<std::string>{"stage", "ground"}));
    EXPECT_EQ(doc.value("scene", -1), 0);
    // Found by the Blender diff: the file's required extension, a float32 rotation (Blender's
    // numbers, a few ulp from unit length) and numbers a float cannot hold (0.1, 0.7, π/8) are
    // written as they were.
    EXPECT_EQ(node("spot")["translation"], json::array({0.0, 3.0, 0.1}));
    EXPECT_EQ(doc["cameras"][node("cam")["camera"].get<std::size_t>()]["perspective"]["yfov"], 0.7);
    EXPECT_EQ(
        lights[node("spot")["extensions"]["KHR_lights_punctual"]["light"].get<std::size_t>()]["spot"]["outerConeAngle"],
        0.39269908169872414);
    EXPECT_EQ(doc.value("extensionsRequired", json()), json::array({"KHR_lights_punctual"}));
    EXPECT_EQ(node("sun")["rotation"], json::array({-0.13498486578464508, 0.0, 0.0, 0.990847647190094}));
}

// Nodes in none of the shown scene's trees are kept (not drawn) and saved with their subtrees,
// lights, cameras, meshes, skins and animation channels, through .gltf and .glb, unedited and
// after an edit of a shown node. Fails when the loader drops them. A few milliseconds.
TEST(GltfRoundTrip, NodesOutsideTheShownSceneSurviveASave) {
    TempDir dir;
    QuietLog log;
    const fs::path source = hiddenNodesFile(dir);
    Scene scene = loadGltf(source, log);
    ASSERT_EQ(scene.nodes.size(), 2u);  // ground and sun: only they are drawn
    EXPECT_EQ(scene.keptNodes.size(), 6u);
    expectHiddenNodes(jsonOf(source));  // the checker agrees with the source
    for (const char* ext : {".gltf", ".glb"}) {
        SCOPED_TRACE(ext);
        const fs::path saved = dir / (std::string("saved") + ext);
        saveGltf(scene, saved);
        expectHiddenNodes(jsonOf(saved));
        const Scene back = loadGltf(saved, log);
        EXPECT_EQ(back.nodes.size(), 2u);
        EXPECT_EQ(back.keptNodes.size(), 6u);
        const fs::path again = dir / (std::string("again") + ext);
        saveGltf(back, again);
        expectHiddenNodes(jsonOf(again));
    }
    Scene edited = scene;
    edited.nodes.at(static_cast<std::size_t>(edited.roots.at(0))).translation =
        glm::vec3(4.0f, 0.0f, 0.0f);  // "ground"
    saveGltf(edited, dir / "edited.gltf");
    expectHiddenNodes(jsonOf(dir / "edited.gltf"));
}

// Extras and extensions on every object the writer writes from the Scene: asset, samplers (and
// their names), images, texture references, pbrMetallicRoughness, scenes, textures, materials,
// animation samplers and channels.
fs::path extrasFile(const TempDir& dir) { return copyFixture(dir, "extras.gltf"); }

TEST(GltfRoundTrip, ExtrasOfEveryKindSurviveASave) {
    TempDir dir;
    QuietLog log;
    const fs::path source = extrasFile(dir);
    const json before = json::parse(lit::testing::readText(source));
    saveGltf(loadGltf(source, log), dir / "saved.gltf");
    const json after = json::parse(lit::testing::readText(dir / "saved.gltf"));
    EXPECT_EQ(after["asset"]["extras"], before["asset"]["extras"]);
    EXPECT_EQ(after["extras"], before["extras"]);
    EXPECT_EQ(after["scenes"][0]["extras"], before["scenes"][0]["extras"]);
    EXPECT_EQ(after["images"][0]["extras"], before["images"][0]["extras"]);
    EXPECT_EQ(after["images"][0]["name"], before["images"][0]["name"]);
    EXPECT_EQ(after["textures"][0]["extras"], before["textures"][0]["extras"]);
    EXPECT_EQ(after["materials"][0]["extras"], before["materials"][0]["extras"]);
    EXPECT_EQ(after["materials"][0]["pbrMetallicRoughness"]["extras"],
              before["materials"][0]["pbrMetallicRoughness"]["extras"]);
    EXPECT_EQ(after["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extras"],
              before["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extras"]);
    EXPECT_EQ(after["materials"][0]["normalTexture"]["extras"], before["materials"][0]["normalTexture"]["extras"]);
    EXPECT_EQ(after["animations"][0]["samplers"][0]["extras"], before["animations"][0]["samplers"][0]["extras"]);
    EXPECT_EQ(after["animations"][0]["channels"][0]["extras"], before["animations"][0]["channels"][0]["extras"]);
    // Two samplers with the same wrap and filters stay two when only one has a name and extras.
    ASSERT_EQ(after["samplers"].size(), 2u);
    const json& tiling = after["samplers"][after["textures"][0]["sampler"].get<std::size_t>()];
    EXPECT_EQ(tiling["name"], "tiling");
    EXPECT_EQ(tiling["extras"], before["samplers"][0]["extras"]);
    EXPECT_EQ(tiling["extensions"], before["samplers"][0]["extensions"]);
    EXPECT_EQ(after["samplers"][after["textures"][1]["sampler"].get<std::size_t>()].count("name"), 0u);
    EXPECT_NE(std::find(after["extensionsUsed"].begin(), after["extensionsUsed"].end(), "EXT_lit_test"),
              after["extensionsUsed"].end());
}

// Names, extras and extensions of the accessors, buffer views and buffers whose data a save
// writes again: a kept attribute (TEXCOORD_1), a sparse morph target (its indices' and values'
// views too), an image in a buffer view, an animation's input and output; and the buffer. The
// animation sampler has extensions, and the asset a generator of another tool.
fs::path dataExtrasFile(const TempDir& dir) { return copyFixture(dir, "data_extras.gltf"); }

// The accessor of attribute `name` of the first primitive, and its buffer view.
const json& attributeAccessor(const json& doc, const std::string& name) {
    return doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"].at(name).get<std::size_t>()];
}
const json& viewOf(const json& doc, const json& accessorOrImage) {
    return doc["bufferViews"][accessorOrImage.at("bufferView").get<std::size_t>()];
}
json keptPart(const json& object) {  // name, extras, extensions (absent ones as null)
    return {object.value("name", json()), object.value("extras", json()), object.value("extensions", json())};
}

// Saves `source` as .gltf and .glb (each loaded from the last save: two trips), unedited and
// with an edit of the node, and calls `check(source json, saved json)` on each.
template <typename Check>
void forEachSave(const TempDir& dir, const fs::path& source, Check check) {
    QuietLog log;
    const json before = jsonOf(source);
    for (const char* ext : {".gltf", ".glb"}) {
        SCOPED_TRACE(ext);
        const fs::path saved = dir / (std::string("saved") + ext), again = dir / (std::string("again") + ext);
        saveGltf(loadGltf(source, log), saved);
        check(before, jsonOf(saved));
        saveGltf(loadGltf(saved, log), again);
        check(before, jsonOf(again));
        Scene edited = loadGltf(source, log);
        edited.nodes.at(0).translation = glm::vec3(0.0f, 2.0f, 0.0f);
        saveGltf(edited, dir / (std::string("edited") + ext));
        SCOPED_TRACE("edited");
        check(before, jsonOf(dir / (std::string("edited") + ext)));
    }
}

// Fails when a save drops them. About 20 ms.
TEST(GltfRoundTrip, AccessorBufferViewAndBufferExtrasSurviveASave) {
    TempDir dir;
    forEachSave(dir, dataExtrasFile(dir), [](const json& before, const json& after) {
        const json& uvBefore = attributeAccessor(before, "TEXCOORD_1");
        const json& uvAfter = attributeAccessor(after, "TEXCOORD_1");
        EXPECT_EQ(keptPart(uvAfter), keptPart(uvBefore));
        EXPECT_EQ(keptPart(viewOf(after, uvAfter)), keptPart(viewOf(before, uvBefore)));
        const auto targetOf = [](const json& doc) -> const json& {
            return doc["accessors"][doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"].get<std::size_t>()];
        };
        EXPECT_EQ(keptPart(targetOf(after)), keptPart(targetOf(before)));
        for (const char* part : {"indices", "values"}) {
            SCOPED_TRACE(part);
            EXPECT_EQ(keptPart(viewOf(after, targetOf(after)["sparse"][part])),
                      keptPart(viewOf(before, targetOf(before)["sparse"][part])));
        }
        EXPECT_EQ(keptPart(viewOf(after, after["images"][0])), keptPart(viewOf(before, before["images"][0])));
        for (const char* role : {"input", "output"}) {
            SCOPED_TRACE(role);
            const json& a = after["accessors"][after["animations"][0]["samplers"][0][role].get<std::size_t>()];
            const json& b = before["accessors"][before["animations"][0]["samplers"][0][role].get<std::size_t>()];
            EXPECT_EQ(keptPart(a), keptPart(b));
            EXPECT_EQ(keptPart(viewOf(after, a)), keptPart(viewOf(before, b)));
        }
        ASSERT_EQ(after["buffers"].size(), 1u);
        EXPECT_EQ(keptPart(after["buffers"][0]), keptPart(before["buffers"][0]));
        EXPECT_NE(std::find(after["extensionsUsed"].begin(), after["extensionsUsed"].end(), "EXT_lit_test"),
                  after["extensionsUsed"].end());
    });
}

// Fails when a save drops a sampler's extensions. About 20 ms.
TEST(GltfRoundTrip, AnimationSamplerExtensionsSurviveASave) {
    TempDir dir;
    forEachSave(dir, dataExtrasFile(dir), [](const json& before, const json& after) {
        EXPECT_EQ(after["animations"][0]["samplers"][0].value("extensions", json()),
                  before["animations"][0]["samplers"][0]["extensions"]);
        EXPECT_EQ(after["animations"][0]["samplers"][0].value("extras", json()),
                  before["animations"][0]["samplers"][0]["extras"]);
    });
}

// glTF's generator names the tool that wrote the file: a save writes "Lit", and keeps the
// source's in the asset's extras (also after a second save, whose source says "Lit"). Fails when
// the source's generator is lost. About 20 ms.
TEST(GltfRoundTrip, TheSourceGeneratorIsKeptInTheAssetExtras) {
    TempDir dir;
    forEachSave(dir, dataExtrasFile(dir), [](const json& before, const json& after) {
        EXPECT_EQ(after["asset"]["generator"], "Lit");
        EXPECT_EQ(after["asset"].value("extras", json()).value("litSourceGenerator", ""), before["asset"]["generator"]);
    });
    // A file Lit made from scratch has no source generator to keep.
    QuietLog log;
    Scene scene = loadGltf(dataExtrasFile(dir), log);
    scene.generator.clear();
    saveGltf(scene, dir / "own.gltf");
    EXPECT_FALSE(jsonOf(dir / "own.gltf")["asset"].value("extras", json::object()).contains("litSourceGenerator"));
}

// A 16-bit PNG (stb_image decodes it to 8 bits; a re-encode would lose the low bytes), its
// byte-identical copy (the loader decodes it once), a KTX2 image Lit cannot decode (its texture
// reads it through KHR_texture_basisu, with no fallback source) and a PNG in a data URI: a save
// writes each one's bytes as the file had them, with its MIME type, and adds no stand-in image.
// The fixture's .bin holds deep16.png (2x1 RGB, 16 bits per channel, uncompressed zlib data)
// twice and compressed.ktx2 (a KTX2 header without a real payload); its data URI is small.png.
TEST(GltfRoundTrip, EmbeddedImagesAreWrittenByteForByte) {
    TempDir dir;
    QuietLog log;
    const std::vector<std::uint8_t> deep = lit::testing::readFile(fixtureDir() / "deep16.png");
    const std::vector<std::uint8_t> ktx2 = lit::testing::readFile(fixtureDir() / "compressed.ktx2");
    const std::vector<std::uint8_t> small = lit::testing::readFile(fixtureDir() / "small.png");
    const fs::path source = copyFixture(dir, "images.gltf");
    const Scene scene = loadGltf(source, log);
    // stb_image read the 16-bit PNG (2×1, high bytes of the first pixel 0x12 0x56 0x9A), so the
    // file is a real one and the save must not write these 8-bit pixels instead.
    ASSERT_EQ(scene.images.at(0).width, 2);
    EXPECT_EQ(scene.images[0].rgba.at(0), 0x12);
    EXPECT_EQ(scene.images[0].rgba.at(2), 0x9A);
    saveGltf(scene, dir / "saved.gltf");
    const RawGltf saved = readRaw(dir / "saved.gltf");
    const json& images = saved.doc.at("images");
    ASSERT_EQ(images.size(), 4u) << "no image added or lost";
    const std::vector<std::vector<std::uint8_t>> expected = {deep, deep, ktx2, small};
    const char* mime[] = {"image/png", "image/png", "image/ktx2", "image/png"};
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE("image " + std::to_string(i));
        ASSERT_TRUE(images[i].contains("bufferView"));
        EXPECT_EQ(viewBytes(saved, images[i]["bufferView"].get<int>()), expected[i]);
        EXPECT_EQ(images[i].value("mimeType", ""), mime[i]);
    }
    const json& basisu = saved.doc.at("textures").at(2);
    EXPECT_FALSE(basisu.contains("source")) << "no stand-in source for the KTX2-only texture";
    EXPECT_EQ(basisu["extensions"]["KHR_texture_basisu"]["source"], 2);
}

// Sparse accessors of data Lit keeps are written sparse again: a morph target without a base
// (zeros, unsigned short indices) and a custom attribute whose base buffer view holds other
// values where the sparse ones (unsigned byte indices) replace them.
fs::path sparseFile(const TempDir& dir) { return copyFixture(dir, "sparse.gltf"); }

TEST(GltfRoundTrip, SparseAccessorsAreWrittenSparse) {
    TempDir dir;
    QuietLog log;
    const fs::path source = sparseFile(dir);
    saveGltf(loadGltf(source, log), dir / "saved.gltf");
    const tinygltf::Model before = readModel(source);
    const tinygltf::Model after = readModel(dir / "saved.gltf");
    const tinygltf::Primitive& a = before.meshes.at(0).primitives.at(0);
    const tinygltf::Primitive& p = after.meshes.at(0).primitives.at(0);
    ASSERT_EQ(p.targets.size(), 1u);
    ASSERT_TRUE(p.attributes.count("_WEIGHT"));
    const tinygltf::Accessor& target = after.accessors.at(static_cast<std::size_t>(p.targets[0].at("POSITION")));
    EXPECT_TRUE(target.sparse.isSparse);
    EXPECT_EQ(target.bufferView, -1) << "a base of zeros stays without a buffer view";
    EXPECT_EQ(target.sparse.count, 2);
    EXPECT_EQ(target.sparse.indices.componentType, 5123);
    const tinygltf::Accessor& weight = after.accessors.at(static_cast<std::size_t>(p.attributes.at("_WEIGHT")));
    EXPECT_TRUE(weight.sparse.isSparse);
    EXPECT_GE(weight.bufferView, 0);
    EXPECT_EQ(weight.sparse.count, 1);
    EXPECT_EQ(weight.sparse.indices.componentType, 5121);
    // The base keeps the file's 3 under the sparse 9, and the expanded values are the file's.
    tinygltf::Accessor baseOnly = weight;
    baseOnly.sparse.isSparse = false;
    tinygltf::Model withBase = after;
    withBase.accessors.push_back(baseOnly);
    EXPECT_EQ(elements(withBase, static_cast<int>(withBase.accessors.size()) - 1),
              (std::vector<std::vector<double>>{{1}, {2}, {3}, {4}}));
    EXPECT_EQ(corners(after, p, p.attributes.at("_WEIGHT")), corners(before, a, a.attributes.at("_WEIGHT")));
    EXPECT_EQ(corners(after, p, p.targets[0].at("POSITION")), corners(before, a, a.targets[0].at("POSITION")));
}

// A file laid out as Lit would not write it: the shown scene's
// nodes after a node of no scene, a node with a `matrix`, POSITION/NORMAL/TEXCOORD_0 each in a
// view of its own with names, extras and extensions, UNSIGNED_SHORT indices with min/max, a
// second mesh sharing the first one's accessors (as Blender writes identical data once), a
// non-indexed primitive with a sparse morph target whose `sparse`, `indices` and `values` carry
// extras and extensions, a TEXCOORD_1 with min/max, and animations with one input shared by two
// samplers (its min/max JSON doubles a float cannot hold), a normalized SHORT rotation and
// normalized UNSIGNED_BYTE morph weights.
fs::path losslessFile(const TempDir& dir) { return copyFixture(dir, "lossless.gltf"); }

// An edit of a sparse morph target where the file stored zeros (no base view): the accessor stays
// sparse with one more index, keeps the file's extras and extensions of its `sparse`, `indices`
// and `values` (which a dense accessor cannot hold) and the edited value reads back. Fails when
// the file's sparse layout is written as it was, which reads the edit back as 0. A few
// milliseconds.
TEST(GltfRoundTrip, AnEditedSparseAccessorStaysSparseWithItsExtras) {
    TempDir dir;
    QuietLog log;
    const fs::path source = losslessFile(dir);
    Scene scene = loadGltf(source, log);
    Mesh* tri = nullptr;
    for (Mesh& mesh : scene.meshes)
        if (mesh.name == "tri") tri = &mesh;
    ASSERT_NE(tri, nullptr);
    ASSERT_EQ(tri->primitives.size(), 1u);
    ASSERT_EQ(tri->primitives[0].morphTargets.size(), 1u);
    KeptAccessor& target = tri->primitives[0].morphTargets[0].at("POSITION");
    ASSERT_TRUE(target.sparse.has_value());
    ASSERT_EQ(target.count, 3u);
    const float moved[3] = {0.25f, 0.0f, 0.0f};  // element 0, a zero of the base before
    std::memcpy(target.bytes.data(), moved, sizeof moved);
    const json want = jsonOf(source);
    const std::size_t targetIndex = want["meshes"][2]["primitives"][0]["targets"][0]["POSITION"].get<std::size_t>();
    const json& wantSparse = want["accessors"][targetIndex]["sparse"];
    for (const char* ext : {".gltf", ".glb"}) {
        SCOPED_TRACE(ext);
        const fs::path saved = dir / (std::string("sparse_edited") + ext);
        saveGltf(scene, saved);
        const json got = jsonOf(saved);
        const json& accessor =
            got["accessors"][got["meshes"][2]["primitives"][0]["targets"][0]["POSITION"].get<std::size_t>()];
        ASSERT_TRUE(accessor.contains("sparse")) << accessor.dump();
        EXPECT_FALSE(accessor.contains("bufferView")) << "the base stays zeros";
        const json& sparse = accessor["sparse"];
        EXPECT_EQ(sparse["count"], 2);
        EXPECT_EQ(sparse["indices"]["componentType"], wantSparse["indices"]["componentType"]);
        EXPECT_EQ(sparse.value("extras", json()), wantSparse["extras"]);
        EXPECT_EQ(sparse.value("extensions", json()), wantSparse["extensions"]);
        EXPECT_EQ(sparse["indices"].value("extras", json()), wantSparse["indices"]["extras"]);
        EXPECT_EQ(sparse["values"].value("extensions", json()), wantSparse["values"]["extensions"]);
        const tinygltf::Model model = readModel(saved);
        const int index = model.meshes.at(2).primitives.at(0).targets.at(0).at("POSITION");
        EXPECT_EQ(elements(model, index), (std::vector<std::vector<double>>{{0.25, 0, 0}, {0, 0, 0}, {0, 0, 0.5}}));
    }
}

// The lossless file with its .bin laid out as Lit would not pack it: the views in reverse order,
// each 16-byte aligned after a gap of zeros.
fs::path shuffledLayoutFile(const TempDir& dir) { return copyFixture(dir, "shuffled.gltf"); }

// The buffer's layout: every buffer view whose bytes a save
// writes unchanged is at the file's byteOffset, so an unedited file's .bin comes back byte for
// byte (the generated test file, the same with its views in reverse order and gaps between them,
// and Blender 3.4's exports); after an edit of one primitive the file's views stay where they
// were and the edited data goes into views of its own. Fails when a save packs the views its own
// way (in the order it writes them, 4-byte aligned, back to back: the reversed file's views all
// move; after an edit, every view after the edited data).
// About 10 ms a file.
TEST(GltfRoundTrip, UneditedBufferViewsKeepTheirByteOffsets) {
    TempDir dir;
    QuietLog log;
    const fs::path folder = fs::path(LIT_SOURCE_DIR) / "tests" / "data" / "blender";
    const auto viewData = [](const tinygltf::Model& model, std::size_t v) {
        const tinygltf::BufferView& view = model.bufferViews.at(v);
        const std::vector<unsigned char>& data = model.buffers.at(static_cast<std::size_t>(view.buffer)).data;
        if (view.byteOffset + view.byteLength > data.size()) throw std::runtime_error("buffer view past its buffer");
        return std::vector<unsigned char>(
            data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset),
            data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset + view.byteLength));
    };
    for (const fs::path& source : {shuffledLayoutFile(dir), losslessFile(dir), folder / "point.gltf",
                                   folder / "sun.gltf", folder / "rig.gltf"}) {
        const tinygltf::Model want = readModel(source);
        ASSERT_EQ(want.buffers.size(), 1u);
        Scene scene = loadGltf(source, log);
        for (const char* ext : {".gltf", ".glb"}) {
            SCOPED_TRACE(source.filename().string() + ext);
            const fs::path saved = dir / (source.stem().string() + "_saved" + ext);
            saveGltf(scene, saved);
            const tinygltf::Model got = readModel(saved);
            ASSERT_EQ(got.bufferViews.size(), want.bufferViews.size());
            for (std::size_t v = 0; v < want.bufferViews.size(); ++v) {
                EXPECT_EQ(got.bufferViews[v].byteOffset, want.bufferViews[v].byteOffset) << "buffer view " << v;
                EXPECT_EQ(viewData(got, v), viewData(want, v)) << "buffer view " << v;
            }
            // The whole buffer (a GLB's BIN chunk pads to 4 bytes, as the source .bin does).
            EXPECT_EQ(got.buffers.at(0).data, want.buffers.at(0).data);
        }
    }
    // An edit of the floor's positions: its view moves, every other view keeps its place and
    // bytes, and nothing overlaps.
    const fs::path source = dir / "lossless.gltf";
    const tinygltf::Model want = readModel(source);
    Scene scene = loadGltf(source, log);
    scene.meshes.at(0).primitives.at(0).vertices.at(1).position.x = 2.0f;
    for (const char* ext : {".gltf", ".glb"}) {
        SCOPED_TRACE(std::string("edited") + ext);
        const fs::path saved = dir / (std::string("edited") + ext);
        saveGltf(scene, saved);
        const tinygltf::Model got = readModel(saved);
        // (An edit renumbers views, so they are matched by their bytes.)
        std::vector<std::pair<std::size_t, std::size_t>> ranges;
        for (std::size_t v = 0; v < got.bufferViews.size(); ++v) {
            const tinygltf::BufferView& view = got.bufferViews[v];
            ranges.emplace_back(view.byteOffset, view.byteOffset + view.byteLength);
            bool fileBytes = false, fileOffset = false;
            for (std::size_t w = 0; w < want.bufferViews.size(); ++w)
                if (viewData(got, v) == viewData(want, w)) {
                    fileBytes = true;
                    fileOffset = fileOffset || view.byteOffset == want.bufferViews[w].byteOffset;
                }
            EXPECT_TRUE(!fileBytes || fileOffset) << "buffer view " << v << " holds the file's bytes at another offset";
        }
        std::size_t kept = 0;
        for (std::size_t w = 0; w < want.bufferViews.size(); ++w)
            for (std::size_t v = 0; v < got.bufferViews.size(); ++v)
                if (got.bufferViews[v].byteOffset == want.bufferViews[w].byteOffset &&
                    viewData(got, v) == viewData(want, w)) {
                    ++kept;
                    break;
                }
        // The twin mesh, which shared the floor's accessors, still holds the file's bytes: every
        // file view is found at its place, and the edited floor data is in views of its own.
        EXPECT_EQ(kept, want.bufferViews.size());
        EXPECT_GT(got.bufferViews.size(), want.bufferViews.size());
        std::sort(ranges.begin(), ranges.end());
        for (std::size_t r = 1; r < ranges.size(); ++r)
            EXPECT_LE(ranges[r - 1].second, ranges[r].first) << "views overlap";
        const Scene back = loadGltf(saved, log);
        EXPECT_EQ(back.meshes.at(0).primitives.at(0).vertices.at(1).position.x, 2.0f);
    }
}

// The parts of a document the writer lays out itself, made comparable: offsets (Lit packs the
// buffer its own way), view targets (the source has none) and defaults written out (TRIANGLES,
// LINEAR).
json comparable(json doc) {
    for (json& a : doc["accessors"]) {
        if (a.value("byteOffset", 0) == 0) a.erase("byteOffset");
        if (a.contains("sparse"))
            for (const char* part : {"indices", "values"})
                if (a["sparse"][part].value("byteOffset", 0) == 0) a["sparse"][part].erase("byteOffset");
    }
    for (json& animation : doc["animations"])
        for (json& sampler : animation["samplers"])
            if (sampler.value("interpolation", "LINEAR") == "LINEAR") sampler.erase("interpolation");
    for (json& v : doc["bufferViews"]) {
        v.erase("byteOffset");
        v.erase("target");
    }
    for (json& m : doc["meshes"])
        for (json& p : m["primitives"])
            if (p.value("mode", 4) == 4) p.erase("mode");
    return doc;
}

// The file's own JSON for node matrices, node indices, accessors (order, sharing, names, extras,
// extensions, min/max with the file's exact numbers, component types, sparse parts' extras and
// extensions), buffer views and animations, through .gltf and .glb, unedited and after an edit of
// another node; and every accessor's elements. Fails when a save writes TRS for a matrix, puts
// the kept node last, writes animation data as floats or drops the names of drawn accessors.
// A few milliseconds.
TEST(GltfRoundTrip, AnUnlitFileLayoutIsWrittenBackAsTheFileHadIt) {
    TempDir dir;
    QuietLog log;
    const fs::path source = losslessFile(dir);
    const json want = comparable(jsonOf(source));
    const tinygltf::Model sourceModel = readModel(source);
    Scene scene = loadGltf(source, log);
    ASSERT_EQ(scene.keptNodes.size(), 1u);  // "loose"
    Scene edited = scene;
    for (Node& node : edited.nodes)
        if (node.name == "lamp") node.translation = glm::vec3(0.0f, 4.0f, 0.0f);
    for (const auto& [name, which] : {std::pair{"unedited", &scene}, std::pair{"edited", &edited}})
        for (const char* ext : {".gltf", ".glb"}) {
            SCOPED_TRACE(std::string(name) + ext);
            const fs::path saved = dir / (std::string(name) + ext);
            saveGltf(*which, saved);
            json got = comparable(jsonOf(saved));
            if (which == &edited) {
                EXPECT_EQ(got["nodes"][2]["translation"], json::array({0.0, 4.0, 0.0}));
                got["nodes"][2]["translation"] = want["nodes"][2]["translation"];
            }
            EXPECT_EQ(got["nodes"], want["nodes"]);
            EXPECT_EQ(got["scenes"], want["scenes"]);
            EXPECT_EQ(got["meshes"], want["meshes"]);
            EXPECT_EQ(got["accessors"], want["accessors"]);
            EXPECT_EQ(got["animations"], want["animations"]);
            ASSERT_EQ(got["bufferViews"].size(), want["bufferViews"].size());
            for (std::size_t v = 0; v < want["bufferViews"].size(); ++v) {
                json view = got["bufferViews"][v];
                view.erase("buffer");
                json wanted = want["bufferViews"][v];
                wanted.erase("buffer");
                EXPECT_EQ(view, wanted) << "buffer view " << v;
            }
            const tinygltf::Model savedModel = readModel(saved);
            ASSERT_EQ(savedModel.accessors.size(), sourceModel.accessors.size());
            for (std::size_t a = 0; a < sourceModel.accessors.size(); ++a)
                EXPECT_EQ(elements(savedModel, static_cast<int>(a)), elements(sourceModel, static_cast<int>(a)))
                    << "accessor " << a;
        }
}

// What an edit changes: a moved matrix node is written as translation, rotation and scale (its
// other values the matrix's); edited geometry is written fresh (min/max recomputed from the new
// values, the file's names, extras and extensions of its accessors kept) while the file's layout
// stays; a node Lit adds goes after the file's nodes, which keep their indices. A few milliseconds.
TEST(GltfRoundTrip, EditsWriteFreshDataAndKeepTheRest) {
    TempDir dir;
    QuietLog log;
    const fs::path source = losslessFile(dir);
    const json want = comparable(jsonOf(source));
    Scene scene = loadGltf(source, log);
    std::size_t tilted = 0;
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].name == "tilted") tilted = i;
    scene.nodes[tilted].translation.x += 1.0f;
    Mesh& floor = scene.meshes.at(0);
    ASSERT_EQ(floor.name, "floor");
    floor.primitives.at(0).vertices.at(1).position.x = 2.0f;
    floor.primitives.at(0).vertices.at(2).uv.y = 3.0f;
    Node added;
    added.name = "added";
    scene.nodes.push_back(added);
    scene.roots.push_back(static_cast<int>(scene.nodes.size()) - 1);
    for (const char* ext : {".gltf", ".glb"}) {
        SCOPED_TRACE(ext);
        const fs::path saved = dir / (std::string("edited") + ext);
        saveGltf(scene, saved);
        const json got = comparable(jsonOf(saved));
        ASSERT_EQ(got["nodes"].size(), 6u);
        EXPECT_EQ(got["nodes"][5]["name"], "added");
        for (std::size_t n = 0; n < 5; ++n) EXPECT_EQ(got["nodes"][n]["name"], want["nodes"][n]["name"]);
        const json& node = got["nodes"][1];
        EXPECT_FALSE(node.contains("matrix"));
        // The matrix's columns: x → -2z, y → y, z → 2x: scale (2, 1, 2), 90° about y.
        ASSERT_TRUE(node.contains("translation") && node.contains("rotation") && node.contains("scale"));
        EXPECT_NEAR(node["translation"][0].get<double>(), 1.1, 1e-6);
        EXPECT_NEAR(node["translation"][2].get<double>(), 0.3, 1e-6);
        EXPECT_NEAR(node["scale"][0].get<double>(), 2.0, 1e-6);
        EXPECT_NEAR(node["scale"][2].get<double>(), 2.0, 1e-6);
        EXPECT_NEAR(std::abs(node["rotation"][1].get<double>()), std::sqrt(0.5), 1e-6);
        // The edited floor: fresh accessors in the file's layout, min/max of the new values, and
        // the file's names, extras and extensions of those accessors and views (which an edit
        // must not lose silently).
        const json& floorPrimitive = got["meshes"][0]["primitives"][0];
        const json& positions = got["accessors"][floorPrimitive["attributes"]["POSITION"].get<std::size_t>()];
        EXPECT_EQ(positions.value("name", ""), "floor positions");
        EXPECT_EQ(positions["max"][0], 2.0);
        const json& uvs = got["accessors"][floorPrimitive["attributes"]["TEXCOORD_0"].get<std::size_t>()];
        EXPECT_EQ(uvs.value("extras", json()), json({{"accessor", "uv"}}));
        EXPECT_EQ(uvs["max"], json::array({1.0, 3.0}));
        const json& normals = got["accessors"][floorPrimitive["attributes"]["NORMAL"].get<std::size_t>()];
        EXPECT_EQ(normals.value("extensions", json()), json({{"EXT_lit_test", {{"n", 1}}}}));
        const json& normalView = got["bufferViews"][normals["bufferView"].get<std::size_t>()];
        EXPECT_EQ(normalView.value("name", ""), "normal view");
        EXPECT_EQ(normalView.value("extras", json()), json({{"view", "normal"}}));
        const json& indices = got["accessors"][floorPrimitive["indices"].get<std::size_t>()];
        EXPECT_EQ(indices["componentType"], 5123);
        EXPECT_EQ(indices.value("name", ""), "floor indices");
        EXPECT_EQ(indices["max"], json::array({3}));
        EXPECT_FALSE(
            got["bufferViews"][positions["bufferView"].get<std::size_t>()].contains("byteStride"));  // not interleaved
        // The twin, unedited, keeps its names (it no longer shares the edited positions).
        const json& twin = got["meshes"][1]["primitives"][0];
        EXPECT_NE(twin["attributes"]["POSITION"], floorPrimitive["attributes"]["POSITION"]);
        EXPECT_EQ(got["accessors"][twin["attributes"]["POSITION"].get<std::size_t>()]["name"], "floor positions");
        EXPECT_EQ(got["accessors"][twin["indices"].get<std::size_t>()]["name"], "floor indices");
        for (std::size_t a = 0; a < want["animations"].size(); ++a)  // the nodes kept their indices
            EXPECT_EQ(got["animations"][a]["channels"], want["animations"][a]["channels"]);
        // Read back: the edit and every other value are there.
        const Scene back = loadGltf(saved, log);
        EXPECT_EQ(back.meshes.at(0).primitives.at(0).vertices.at(1).position.x, 2.0f);
        EXPECT_EQ(back.nodes.size(), scene.nodes.size());
    }
}

// Real Blender 3.4 exports (tests/data/blender: the lit scenes of tools/blender/make_scenes.py
// and rig.gltf of tools/blender/make_round_trip_scene.py, with a skin, an animated shape key, a
// colour attribute and a mesh two objects share) come back from a save with the same JSON
// (but for the generator, the buffer's layout and defaults written out) and every accessor's
// elements byte for byte, through .gltf and .glb; after moving one node only that node differs.
// About 10 ms a file.
TEST(GltfRoundTrip, BlenderExportsComeBackAsTheyWere) {
    TempDir dir;
    QuietLog log;
    const fs::path folder = fs::path(LIT_SOURCE_DIR) / "tests" / "data" / "blender";
    for (const char* name : {"point.gltf", "spot.gltf", "sun.gltf", "rig.gltf"}) {
        const fs::path source = folder / name;
        const json want = comparable(jsonOf(source));
        const tinygltf::Model sourceModel = readModel(source);
        Scene scene = loadGltf(source, log);
        ASSERT_FALSE(scene.nodes.empty());
        Scene edited = scene;
        edited.nodes[0].translation += glm::vec3(1.0f, 0.0f, 0.0f);
        for (const auto& [kind, which] : {std::pair{"unedited", &scene}, std::pair{"edited", &edited}})
            for (const char* ext : {".gltf", ".glb"}) {
                SCOPED_TRACE(std::string(name) + " " + kind + ext);
                const fs::path saved = dir / (fs::path(name).stem().string() + "_" + kind + ext);
                saveGltf(*which, saved);
                json got = comparable(jsonOf(saved));
                if (which == &edited) {
                    // Node 0 is scene.nodes[0]: Blender lists the shown scene's nodes first.
                    const float x = edited.nodes[0].translation.x;
                    ASSERT_EQ(got["nodes"][0]["translation"][0].get<double>(), static_cast<double>(x));
                    got["nodes"][0] = want["nodes"][0];
                }
                for (const char* key :
                     {"nodes", "scenes", "meshes", "accessors", "animations", "skins", "materials", "textures",
                      "samplers", "images", "cameras", "extensions", "extensionsUsed", "extensionsRequired"})
                    EXPECT_EQ(got.value(key, json()), want.value(key, json())) << key;
                ASSERT_EQ(got["bufferViews"].size(), want["bufferViews"].size());
                for (std::size_t v = 0; v < want["bufferViews"].size(); ++v) {
                    json view = got["bufferViews"][v];
                    json wanted = want["bufferViews"][v];
                    view.erase("buffer");
                    wanted.erase("buffer");
                    EXPECT_EQ(view, wanted) << "buffer view " << v;
                }
                const tinygltf::Model savedModel = readModel(saved);
                ASSERT_EQ(savedModel.accessors.size(), sourceModel.accessors.size());
                for (std::size_t a = 0; a < sourceModel.accessors.size(); ++a)
                    EXPECT_EQ(elements(savedModel, static_cast<int>(a)), elements(sourceModel, static_cast<int>(a)))
                        << "accessor " << a;
            }
    }
}

// A file that writes glTF defaults out (alphaCutoff 0.5, roughnessFactor 1, alphaMode OPAQUE,
// doubleSided false, texCoord 0, normal scale 1, ...), leaves others out (a texture without a
// sampler, a sampler without wraps or minFilter, a material with no fields, a scene without a
// name), gives an image by URI its optional mimeType and has material factors a float cannot
// hold (0.1, 0.7): a save writes exactly what the file had. Fails when a save drops the defaults,
// adds a default sampler, names the scene after the file, drops the mimeType or writes 0.1 as
// 0.10000000149011612. An edit of one factor changes only it.
// A few milliseconds.
fs::path defaultsFile(const TempDir& dir) { return copyFixture(dir, "defaults.gltf"); }

TEST(GltfRoundTrip, DefaultsAndExactFactorsAreWrittenAsTheFileHadThem) {
    TempDir dir;
    QuietLog log;
    const fs::path source = defaultsFile(dir);
    const json want = jsonOf(source);
    Scene scene = loadGltf(source, log);
    Scene edited = scene;
    ASSERT_EQ(edited.materials.size(), 2u);
    edited.materials[0].metallic = 0.25f;
    for (const auto& [kind, which] : {std::pair{"unedited", &scene}, std::pair{"edited", &edited}})
        for (const char* ext : {".gltf", ".glb"}) {
            SCOPED_TRACE(std::string(kind) + ext);
            const fs::path saved = dir / (std::string(kind) + ext);  // beside white.png: the same uri
            saveGltf(*which, saved);
            json got = jsonOf(saved);
            if (which == &edited) {
                EXPECT_EQ(got["materials"][0]["pbrMetallicRoughness"]["metallicFactor"], 0.25);
                got["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 0.7;
            }
            for (const char* key : {"materials", "textures", "samplers", "images", "scenes"})
                EXPECT_EQ(got.value(key, json()), want.value(key, json())) << key;
            // The numbers are the file's doubles, not their floats' (0.10000000149011612).
            EXPECT_EQ(got["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"][0].get<double>(), 0.1);
            // What the file wrote is read back the same way.
            const Scene back = loadGltf(saved, log);
            if (which == &scene) {
                EXPECT_EQ(back.materials, scene.materials);
            }
            EXPECT_FALSE(back.fileSceneNamed);
            EXPECT_EQ(back.name, kind);  // the loader names an unnamed scene after the file
        }
}

// A primitive whose TANGENTs are not unit length (glTF requires unit ones; some exporters write
// them scaled): drawn normalized, saved as the file had them while the tangents are unedited,
// normalized once one is edited. Fails when a save writes them normalized. A few milliseconds.
TEST(GltfRoundTrip, NonUnitTangentsAreWrittenAsTheFileHadThem) {
    TempDir dir;
    QuietLog log;
    // The fixture's TANGENTs.
    const std::vector<float> fileTangents = {2, 0, 0, 1, 0.5f, 0, 0, -1, 1, 0, 0, 1};
    const fs::path source = copyFixture(dir, "tangents.gltf");
    const Scene scene = loadGltf(source, log);
    const Primitive& primitive = scene.meshes.at(0).primitives.at(0);
    EXPECT_EQ(primitive.vertices.at(0).tangent, glm::vec4(1, 0, 0, 1));  // drawn normalized
    EXPECT_EQ(primitive.vertices.at(1).tangent, glm::vec4(1, 0, 0, -1));
    const auto savedTangents = [&](const Scene& s, const char* name) {
        saveGltf(s, dir / name);
        const tinygltf::Model model = readModel(dir / name);
        const tinygltf::Primitive& p = model.meshes.at(0).primitives.at(0);
        std::vector<float> out;
        for (const std::vector<double>& e : elements(model, p.attributes.at("TANGENT")))
            for (double c : e) out.push_back(static_cast<float>(c));
        return out;
    };
    EXPECT_EQ(savedTangents(scene, "unedited.gltf"), fileTangents);
    EXPECT_EQ(savedTangents(scene, "unedited.glb"), fileTangents);
    Scene edited = scene;
    edited.meshes[0].primitives[0].vertices[2].tangent = glm::vec4(0, 0, 1, 1);
    EXPECT_EQ(savedTangents(edited, "edited.gltf"), (std::vector<float>{1, 0, 0, 1, 1, 0, 0, -1, 0, 0, 1, 1}));
}

// The shared test scenes (../shared/scenes or LIT_SCENES_DIR: Khronos samples and Sponza, skipped
// where absent) come back from a save with the same JSON: nodes, scenes (unnamed ones stay
// unnamed), meshes, accessors, materials (defaults the file wrote out), textures, samplers (the
// DamagedHelmet's empty one), images (mimeType beside a uri; the uri itself points at the same
// file from the new folder) and buffer views (but for where Lit puts them in its buffer).
// Sponza takes about 2 s, the others a few ms each.
TEST(GltfRoundTrip, SharedScenesComeBackAsTheyWere) {
    const char* env = std::getenv("LIT_SCENES_DIR");
    const fs::path root = env && *env ? fs::path(env) : fs::path(LIT_SOURCE_DIR) / ".." / "shared" / "scenes";
    const std::vector<std::string> files = {
        "avocado/Avocado.gltf",          "box_textured/BoxTextured.gltf",        "damaged_helmet/DamagedHelmet.gltf",
        "water_bottle/WaterBottle.gltf", "cornell_box/CornellBox-Original.gltf", "sponza/Sponza.gltf"};
    TempDir dir;
    QuietLog log;
    int found = 0;
    for (const std::string& name : files) {
        const fs::path source = root / name;
        if (!fs::exists(source)) continue;
        ++found;
        SCOPED_TRACE(name);
        const fs::path saved = dir / fs::path(name).filename();
        saveGltf(loadGltf(source, log), saved);
        json want = comparable(jsonOf(source));
        json got = comparable(jsonOf(saved));
        for (json* doc : {&want, &got}) {
            for (json& image : (*doc)["images"])
                if (image.contains("uri"))
                    image["uri"] = fs::path(percentDecode(image["uri"].get<std::string>())).filename().string();
            for (json& view : (*doc)["bufferViews"]) view.erase("buffer");
        }
        for (const char* key : {"nodes", "scenes", "meshes", "accessors", "materials", "textures", "samplers", "images",
                                "bufferViews", "extensionsUsed", "extensionsRequired"})
            EXPECT_EQ(got.value(key, json()), want.value(key, json())) << key;
    }
    if (found == 0) GTEST_SKIP() << "no shared scenes in " << root.string() << " (set LIT_SCENES_DIR): skipped";
}

// The Khronos validator accepts the saved file (strides, min/max of morph POSITIONs, skins).
// Skipped without node or the validator (tools/install-gltf-validator.sh). About 1 s.
TEST(GltfRoundTrip, ValidatorAcceptsTheSavedFile) {
    std::string whyNot;
    const auto validatorDir = lit::testing::findGltfValidator(whyNot);
    if (validatorDir.empty()) GTEST_SKIP() << whyNot;
    TempDir dir;
    QuietLog log;
    const fs::path source = riggedFile(dir);
    saveGltf(loadGltf(source, log), dir / "saved.gltf");
    saveGltf(loadGltf(source, log), dir / "saved.glb");
    // Several scenes, sparse accessors and extras written back (the other round-trip cases; the
    // embedded-images case is not validated: its KTX2 image is not a real one).
    saveGltf(loadGltf(scenesFile(dir), log), dir / "scenes_saved.gltf");
    saveGltf(loadGltf(sparseFile(dir), log), dir / "sparse_saved.glb");
    saveGltf(loadGltf(extrasFile(dir), log), dir / "extras_saved.gltf");
    saveGltf(loadGltf(hiddenNodesFile(dir), log), dir / "hidden_saved.glb");
    saveGltf(loadGltf(dataExtrasFile(dir), log), dir / "data_extras_saved.gltf");
    saveGltf(loadGltf(losslessFile(dir), log), dir / "lossless_saved.glb");
    saveGltf(loadGltf(fs::path(LIT_SOURCE_DIR) / "tests" / "data" / "blender" / "rig.gltf", log),
             dir / "rig_saved.gltf");
    saveGltf(loadGltf(defaultsFile(dir), log), dir / "defaults_saved.gltf");
    // The file's own buffer layout kept (views reversed, gaps), and an edit of drawn geometry and
    // of a sparse morph target (new views in the gaps or after the end, the target re-sparsed).
    saveGltf(loadGltf(shuffledLayoutFile(dir), log), dir / "shuffled_saved.gltf");
    {
        Scene edited = loadGltf(dir / "shuffled.gltf", log);
        edited.meshes.at(0).primitives.at(0).vertices.at(1).position.x = 2.0f;
        for (Mesh& mesh : edited.meshes)
            if (mesh.name == "tri") {
                const float moved[3] = {0.25f, 0.0f, 0.0f};
                std::memcpy(mesh.primitives.at(0).morphTargets.at(0).at("POSITION").bytes.data(), moved, sizeof moved);
            }
        saveGltf(edited, dir / "shuffled_edited.glb");
    }
    std::vector<fs::path> files;
    for (const char* name : {"rigged.gltf",
                             "saved.gltf",
                             "saved.glb",
                             "scenes.gltf",
                             "scenes_saved.gltf",
                             "sparse.gltf",
                             "sparse_saved.glb",
                             "extras.gltf",
                             "extras_saved.gltf",
                             "hidden.gltf",
                             "hidden_saved.glb",
                             "data_extras.gltf",
                             "data_extras_saved.gltf",
                             "lossless.gltf",
                             "lossless_saved.glb",
                             "rig_saved.gltf",
                             "defaults.gltf",
                             "defaults_saved.gltf",
                             "shuffled.gltf",
                             "shuffled_saved.gltf",
                             "shuffled_edited.glb"})
        files.push_back(dir / name);
    std::string report;
    const int status = lit::testing::runGltfValidator(validatorDir, files, report, dir / "report.txt");
    std::printf("%s", report.c_str());
    // The source itself must be valid, or the test proves nothing about the writer.
    EXPECT_NE(report.find("rigged.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("scenes.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("sparse.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("extras.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("hidden.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("data_extras.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("lossless.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("defaults.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("shuffled.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_EQ(status, 0) << report;
}

}  // namespace
}  // namespace lit
