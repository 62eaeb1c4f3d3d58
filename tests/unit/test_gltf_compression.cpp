// Compressed glTF geometry (renderer/scene/GltfCompression.cpp, GltfMeshopt.cpp, GltfDraco.cpp).
// The files are made the way users make them: Blender's export of the point scene
// (tests/data/blender/point.gltf) compressed by glTF-Transform's `draco` and `meshopt` commands
// (tests/data/compressed, made by tools/make-compressed-scenes.sh). Each must load to the
// geometry of the uncompressed file within the compression's quantization, save uncompressed,
// and a damaged one must give a one-line SceneLoadError naming the problem.

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "Log.h"
#include "GltfValidator.h"
#include "TempDir.h"
#include "io/LittleEndian.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "QuietLog.h"

namespace lit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

struct TempDir : lit::testing::TempDir {
    TempDir() : lit::testing::TempDir("lit_compression") {}
};

using lit::testing::QuietLog;

const fs::path kData = fs::path(LIT_SOURCE_DIR) / "tests" / "data";
const fs::path kUncompressed = kData / "blender" / "point.gltf";

// ---------------------------------------------------------------------------------------------
// Geometry in world space, per node name, compared order-independently (Draco reorders
// vertices and triangles; both compressors quantize).

struct WorldVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};
using Triangle = std::array<WorldVertex, 3>;

std::map<std::string, std::vector<Triangle>> worldTriangles(const Scene& scene) {
    std::map<std::string, std::vector<Triangle>> out;
    for (const Node& node : scene.nodes) {
        if (node.mesh < 0) continue;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(node.world)));
        for (const Primitive& p : scene.meshes.at(static_cast<std::size_t>(node.mesh)).primitives)
            for (std::size_t i = 0; i + 2 < p.indices.size(); i += 3) {
                Triangle t;
                for (int c = 0; c < 3; ++c) {
                    const Vertex& v = p.vertices.at(p.indices[i + static_cast<std::size_t>(c)]);
                    t[static_cast<std::size_t>(c)] = {glm::vec3(node.world * glm::vec4(v.position, 1.0f)),
                                                      glm::normalize(normalMatrix * v.normal), v.uv};
                }
                out[node.name].push_back(t);
            }
    }
    return out;
}

// How far apart two triangles are: the largest vertex distance of the best rotation of `b`
// (the winding must be the same; a compressor may start a triangle at another corner).
float triangleDistance(const Triangle& a, const Triangle& b, int& rotation) {
    float best = 1e30f;
    for (int r = 0; r < 3; ++r) {
        float worst = 0.0f;
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, glm::distance(a[static_cast<std::size_t>(c)].position,
                                                  b[static_cast<std::size_t>((c + r) % 3)].position));
        if (worst < best) {
            best = worst;
            rotation = r;
        }
    }
    return best;
}

// The tolerances: both tools quantize positions to 14 bits over the mesh's extent (the scene is
// 6 m across: 0.4 mm a step), normals to 8 (meshopt's octahedral) or 10 bits (Draco), UVs to 12.
constexpr float kPositionTolerance = 2e-3f;  // m
constexpr float kNormalCosine = 0.99f;       // 8°
constexpr float kUvTolerance = 2e-3f;

void expectSameGeometry(const Scene& expected, const Scene& actual, const std::string& label) {
    const auto want = worldTriangles(expected);
    const auto got = worldTriangles(actual);
    ASSERT_EQ(want.size(), got.size()) << label;
    ASSERT_GE(want.size(), 5u) << "the point scene has a floor, walls, a box and a sphere";
    for (const auto& [name, triangles] : want) {
        const auto found = got.find(name);
        ASSERT_NE(found, got.end()) << label << ": node " << name;
        ASSERT_EQ(found->second.size(), triangles.size()) << label << ": triangles of " << name;
        std::vector<char> used(found->second.size(), 0);
        std::size_t unmatched = 0;
        float worstNormal = 1.0f, worstUv = 0.0f;
        for (const Triangle& t : triangles) {
            std::size_t best = 0;
            int bestRotation = 0;
            float bestDistance = 1e30f;
            for (std::size_t u = 0; u < found->second.size(); ++u) {
                if (used[u]) continue;
                int rotation = 0;
                const float d = triangleDistance(t, found->second[u], rotation);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = u;
                    bestRotation = rotation;
                }
            }
            if (bestDistance > kPositionTolerance) {
                ++unmatched;
                continue;
            }
            used[best] = 1;
            for (int c = 0; c < 3; ++c) {
                const WorldVertex& a = t[static_cast<std::size_t>(c)];
                const WorldVertex& b = found->second[best][static_cast<std::size_t>((c + bestRotation) % 3)];
                worstNormal = std::min(worstNormal, glm::dot(a.normal, b.normal));
                worstUv = std::max(worstUv, glm::distance(a.uv, b.uv));
            }
        }
        EXPECT_EQ(unmatched, 0u) << label << ": triangles of " << name << " with no counterpart within "
                                 << kPositionTolerance << " m";
        EXPECT_GT(worstNormal, kNormalCosine) << label << ": normals of " << name;
        EXPECT_LT(worstUv, kUvTolerance) << label << ": UVs of " << name;
    }
}

