// The catalogue of malformed scenes (docs/RELIABILITY.md, "The catalogue of malformed scenes"):
// one named set, each kind made from the project's Cornell box by one mutation, each with what Lit
// must do with it. A file that cannot be drawn is
// refused with a SceneLoadError that names the file and the problem; a file whose values are only
// out of the spec's ranges loads, with a warning naming the value, and Lit draws the nearest valid
// value. The suite's sanitizer build (tools/lit.sh test-sanitize) runs the catalogue under
// ASan+UBSan. The loader tests (test_gltf_loader.cpp, test_gltf_guard.cpp) test each check in
// detail; this file is the list a reviewer reads to see what is covered.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "Log.h"
#include "TempDir.h"
#include "scene/GltfLoader.h"
#include "QuietLog.h"

namespace lit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The Cornell box as the mutations see it: its JSON and its buffer's bytes.
struct Files {
    json doc;
    std::vector<std::uint8_t> bin;
};

Files cornellBox() {
    const fs::path assets = fs::path(LIT_SOURCE_DIR) / "assets";
    Files f;
    f.doc = json::parse(lit::testing::readText(assets / "cornell_box.gltf"));
    f.bin = lit::testing::readFile(assets / "cornell_box.bin");
    return f;
}

void write(const fs::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}
void write(const fs::path& path, const std::string& text) { write(path, text.data(), text.size()); }

// Writes cornell.gltf + cornell.bin (the buffer's uri is pointed at it).
fs::path writeGltf(const fs::path& dir, Files f) {
    f.doc["buffers"][0]["uri"] = "cornell.bin";
    write(dir / "cornell.bin", f.bin.data(), f.bin.size());
    write(dir / "cornell.gltf", f.doc.dump());
    return dir / "cornell.gltf";
}

// A .glb of the document with its buffer in the BIN chunk.
std::vector<std::uint8_t> glbBytes(Files f) {
    f.doc["buffers"][0].erase("uri");
    std::string text = f.doc.dump();
    while (text.size() % 4) text += ' ';
    std::vector<std::uint8_t> bin = f.bin;
    while (bin.size() % 4) bin.push_back(0);
    std::vector<std::uint8_t> out;
    const auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    };
    u32(0x46546C67);  // "glTF"
    u32(2);
    u32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    u32(static_cast<std::uint32_t>(text.size()));
    u32(0x4E4F534A);  // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    u32(static_cast<std::uint32_t>(bin.size()));
    u32(0x004E4942);  // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

json& light(Files& f) { return f.doc["extensions"]["KHR_lights_punctual"]["lights"][0]; }
json& firstMaterial(Files& f) { return f.doc["materials"][0]; }
std::size_t nodeNamed(const Files& f, const std::string& name) {
    for (std::size_t i = 0; i < f.doc["nodes"].size(); ++i)
        if (f.doc["nodes"][i].value("name", "") == name) return i;
    ADD_FAILURE() << "the Cornell box has no node " << name;
    return 0;
}
// The byte offset in the buffer of element 0 of accessor `a`.
std::size_t accessorOffset(const Files& f, std::size_t a) {
    const json& accessor = f.doc["accessors"][a];
    const json& view = f.doc["bufferViews"][accessor["bufferView"].get<std::size_t>()];
    return view.value("byteOffset", std::size_t{0}) + accessor.value("byteOffset", std::size_t{0});
}
std::size_t primitiveAccessor(const Files& f, std::size_t mesh, const char* attribute) {
    const json& primitive = f.doc["meshes"][mesh]["primitives"][0];
    return std::string(attribute) == "indices" ? primitive["indices"].get<std::size_t>()
                                              : primitive["attributes"][attribute].get<std::size_t>();
}

// One kind of malformed scene: how to make it from the Cornell box, and what Lit must do.
struct Kind {
    std::string name;
    std::function<fs::path(const fs::path& dir)> make;
    std::string error;    // refused: the SceneLoadError holds this (and the file's name)
    std::string warning;  // loads: a warning holds this
    std::function<void(const Scene&)> check = nullptr;  // loads: what the scene must hold
};