// The camera animation ("fly"): meshopt compresses it too (exponential and quaternion filters).
void expectSameAnimation(const Scene& expected, const Scene& actual, const std::string& label) {
    ASSERT_EQ(expected.animations.size(), actual.animations.size()) << label;
    for (std::size_t a = 0; a < expected.animations.size(); ++a) {
        const Animation& want = expected.animations[a];
        const Animation& got = actual.animations[a];
        ASSERT_EQ(want.samplers.size(), got.samplers.size()) << label;
        for (std::size_t s = 0; s < want.samplers.size(); ++s) {
            ASSERT_EQ(want.samplers[s].input.size(), got.samplers[s].input.size()) << label;
            ASSERT_EQ(want.samplers[s].output.size(), got.samplers[s].output.size()) << label;
            for (std::size_t k = 0; k < want.samplers[s].input.size(); ++k)
                EXPECT_NEAR(want.samplers[s].input[k], got.samplers[s].input[k], 1e-4f) << label;
            // 0.1 % of the largest value: meshopt's exponential filter gives a vector one
            // exponent and 12-bit mantissas (the camera's translations, up to 6.5 m, move by up to
            // 2 mm), its quaternion filter 16-bit components.
            float largest = 1.0f;
            for (float v : want.samplers[s].output) largest = std::max(largest, std::abs(v));
            for (std::size_t k = 0; k < want.samplers[s].output.size(); ++k)
                EXPECT_NEAR(want.samplers[s].output[k], got.samplers[s].output[k], 1e-3f * largest) << label;
        }
    }
}

// ---------------------------------------------------------------------------------------------

class CompressedScenes : public ::testing::TestWithParam<const char*> {};

TEST_P(CompressedScenes, LoadToTheGeometryOfTheUncompressedFile) {
    QuietLog log;
    const Scene expected = loadGltf(kUncompressed, log);
    const Scene actual = loadGltf(kData / "compressed" / GetParam(), log);
    EXPECT_EQ(log.warnings(), 0u) << "a supported extension is not warned about";
    EXPECT_FALSE(actual.decodedCompression.empty());
    EXPECT_TRUE(actual.unknownExtensionsUsed.empty() ||
                std::none_of(actual.unknownExtensionsUsed.begin(), actual.unknownExtensionsUsed.end(),
                             [](const std::string& e) { return e.find("compression") != std::string::npos; }));
    EXPECT_EQ(actual.materials.size(), expected.materials.size());
    EXPECT_EQ(actual.lights.size(), expected.lights.size());
    EXPECT_EQ(actual.cameras.size(), expected.cameras.size());
    expectSameGeometry(expected, actual, GetParam());
    expectSameAnimation(expected, actual, GetParam());
}

// Saved uncompressed: no trace of the compression in the file, the geometry as loaded, and the
// note a front end logs names the extension.
TEST_P(CompressedScenes, SaveUncompressed) {
    TempDir dir;
    QuietLog log;
    const Scene loaded = loadGltf(kData / "compressed" / GetParam(), log);
    const std::string note = uncompressedSaveNote(loaded);
    EXPECT_NE(note.find("uncompressed"), std::string::npos) << note;
    EXPECT_NE(note.find(loaded.decodedCompression.at(0)), std::string::npos) << note;
    for (const char* name : {"saved.gltf", "saved.glb"}) {
        saveGltf(loaded, dir / name);
        const std::string text = lit::testing::readText(dir / name);
        EXPECT_EQ(text.find("EXT_meshopt_compression"), std::string::npos) << name;
        EXPECT_EQ(text.find("KHR_draco_mesh_compression"), std::string::npos) << name;
        const Scene reloaded = loadGltf(dir / name, log);
        EXPECT_TRUE(reloaded.decodedCompression.empty());
        EXPECT_TRUE(uncompressedSaveNote(reloaded).empty());
        expectSameGeometry(loaded, reloaded, std::string(GetParam()) + " saved as " + name);
        expectSameAnimation(loaded, reloaded, std::string(GetParam()) + " saved as " + name);
    }
    // The uncompressed save is no larger than a plain export of the same scene needs: the
    // compressed streams and fallback layout are not carried over.
    const Scene plain = loadGltf(kUncompressed, log);
    saveGltf(plain, dir / "plain.glb");
    EXPECT_LT(fs::file_size(dir / "saved.glb"), fs::file_size(dir / "plain.glb") * 5 / 4);
}

INSTANTIATE_TEST_SUITE_P(GltfTransform, CompressedScenes,
                         ::testing::Values("point_draco.glb", "point_meshopt.glb", "gltf/point_meshopt.gltf"),
                         [](const auto& info) {
                             std::string name = info.param;
                             std::replace_if(
                                 name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                             return name;
                         });

// ---------------------------------------------------------------------------------------------
// Damaged files: a GLB's JSON edited, its BIN chunk kept (or edited).

struct Glb {
    json doc;
    std::vector<std::uint8_t> bin;
};

Glb readGlb(const fs::path& path) {
    const std::vector<std::uint8_t> bytes = lit::testing::readFile(path);
    const std::uint32_t jsonLength = readLittleEndian32(bytes.data() + 12);
    Glb glb;
    glb.doc = json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength);
    const std::size_t bin = 20 + jsonLength;
    const std::uint32_t binLength = readLittleEndian32(bytes.data() + bin);
    glb.bin.assign(bytes.begin() + static_cast<std::ptrdiff_t>(bin + 8),
                   bytes.begin() + static_cast<std::ptrdiff_t>(bin + 8 + binLength));
    return glb;
}

fs::path writeGlb(const fs::path& path, const Glb& glb) {
    std::string text = glb.doc.dump();
    text.resize((text.size() + 3) & ~std::size_t(3), ' ');
    std::vector<std::uint8_t> bin = glb.bin;
    bin.resize((bin.size() + 3) & ~std::size_t(3), 0);
    std::vector<std::uint8_t> out;
    const auto put32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    };
    out.insert(out.end(), {'g', 'l', 'T', 'F'});
    put32(2);
    put32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    put32(static_cast<std::uint32_t>(text.size()));
    out.insert(out.end(), {'J', 'S', 'O', 'N'});
    out.insert(out.end(), text.begin(), text.end());
    put32(static_cast<std::uint32_t>(bin.size()));
    out.insert(out.end(), {'B', 'I', 'N', '\0'});
    out.insert(out.end(), bin.begin(), bin.end());
    std::ofstream file(path, std::ios::binary);
    file.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
    return path;
}

// The SceneLoadError of a load: one line that names the file.
std::string loadError(const fs::path& path) {
    QuietLog log;
    try {
        loadGltf(path, log);
    } catch (const SceneLoadError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected SceneLoadError, got " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected SceneLoadError for " << path;
    return {};
}

#define EXPECT_CONTAINS(text, phrase) EXPECT_NE((text).find(phrase), std::string::npos) << (text)

// The first primitive's Draco extension, and the first meshopt-compressed view of a mode.
json& dracoOf(Glb& glb) { return glb.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]; }
json& meshoptView(Glb& glb, const std::string& mode, std::size_t* index = nullptr) {
    for (std::size_t v = 0; v < glb.doc["bufferViews"].size(); ++v) {
        json& view = glb.doc["bufferViews"][v];
        if (view.contains("extensions") && view["extensions"]["EXT_meshopt_compression"]["mode"] == mode) {
            if (index) *index = v;
            return view;
        }
    }
    throw std::runtime_error("no meshopt view of mode " + mode);
}

TEST(GltfDraco, TheUntouchedFileLoads) {
    TempDir dir;
    QuietLog log;
    EXPECT_NO_THROW(loadGltf(writeGlb(dir / "same.glb", readGlb(kData / "compressed" / "point_draco.glb")), log));
}