// A mutation of the JSON or the buffer, written as .gltf + .bin.
std::function<fs::path(const fs::path&)> mutated(std::function<void(Files&)> mutate) {
    return [mutate](const fs::path& dir) {
        Files f = cornellBox();
        mutate(f);
        return writeGltf(dir, std::move(f));
    };
}
// Raw file contents under a name.
std::function<fs::path(const fs::path&)> raw(std::string name, std::function<std::vector<std::uint8_t>()> bytes) {
    return [name, bytes](const fs::path& dir) {
        const std::vector<std::uint8_t> b = bytes();
        write(dir / name, b.data(), b.size());
        return dir / name;
    };
}
std::vector<std::uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }
std::string cornellText() {
    Files f = cornellBox();
    f.doc["buffers"][0]["uri"] = "cornell.bin";
    return f.doc.dump(1);
}

std::vector<Kind> catalogue() {
    std::vector<Kind> kinds;
    const auto refused = [&](std::string name, std::function<fs::path(const fs::path&)> make, std::string error) {
        kinds.push_back({std::move(name), std::move(make), std::move(error), "", nullptr});
    };
    const auto loads = [&](std::string name, std::function<fs::path(const fs::path&)> make, std::string warning,
                           std::function<void(const Scene&)> check) {
        kinds.push_back({std::move(name), std::move(make), "", std::move(warning), std::move(check)});
    };

    // ---- the container -----------------------------------------------------------------------
    refused("EmptyFile", raw("empty.gltf", [] { return std::vector<std::uint8_t>{}; }), "empty");
    refused("RandomBytes", raw("noise.gltf", [] {
        std::vector<std::uint8_t> b(4096);
        std::uint32_t x = 12345;
        for (auto& v : b) v = static_cast<std::uint8_t>((x = x * 1664525u + 1013904223u) >> 24);
        return b;
    }), "not a glTF");
    refused("TruncatedJson", raw("half.gltf", [] {
        const std::string text = cornellText();
        return bytesOf(text.substr(0, text.size() / 2));
    }), "invalid JSON");
    refused("TruncatedGlb", raw("half.glb", [] {
        std::vector<std::uint8_t> b = glbBytes(cornellBox());
        b.resize(b.size() / 2);
        return b;
    }), "truncated");
    refused("JsonThatIsNotAnObject", raw("array.gltf", [] { return bytesOf("[1, 2, 3]"); }), "not a glTF");
    refused("NumberOverflow", raw("overflow.gltf", [] {
        std::string text = cornellText();
        const std::size_t at = text.find("\"intensity\": ");
        text.replace(at, std::string("\"intensity\": ").size(), "\"intensity\": 1e999, \"x\": ");
        return bytesOf(text);
    }), "invalid JSON");
    refused("DeeplyNestedExtras", mutated([](Files& f) {
        json deep = 1;
        for (int i = 0; i < 1000; ++i) deep = json::array({deep});
        f.doc["extras"] = deep;
    }), "nests deeper");
    refused("UnknownMajorVersion", mutated([](Files& f) { f.doc["asset"]["version"] = "3.0"; }), "3.0");
    refused("UnknownRequiredExtension", mutated([](Files& f) {
        f.doc["extensionsUsed"].push_back("EXT_made_up");
        f.doc["extensionsRequired"] = {"EXT_made_up"};
    }), "EXT_made_up");

    // ---- buffers and accessors ---------------------------------------------------------------
    refused("MissingBufferFile", [](const fs::path& dir) {
        Files f = cornellBox();
        f.doc["buffers"][0]["uri"] = "gone.bin";
        write(dir / "cornell.gltf", f.doc.dump());
        return dir / "cornell.gltf";
    }, "gone.bin");
    refused("BufferFileShorterThanDeclared", mutated([](Files& f) { f.bin.resize(f.bin.size() / 2); }), "cornell.bin");
    refused("BufferUriIsAFolder", [](const fs::path& dir) {
        Files f = cornellBox();
        f.doc["buffers"][0]["uri"] = ".";
        write(dir / "cornell.gltf", f.doc.dump());
        return dir / "cornell.gltf";
    }, "folder");
    refused("BufferViewPastTheBuffer", mutated([](Files& f) { f.doc["bufferViews"][0]["byteOffset"] = 1u << 30; }),
            "buffer view 0");
    refused("AccessorPastItsBufferView", mutated([](Files& f) { f.doc["accessors"][0]["count"] = 1000000; }),
            "reads past the end of buffer view");
    refused("AccessorIndexOutOfRange", mutated([](Files& f) {
        f.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 999;
    }), "999");
    refused("IndexValueOutOfRange", mutated([](Files& f) {
        const std::size_t at = accessorOffset(f, primitiveAccessor(f, 0, "indices"));
        const std::uint16_t big = 60000;  // the floor has a handful of vertices
        std::memcpy(f.bin.data() + at, &big, sizeof big);
    }), "out of range");
    refused("FloatIndices", mutated([](Files& f) {
        f.doc["accessors"][primitiveAccessor(f, 0, "indices")]["componentType"] = 5126;
    }), "must have an unsigned integer component type");

    // ---- references between objects ----------------------------------------------------------
    refused("NodeCycle", mutated([](Files& f) {
        f.doc["nodes"][0]["children"] = {1};
        f.doc["nodes"][1]["children"] = {0};
    }), "node cycle");
    refused("ChildIndexOutOfRange", mutated([](Files& f) { f.doc["nodes"][0]["children"] = {77}; }), "77");
    refused("MeshIndexOutOfRange", mutated([](Files& f) { f.doc["nodes"][0]["mesh"] = 42; }), "mesh 42");
    refused("MaterialIndexOutOfRange", mutated([](Files& f) { f.doc["meshes"][0]["primitives"][0]["material"] = 99; }),
            "material 99");
    refused("TextureIndexOutOfRange", mutated([](Files& f) {
        firstMaterial(f)["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 4}};
    }), "texture 4");
    refused("SceneIndexOutOfRange", mutated([](Files& f) { f.doc["scene"] = 7; }), "scene 7");
    refused("LightIndexOutOfRange", mutated([](Files& f) {
        f.doc["nodes"][nodeNamed(f, "ceiling_spot")]["extensions"]["KHR_lights_punctual"]["light"] = 5;
    }), "light 5");
    refused("UnknownLightType", mutated([](Files& f) { light(f)["type"] = "laser"; }), "unknown type 'laser'");

    // ---- values out of range: loaded with a warning, the nearest valid value drawn ------------
    loads("NonFiniteVertexPositions", mutated([](Files& f) {
        const std::size_t mesh = 5;  // tall_box
        const std::size_t at = accessorOffset(f, primitiveAccessor(f, mesh, "POSITION"));
        const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
        std::memcpy(f.bin.data() + at, &nan, sizeof nan);
        std::memcpy(f.bin.data() + at + 16, &inf, sizeof inf);
    }), "not finite", [](const Scene& scene) {
        const Mesh& box = scene.meshes[5];
        EXPECT_TRUE(std::isfinite(box.primitives[0].bounds.min.x) && std::isfinite(box.primitives[0].bounds.max.y));
        EXPECT_LT(box.primitives[0].indices.size(), 144u) << "the file's 48 triangles less those with the bad vertices";
        EXPECT_GT(box.primitives[0].indices.size(), 0u);
    });
    loads("NegativeLightIntensity", mutated([](Files& f) { light(f)["intensity"] = -5.0; }), "intensity -5",
          [](const Scene& scene) { EXPECT_EQ(scene.lights[0].intensity, 0.0f); });
    loads("LightColourOutsideZeroToOne", mutated([](Files& f) { light(f)["color"] = {-1.0, 0.5, 2.0}; }), "color (-1, 0.5, 2)",
          [](const Scene& scene) { EXPECT_EQ(scene.lights[0].color, glm::vec3(0.0f, 0.5f, 1.0f)); });
    loads("SpotConeAnglesInverted", mutated([](Files& f) {
        light(f)["spot"] = {{"innerConeAngle", 1.0}, {"outerConeAngle", 0.2}};
    }), "cone angles", [](const Scene& scene) {
        EXPECT_LT(scene.lights[0].innerConeAngle, scene.lights[0].outerConeAngle);
        EXPECT_FLOAT_EQ(scene.lights[0].outerConeAngle, 0.2f);
    });
    loads("SpotConeWiderThanAQuarterTurn", mutated([](Files& f) { light(f)["spot"]["outerConeAngle"] = 3.0; }),
          "cone angles", [](const Scene& scene) { EXPECT_LE(scene.lights[0].outerConeAngle, 1.5708f); });
    loads("CameraWithoutFieldOfView", mutated([](Files& f) { f.doc["cameras"][0]["perspective"]["yfov"] = -1.0; }),
          "yfov -1", [](const Scene& scene) { EXPECT_GT(scene.cameras[0].yfov, 0.0f); });
    loads("CameraNearPlaneAtZero", mutated([](Files& f) { f.doc["cameras"][0]["perspective"]["znear"] = 0.0; }),
          "znear 0", [](const Scene& scene) { EXPECT_GT(scene.cameras[0].znear, 0.0f); });
    loads("CameraFarPlaneBeforeNear", mutated([](Files& f) {
        f.doc["cameras"][0]["perspective"]["znear"] = 10.0;
        f.doc["cameras"][0]["perspective"]["zfar"] = 1.0;
    }), "infinite far plane", [](const Scene& scene) { EXPECT_EQ(scene.cameras[0].zfar, 0.0f); });
    loads("MaterialFactorsOutsideZeroToOne", mutated([](Files& f) {
        firstMaterial(f)["pbrMetallicRoughness"]["baseColorFactor"] = {1.5, -0.2, 0.5, 1.0};
        firstMaterial(f)["pbrMetallicRoughness"]["roughnessFactor"] = 7.0;
    }), "baseColorFactor (1.5, -0.2, 0.5, 1)", [](const Scene& scene) {
        EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(1.0f, 0.0f, 0.5f, 1.0f));
        EXPECT_EQ(scene.materials[0].roughness, 1.0f);
    });
    loads("ZeroRotationQuaternion", mutated([](Files& f) { f.doc["nodes"][nodeNamed(f, "tall_box")]["rotation"] = {0, 0, 0, 0}; }),
          "zero rotation quaternion", [](const Scene& scene) {
              for (const Node& node : scene.nodes)
                  for (int c = 0; c < 4; ++c)
                      for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(node.world[c][r]));
          });
    loads("MissingImageFile", mutated([](Files& f) {
        f.doc["images"] = {{{"uri", "nope.png"}}};
        f.doc["textures"] = {{{"source", 0}}};
        firstMaterial(f)["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    }), "nope.png", [](const Scene& scene) { EXPECT_EQ(scene.textures.size(), 1u); });
    return kinds;
}

// gtest names a failing parameter by this instead of its bytes.
void PrintTo(const Kind& kind, std::ostream* out) { *out << kind.name; }

using lit::testing::QuietLog;

class MalformedScene : public ::testing::TestWithParam<Kind> {};

TEST_P(MalformedScene, IsRefusedWithAClearErrorOrLoadsWithAWarning) {
    const Kind& kind = GetParam();
    lit::testing::TempDir dir("lit_malformed");
    const fs::path file = kind.make(dir.path());
    QuietLog log;
    if (!kind.error.empty()) {
        try {
            loadGltf(file, log);
            ADD_FAILURE() << kind.name << ": loaded; expected an error holding '" << kind.error << "'";
        } catch (const SceneLoadError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(kind.error), std::string::npos) << message;
            EXPECT_NE(message.find(file.filename().string()), std::string::npos) << "the file is not named: " << message;
        }
        return;
    }
    Scene scene;
    ASSERT_NO_THROW(scene = loadGltf(file, log)) << kind.name;
    bool warned = false;
    std::string warnings;
    for (const LogMessage& m : log.recent())
        if (m.level == LogLevel::Warning) {
            warnings += m.text + "\n";
            warned = warned || m.text.find(kind.warning) != std::string::npos;
        }
    EXPECT_TRUE(warned) << "no warning holds '" << kind.warning << "'; warnings:\n" << warnings;
    if (kind.check) kind.check(scene);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, MalformedScene, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<Kind>& info) { return info.param.name; });

// The catalogue holds 21 kinds at least and must not shrink below that unnoticed.
TEST(MalformedSceneCatalogue, HoldsAtLeast21Kinds) { EXPECT_GE(catalogue().size(), 21u); }

}  // namespace
}  // namespace lit