TEST(GltfDraco, TruncatedDataIsAClearError) {
    TempDir dir;
    Glb glb = readGlb(kData / "compressed" / "point_draco.glb");
    const int view = dracoOf(glb)["bufferView"].get<int>();
    glb.doc["bufferViews"][static_cast<std::size_t>(view)]["byteLength"] =
        glb.doc["bufferViews"][static_cast<std::size_t>(view)]["byteLength"].get<int>() / 2;
    const std::string message = loadError(writeGlb(dir / "truncated.glb", glb));
    EXPECT_CONTAINS(message, "mesh 0");
    EXPECT_CONTAINS(message, "KHR_draco_mesh_compression: the Draco data in buffer view " + std::to_string(view));
    EXPECT_CONTAINS(message, "does not decode");
}

TEST(GltfDraco, ZeroedDataIsAClearError) {
    TempDir dir;
    Glb glb = readGlb(kData / "compressed" / "point_draco.glb");
    const json& view = glb.doc["bufferViews"][dracoOf(glb)["bufferView"].get<std::size_t>()];
    std::fill_n(glb.bin.begin() + view.value("byteOffset", 0), view["byteLength"].get<int>(), 0);
    EXPECT_CONTAINS(loadError(writeGlb(dir / "zeroed.glb", glb)), "does not decode");
}

TEST(GltfDraco, CountsThatDisagreeWithTheDataAreClearErrors) {
    TempDir dir;
    const Glb original = readGlb(kData / "compressed" / "point_draco.glb");
    {
        Glb glb = original;
        const int position = glb.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<int>();
        json& count = glb.doc["accessors"][static_cast<std::size_t>(position)]["count"];
        count = count.get<int>() + 1;
        const std::string message = loadError(writeGlb(dir / "points.glb", glb));
        EXPECT_CONTAINS(message, "points but the POSITION accessor " + std::to_string(position) + " has");
    }
    {
        Glb glb = original;
        const int indices = glb.doc["meshes"][0]["primitives"][0]["indices"].get<int>();
        json& count = glb.doc["accessors"][static_cast<std::size_t>(indices)]["count"];
        count = count.get<int>() - 3;
        EXPECT_CONTAINS(loadError(writeGlb(dir / "faces.glb", glb)), "triangles");
    }
    {
        Glb glb = original;
        dracoOf(glb)["attributes"]["POSITION"] = 77;
        EXPECT_CONTAINS(loadError(writeGlb(dir / "id.glb", glb)), "has no attribute with id 77 (POSITION)");
    }
    {
        Glb glb = original;
        dracoOf(glb)["bufferView"] = 999;
        EXPECT_CONTAINS(loadError(writeGlb(dir / "view.glb", glb)), "names buffer view 999, which does not exist");
    }
    {
        Glb glb = original;
        const std::size_t view = dracoOf(glb)["bufferView"].get<std::size_t>();
        glb.doc["bufferViews"][view]["byteOffset"] = glb.bin.size() - 4;
        EXPECT_CONTAINS(loadError(writeGlb(dir / "outside.glb", glb)), "lies outside its buffer");
    }
}

TEST(GltfMeshopt, TheUntouchedFileLoads) {
    TempDir dir;
    QuietLog log;
    EXPECT_NO_THROW(loadGltf(writeGlb(dir / "same.glb", readGlb(kData / "compressed" / "point_meshopt.glb")), log));
}

TEST(GltfMeshopt, TruncatedDataIsAClearError) {
    TempDir dir;
    for (const char* mode : {"ATTRIBUTES", "TRIANGLES"}) {
        Glb glb = readGlb(kData / "compressed" / "point_meshopt.glb");
        std::size_t index = 0;
        json& extension = meshoptView(glb, mode, &index)["extensions"]["EXT_meshopt_compression"];
        extension["byteLength"] = extension["byteLength"].get<int>() - 8;
        const std::string message = loadError(writeGlb(dir / "truncated.glb", glb));
        EXPECT_CONTAINS(message, "buffer view " + std::to_string(index) + ": EXT_meshopt_compression " + mode);
        EXPECT_CONTAINS(message, "does not decode");
    }
}

TEST(GltfMeshopt, FieldsOutsideTheSpecAreClearErrors) {
    TempDir dir;
    const Glb original = readGlb(kData / "compressed" / "point_meshopt.glb");
    const auto expectError = [&](const std::string& mode, const std::function<void(json&, json&)>& edit,
                                 const std::string& phrase) {
        Glb glb = original;
        json& view = meshoptView(glb, mode);
        edit(view, view["extensions"]["EXT_meshopt_compression"]);
        EXPECT_CONTAINS(loadError(writeGlb(dir / "edited.glb", glb)), phrase);
    };
    // More elements than the view holds.
    expectError(
        "ATTRIBUTES", [](json&, json& e) { e["count"] = e["count"].get<int>() * 4; }, "more than the buffer view's");
    // Strides libmeshoptimizer would assert on.
    expectError(
        "ATTRIBUTES",
        [](json& v, json& e) {
            e["byteStride"] = 6;
            v["byteLength"] = 6 * e["count"].get<int>();
        },
        "ATTRIBUTES byteStride 6 is not a multiple of 4");
    expectError(
        "TRIANGLES", [](json&, json& e) { e["byteStride"] = 1; }, "TRIANGLES byteStride 1 is not 2 or 4");
    expectError(
        "TRIANGLES", [](json&, json& e) { e["count"] = e["count"].get<int>() - 1; }, "is not a multiple of 3");
    expectError(
        "ATTRIBUTES", [](json&, json& e) { e["mode"] = "POINTS"; }, "mode 'POINTS' is not");
    expectError(
        "ATTRIBUTES",
        [](json&, json& e) {
            e["filter"] = "QUATERNION";
            e["byteStride"] = 4;
        },
        "QUATERNION needs byteStride 8");
    expectError(
        "ATTRIBUTES", [](json&, json& e) { e["filter"] = "LOG"; }, "filter 'LOG' is not");
    expectError(
        "ATTRIBUTES", [](json&, json& e) { e.erase("count"); }, "EXT_meshopt_compression has no 'count'");
    expectError(
        "ATTRIBUTES", [](json&, json& e) { e["byteOffset"] = 1u << 30; }, "lies outside its buffer");
    // The compressed data must not come from the fallback buffer itself.
    expectError(
        "ATTRIBUTES", [](json& v, json& e) { e["buffer"] = v["buffer"]; }, "a fallback buffer that holds no data");
    expectError(
        "ATTRIBUTES", [](json& v, json&) { v["byteOffset"] = 1u << 30; }, "lies outside buffer");
}

// The INDICES mode (index sequences: gltf-transform writes it for non-triangle primitives),
// made here with libmeshoptimizer's encoder: decoded, and damaged.
TEST(GltfMeshopt, IndexSequencesDecode) {
    TempDir dir;
    // A triangle: 3 positions (plain) and 3 uint16 indices encoded as a sequence.
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const unsigned int indices[3] = {2, 0, 1};
    std::vector<unsigned char> encoded(meshopt_encodeIndexSequenceBound(3, 3));
    encoded.resize(meshopt_encodeIndexSequence(encoded.data(), encoded.size(), indices, 3));
    ASSERT_GT(encoded.size(), 0u);
    Glb glb;
    glb.bin.assign(reinterpret_cast<const std::uint8_t*>(positions),
                   reinterpret_cast<const std::uint8_t*>(positions) + 36);
    glb.bin.insert(glb.bin.end(), encoded.begin(), encoded.end());
    glb.doc = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"EXT_meshopt_compression"}},
        {"extensionsRequired", {"EXT_meshopt_compression"}},
        {"buffers",
         json::array({{{"byteLength", glb.bin.size()}},
                      {{"byteLength", 8}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteLength", 36}},
                                     {{"buffer", 1},
                                      {"byteLength", 6},
                                      {"extensions",
                                       {{"EXT_meshopt_compression",
                                         {{"buffer", 0},
                                          {"byteOffset", 36},
                                          {"byteLength", encoded.size()},
                                          {"byteStride", 2},
                                          {"count", 3},
                                          {"mode", "INDICES"}}}}}}})},
        {"accessors", json::array({{{"bufferView", 0},
                                    {"componentType", 5126},
                                    {"count", 3},
                                    {"type", "VEC3"},
                                    {"min", {0, 0, 0}},
                                    {"max", {1, 1, 0}}},
                                   {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}})},
        {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}})}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"scenes", json::array({{{"nodes", {0}}}})},
        {"scene", 0}};
    QuietLog log;
    const Scene scene = loadGltf(writeGlb(dir / "sequence.glb", glb), log);
    const Primitive& triangle = scene.meshes.at(0).primitives.at(0);
    ASSERT_EQ(triangle.indices.size(), 3u);
    // Lit unwelds a primitive without normals (the vertices follow the indices): compare the
    // corners the indices name.
    for (std::size_t c = 0; c < 3; ++c)
        EXPECT_EQ(triangle.vertices.at(triangle.indices[c]).position,
                  glm::vec3(positions[3 * indices[c]], positions[3 * indices[c] + 1], positions[3 * indices[c] + 2]))
            << "corner " << c;

    glb.doc["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 1;
    EXPECT_CONTAINS(loadError(writeGlb(dir / "short.glb", glb)),
                    "INDICES data (1 bytes for 3 elements) does not decode");
}

// ---------------------------------------------------------------------------------------------
// With glTF-Transform installed (tools/install-gltf-transform.sh): the point scene compressed
// at test time, with settings other than the committed files' (meshopt "medium": no filters;
// Draco with 16-bit positions), loads to the same geometry.

fs::path gltfTransformTool() {
    const char* env = std::getenv("LIT_GLTF_TRANSFORM_DIR");
    const char* home = std::getenv("HOME");
    const char* cache = std::getenv("XDG_CACHE_HOME");
    const fs::path dir = env && *env ? fs::path(env)
                                     : (cache && *cache ? fs::path(cache) : fs::path(home ? home : "") / ".cache") /
                                           "lit" / "gltf-transform";
    return dir / "node_modules" / ".bin" / "gltf-transform";
}

TEST(GltfCompression, GltfTransformOutputLoadsAtTestTime) {
    const fs::path tool = gltfTransformTool();
    if (std::system("node --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "node is not installed: skipped";
    if (!fs::exists(tool))
        GTEST_SKIP() << "gltf-transform not found at " << tool.string()
                     << " (run tools/install-gltf-transform.sh): skipped; the committed files are tested above";
    TempDir dir;
    QuietLog log;
    const Scene expected = loadGltf(kUncompressed, log);
    const std::vector<std::pair<std::string, std::string>> runs = {{"meshopt --level medium", "medium.glb"},
                                                                   {"draco --quantize-position 16", "draco16.gltf"}};
    for (const auto& [command, output] : runs) {
        const std::string line = "'" + tool.string() + "' " + command.substr(0, command.find(' ')) + " '" +
                                 kUncompressed.string() + "' '" + (dir / output).string() + "'" +
                                 command.substr(command.find(' ')) + " > '" + (dir / "log.txt").string() + "' 2>&1";
        ASSERT_EQ(std::system(line.c_str()), 0) << line << "\n" << lit::testing::readText(dir / "log.txt");
        const Scene actual = loadGltf(dir / output, log);
        EXPECT_FALSE(actual.decodedCompression.empty()) << command;
        expectSameGeometry(expected, actual, command);
    }
}

// The Khronos validator accepts the compressed sources and the uncompressed saves. Skipped
// without node or the validator (tools/install-gltf-validator.sh).
TEST(GltfCompression, ValidatorAcceptsTheSourcesAndTheSaves) {
    std::string whyNot;
    const auto validatorDir = lit::testing::findGltfValidator(whyNot);
    if (validatorDir.empty()) GTEST_SKIP() << whyNot;
    TempDir dir;
    QuietLog log;
    std::vector<fs::path> files;
    for (const char* source : {"point_draco.glb", "point_meshopt.glb", "gltf/point_meshopt.gltf"}) {
        const fs::path path = kData / "compressed" / source;
        std::string stem = path.stem().string();
        saveGltf(loadGltf(path, log), dir / (stem + "_saved.gltf"));
        saveGltf(loadGltf(path, log), dir / (stem + "_saved.glb"));
        files.insert(files.end(), {path, dir / (stem + "_saved.gltf"), dir / (stem + "_saved.glb")});
    }
    std::string report;
    const int status = lit::testing::runGltfValidator(validatorDir, files, report, dir / "report.txt");
    std::printf("%s", report.c_str());
    EXPECT_NE(report.find("point_draco.glb: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("point_meshopt.glb: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("point_draco_saved.glb: 0 errors"), std::string::npos) << report;
    EXPECT_NE(report.find("point_meshopt_saved.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_EQ(status, 0) << report;
}

}  // namespace
}  // namespace lit
