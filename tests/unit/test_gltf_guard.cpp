// The hardened loader front (renderer/io/GltfGuard.h) through loadGltf: each test is one of the
// hostile inputs the guard exists for (deep JSON, a folder or an escaping path as a URI,
// amplification, unknown versions) written small into a fresh folder. Each must give a
// SceneLoadError naming the file (or load correctly), never a crash, an allocation of the file
// system's whim or a hang.

#include <gtest/gtest.h>

#include "TempDir.h"
#include <stb/stb_image_write.h>
#include <sys/stat.h>
#include <unistd.h>

#include <ctime>
#include <cstring>
#include <vector>
#include <fstream>
#include <nlohmann/json.hpp>

#include "Log.h"
#include "scene/GltfLoader.h"
#include "QuietLog.h"

namespace lit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

struct TempDir : lit::testing::TempDir {
    TempDir() : lit::testing::TempDir("lit_guard") {}
};

void writeBytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << path;
}
void writeText(const fs::path& path, const std::string& text) {
    writeBytes(path, std::vector<std::uint8_t>(text.begin(), text.end()));
}

using lit::testing::QuietLog;

// One triangle: positions (36 bytes) then uint16 indices (6 bytes) in "tri.bin".
std::vector<std::uint8_t> triangleBin() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[3] = {0, 1, 2};
    std::vector<std::uint8_t> bin(44, 0);
    std::memcpy(bin.data(), positions, 36);
    std::memcpy(bin.data() + 36, indices, 6);
    return bin;
}

json triangleDoc(const std::string& bufferUri = "tri.bin", int primitives = 1) {
    json primitive = {{"attributes", {{"POSITION", 0}}}, {"indices", 1}};
    json list = json::array();
    for (int i = 0; i < primitives; ++i) list.push_back(primitive);
    return {{"asset", {{"version", "2.0"}}},
            {"buffers", json::array({{{"uri", bufferUri}, {"byteLength", 44}}})},
            {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                         {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}})},
            {"accessors", json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                                        {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                                       {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}})},
            {"meshes", json::array({{{"primitives", list}}})},
            {"nodes", json::array({{{"mesh", 0}}})},
            {"scenes", json::array({{{"nodes", {0}}}})},
            {"scene", 0}};
}

fs::path writeScene(const TempDir& dir, const std::string& name, const json& doc) {
    writeBytes(dir / "tri.bin", triangleBin());
    const fs::path path = dir / name;
    writeText(path, doc.dump());
    return path;
}

std::string loadError(const fs::path& path, const GltfLoadOptions& options = {}) {
    QuietLog log;
    try {
        loadGltf(path, log, options);
    } catch (const SceneLoadError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path.filename().string()), std::string::npos) << "the message names the file: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
        return message;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected SceneLoadError, got: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected SceneLoadError for " << path;
    return {};
}

#define EXPECT_CONTAINS(text, phrase) EXPECT_NE((text).find(phrase), std::string::npos) << (text)

std::vector<std::uint8_t> png(int width, int height, std::uint8_t value) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, value);
    std::vector<std::uint8_t> out;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* bytes = static_cast<std::vector<std::uint8_t>*>(context);
            bytes->insert(bytes->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
        },
        &out, width, height, 4, rgba.data(), width * 4);
    return out;
}

TEST(GltfGuard, TheTriangleLoads) {
    TempDir dir;
    QuietLog log;
    const Scene scene = loadGltf(writeScene(dir, "ok.gltf", triangleDoc()), log);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].primitives[0].indices.size(), 3u);
}

// Extras nested 1,000-100,000 levels deep overflow tinygltf's recursion.
TEST(GltfGuard, DeepJsonIsRefusedBeforeTinygltfRecurses) {
    TempDir dir;
    for (const int depth : {65, 1000, 100000}) {
        json doc = triangleDoc();
        std::string text = doc.dump();
        const std::string extras = "\"extras\":" + std::string(static_cast<std::size_t>(depth), '[') +
                                   std::string(static_cast<std::size_t>(depth), ']') + ",";
        text.insert(1, extras);
        const fs::path path = dir / ("deep" + std::to_string(depth) + ".gltf");
        writeBytes(dir / "tri.bin", triangleBin());
        writeText(path, text);
        EXPECT_CONTAINS(loadError(path), "nests deeper than 64 levels");
    }
    // 60 levels of extras (61 with the root object) are within the limit and load.
    json doc = triangleDoc();
    std::string text = doc.dump();
    text.insert(1, "\"extras\":" + std::string(60, '[') + std::string(60, ']') + ",");
    writeText(dir / "deep60.gltf", text);
    QuietLog log;
    EXPECT_NO_THROW(loadGltf(dir / "deep60.gltf", log));
}

TEST(GltfGuard, TooManyJsonValuesAreRefused) {
    TempDir dir;
    json doc = triangleDoc();
    doc["extras"] = std::vector<int>(500, 7);
    GltfLoadOptions options;
    options.limits.maxJsonValues = 400;  // the triangle itself has ~60 values
    EXPECT_CONTAINS(loadError(writeScene(dir, "values.gltf", doc), options), "more than 400 values");
}

// A uri naming a folder makes tinygltf try to allocate ~2^63 bytes.
TEST(GltfGuard, AFolderAsBufferOrImageIsNotRead) {
    TempDir dir;
    fs::create_directories(dir / "sub");
    for (const std::string& uri : std::vector<std::string>{".", "sub", "sub/"}) {
        const std::string message = loadError(writeScene(dir, "folder.gltf", triangleDoc(uri)));
        EXPECT_CONTAINS(message, "File not found");
    }
    json doc = triangleDoc();
    doc["images"] = json::array({{{"uri", "."}}});
    doc["textures"] = json::array({{{"source", 0}}});
    QuietLog log;
    const Scene scene = loadGltf(writeScene(dir, "image_folder.gltf", doc), log);  // a white texture, a warning
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].width, 1);
}

TEST(GltfGuard, UrisOutsideTheScenesFolderAreRefused) {
    TempDir dir;
    fs::create_directories(dir / "scene");
    writeBytes(dir / "outside.bin", triangleBin());
    const fs::path scene = dir / "scene" / "escape.gltf";
    for (const std::string& uri : std::vector<std::string>{"../outside.bin", "%2E%2E/outside.bin", (dir / "outside.bin").string(),
                                                           "file://" + (dir / "outside.bin").string(), "file:///etc/passwd",
                                                           "/etc/passwd", "sub/../../outside.bin"}) {
        writeText(scene, triangleDoc(uri).dump());
        EXPECT_CONTAINS(loadError(scene), "points outside the scene's folder") << uri;
    }
    json doc = triangleDoc();
    doc["images"] = json::array({{{"uri", "/etc/passwd"}}});
    writeBytes(dir / "scene" / "tri.bin", triangleBin());
    writeText(scene, doc.dump());
    EXPECT_CONTAINS(loadError(scene), "image 0's uri '/etc/passwd' points outside");
    doc["images"] = json::array({{{"uri", "file:///etc/passwd"}}});
    writeText(scene, doc.dump());
    EXPECT_CONTAINS(loadError(scene), "image 0's uri 'file:///etc/passwd' points outside");
    // An image by a relative path that goes up is read (Lit's Save As writes such paths): its
    // bytes only become pixels.
    writeBytes(dir / "up.png", {0x89, 'P', 'N', 'G'});
    doc["images"] = json::array({{{"uri", "../up.png"}}});
    writeText(scene, doc.dump());
    {
        QuietLog log;
        EXPECT_EQ(loadGltf(scene, log).images.size(), 1u);
    }

    // The opt-in reads it.
    GltfLoadOptions options;
    options.limits.allowExternalUris = true;
    writeText(scene, triangleDoc("../outside.bin").dump());
    QuietLog log;
    EXPECT_EQ(loadGltf(scene, log, options).meshes.size(), 1u);
}

// An absolute path or a file: URI names a file anywhere: refused without the opt-in, read with
// it. tinygltf joins every URI onto the scene's folder ("scene/" + "/data/tri.bin"), so left to
// tinygltf the opt-in would still end in "File not found".
TEST(GltfGuard, AbsolutePathsAndFileUrisAreReadOnlyWithTheOptIn) {
    TempDir dir;
    fs::create_directories(dir / "scene");
    fs::create_directories(dir / "data");
    writeBytes(dir / "data" / "tri.bin", triangleBin());
    writeBytes(dir / "data" / "tri+1 a.bin", triangleBin());  // '+' is a plus in a URI; tinygltf reads a space
    writeBytes(dir / "data" / "img.png", png(2, 3, 200));
    const std::string absolute = fs::absolute(dir / "data").string();
    const std::vector<std::string> uris = {absolute + "/tri.bin", "file://" + absolute + "/tri.bin",
                                           "file://localhost" + absolute + "/tri.bin", "FILE:" + absolute + "/tri.bin",
                                           "file://" + absolute + "/tri+1%20a.bin"};
    const fs::path scene = dir / "scene" / "absolute.gltf";
    GltfLoadOptions allow;
    allow.limits.allowExternalUris = true;
    for (const std::string& uri : uris) {
        SCOPED_TRACE(uri);
        writeText(scene, triangleDoc(uri).dump());
        const std::string refused = loadError(scene);
        EXPECT_CONTAINS(refused, "points outside the scene's folder");
        EXPECT_CONTAINS(refused, "--allow-external-uris");
        QuietLog log;
        const Scene loaded = loadGltf(scene, log, allow);
        ASSERT_EQ(loaded.meshes.size(), 1u);
        ASSERT_EQ(loaded.meshes[0].primitives.size(), 1u);
        EXPECT_EQ(loaded.meshes[0].primitives[0].indices.size(), 3u);
    }
    // The same through a relative scene path (the loader hands tinygltf a relative folder).
    {
        writeText(scene, triangleDoc("file://" + absolute + "/tri.bin").dump());
        QuietLog log;
        EXPECT_EQ(loadGltf(fs::relative(scene), log, allow).meshes.size(), 1u);
    }

    // An image by file: URI and by absolute path: its pixels arrive (2×3), not the 1×1 placeholder.
    writeBytes(dir / "scene" / "tri.bin", triangleBin());
    for (const std::string& uri : {"file://" + absolute + "/img.png", absolute + "/img.png"}) {
        SCOPED_TRACE(uri);
        json doc = triangleDoc();
        doc["images"] = json::array({{{"uri", uri}}});
        doc["textures"] = json::array({{{"source", 0}}});
        writeText(scene, doc.dump());
        EXPECT_CONTAINS(loadError(scene), "image 0's uri '" + uri + "' points outside the scene's folder");
        QuietLog log;
        const Scene loaded = loadGltf(scene, log, allow);
        ASSERT_EQ(loaded.images.size(), 1u);
        EXPECT_EQ(loaded.images[0].width, 2);
        EXPECT_EQ(loaded.images[0].height, 3);
    }

    // Never read, opt-in or not: another host, a file: URI without an absolute path, other schemes.
    for (const GltfLoadOptions& options : {GltfLoadOptions{}, allow}) {
        SCOPED_TRACE(options.limits.allowExternalUris ? "allowed" : "not allowed");
        writeText(scene, triangleDoc("http://example.com/tri.bin").dump());
        EXPECT_CONTAINS(loadError(scene, options), "uses the scheme 'http:'; Lit reads buffers and images from data: URIs and local files only");
        if (!options.limits.allowExternalUris) continue;
        writeText(scene, triangleDoc("file://example.com" + absolute + "/tri.bin").dump());
        EXPECT_CONTAINS(loadError(scene, options), "names the host 'example.com'; Lit reads local files only");
        writeText(scene, triangleDoc("file:tri.bin").dump());
        EXPECT_CONTAINS(loadError(scene, options), "is not a file: URI with an absolute path");
    }
    // A missing absolute file is "not found" by its own path, not by the joined one.
    writeText(scene, triangleDoc("file://" + absolute + "/missing.bin").dump());
    EXPECT_CONTAINS(loadError(scene, allow), "File not found");
}

TEST(GltfGuard, ASymbolicLinkOutOfTheFolderIsNotFollowed) {
    TempDir dir;
    fs::create_directories(dir / "scene");
    writeBytes(dir / "secret.bin", triangleBin());
    fs::create_symlink(dir / "secret.bin", dir / "scene" / "link.bin");
    const fs::path scene = dir / "scene" / "link.gltf";
    writeText(scene, triangleDoc("link.bin").dump());
    EXPECT_CONTAINS(loadError(scene), "is outside the scene's folder");
}

TEST(GltfGuard, ADeviceOrPipeIsNotAScene) {
    TempDir dir;
    const fs::path fifo = dir / "pipe.gltf";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_CONTAINS(loadError(fifo), "not a regular file");  // and does not block on open
    const std::string device = loadError("/dev/zero");
    EXPECT_CONTAINS(device, "not a regular file");
}

TEST(GltfGuard, AFileOverTheSizeLimitIsRefusedUnread) {
    TempDir dir;
    GltfLoadOptions options;
    options.limits.maxFileBytes = 100;
    EXPECT_CONTAINS(loadError(writeScene(dir, "big.gltf", triangleDoc()), options), "more than the limit of");
}

TEST(GltfGuard, OnlyMajorVersion2IsRead) {
    TempDir dir;
    json doc = triangleDoc();
    doc["asset"]["version"] = "3.0";
    EXPECT_CONTAINS(loadError(writeScene(dir, "v3.gltf", doc)), "asset.version is '3.0'; Lit reads glTF 2.x only");
    doc["asset"]["version"] = "1.0";
    EXPECT_CONTAINS(loadError(writeScene(dir, "v1.gltf", doc)), "glTF 2.x only");
    doc["asset"]["version"] = "two";
    EXPECT_CONTAINS(loadError(writeScene(dir, "vtwo.gltf", doc)), "not of the form MAJOR.MINOR");
    doc["asset"]["version"] = "2.0";
    doc["asset"]["minVersion"] = "2.1";
    EXPECT_CONTAINS(loadError(writeScene(dir, "min21.gltf", doc)), "asset.minVersion is '2.1'");
    doc["asset"]["version"] = "2.5";  // a later minor version is read (spec §5.2: forward compatible)
    doc["asset"].erase("minVersion");
    QuietLog log;
    EXPECT_NO_THROW(loadGltf(writeScene(dir, "v25.gltf", doc), log));
}

TEST(GltfGuard, RequiredExtensionsLitDoesNotHaveAreRefused) {
    TempDir dir;
    json doc = triangleDoc();
    doc["extensionsUsed"] = {"KHR_materials_anisotropy"};
    doc["extensionsRequired"] = {"KHR_materials_anisotropy"};
    EXPECT_CONTAINS(loadError(writeScene(dir, "volume.gltf", doc)),
                    "volume.gltf: requires KHR_materials_anisotropy, which Lit does not support");
}

// Thousands of images naming one PNG would be decoded one by one.
TEST(GltfGuard, IdenticalImagesAreDecodedOnceAndShared) {
    TempDir dir;
    writeBytes(dir / "wood.png", png(64, 64, 200));
    constexpr int kCopies = 3000;
    json doc = triangleDoc();
    doc["images"] = json::array();
    doc["textures"] = json::array();
    for (int i = 0; i < kCopies; ++i) {
        doc["images"].push_back({{"uri", "wood.png"}});
        doc["textures"].push_back({{"source", i}});
    }
    doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", kCopies - 1}}}}}}});
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    QuietLog log;
    GltfLoadOptions options;
    options.decodeThreads = 1;
    // Processor time, not wall time: the check is about the work done, and must not fail because
    // a loaded CI machine gave this process a fraction of a core.
    const std::clock_t start = std::clock();
    const Scene scene = loadGltf(writeScene(dir, "copies.gltf", doc), log, options);
    const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    ASSERT_EQ(scene.images.size(), static_cast<std::size_t>(kCopies));
    for (const Texture& texture : scene.textures) EXPECT_EQ(texture.image, 0);
    EXPECT_EQ(scene.images[0].width, 64);
    EXPECT_EQ(scene.images[kCopies - 1].rgba.size(), 4u) << "a copy holds no pixels of its own";
    EXPECT_TRUE(scene.images[0].srgb) << "the shared image is used as colour";
    EXPECT_LT(summarize(scene).pixelBytes, 64u * 64u * 4u + kCopies * 4u + 16u);
    // 3000 decodes of this PNG took ~1.5 s (measured before sharing); one decode is ~1 ms.
    EXPECT_LT(seconds, 5.0) << "processor seconds";
}

TEST(GltfGuard, DecodedTexturesOverTheBudgetNameTheImage) {
    TempDir dir;
    writeBytes(dir / "big.png", png(1024, 1024, 9));  // a few kB encoded, 4 MiB decoded
    json doc = triangleDoc();
    doc["images"] = json::array({{{"uri", "big.png"}}});
    doc["textures"] = json::array({{{"source", 0}}});
    GltfLoadOptions options;
    options.limits.memoryBudgetBytes = 2'000'000;
    const std::string message = loadError(writeScene(dir, "budget.gltf", doc), options);
    // 4.2 MB decoded, 5.6 MB as a GL texture with its mips (scene/SceneMemory.h).
    EXPECT_CONTAINS(message, "scene needs 9.8 MB of memory (textures 5.6 MB, decoded images 4.2 MB, geometry 0.0 MB)");
    EXPECT_CONTAINS(message, "over the limit of 2.0 MB");
    EXPECT_CONTAINS(message, "the largest image 0 alone 5.6 MB with mipmaps");
}

TEST(GltfGuard, GeometryOverTheBudgetNamesThePrimitives) {
    TempDir dir;
    GltfLoadOptions options;
    options.limits.memoryBudgetBytes = 100'000;  // one primitive: 3 × 56 + 3 × 4 = 180 bytes
    const std::string message = loadError(writeScene(dir, "prims.gltf", triangleDoc("tri.bin", 1000)), options);
    EXPECT_CONTAINS(message, "scene needs 360.0 kB of memory (geometry 360.0 kB), over the limit of 100.0 kB");
    EXPECT_CONTAINS(message, "; geometry of 1000 primitives");
    QuietLog log;
    EXPECT_EQ(loadGltf(writeScene(dir, "few.gltf", triangleDoc("tri.bin", 100)), log, options).meshes[0].primitives.size(), 100u);
}

TEST(GltfGuard, BuffersAndImagesThatReadOneFileManyTimesStopAtTheBudget) {
    TempDir dir;
    json doc = triangleDoc();
    for (int i = 0; i < 1000; ++i) doc["buffers"].push_back({{"uri", "tri.bin"}, {"byteLength", 44}});
    GltfLoadOptions options;
    options.limits.memoryBudgetBytes = 20'000;
    EXPECT_CONTAINS(loadError(writeScene(dir, "buffers.gltf", doc), options), "1001 buffers declare");

    writeBytes(dir / "pic.png", png(64, 64, 1));
    json images = triangleDoc();
    for (int i = 0; i < 5000; ++i) images["images"].push_back({{"uri", "pic.png"}});
    EXPECT_CONTAINS(loadError(writeScene(dir, "images.gltf", images), options), "5000 images read");
}

// The shadow maps count before anything is allocated: eight point lights at 8192² texels need six
// faces each, 12.9 GB of depth, and a transmissive material adds twice that in colour layers.
TEST(GltfGuard, ShadowMapsOverTheBudgetAreRefusedWithTheirFigure) {
    TempDir dir;
    json doc = triangleDoc();
    doc["extensionsUsed"] = json::array({"KHR_lights_punctual"});
    doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({{{"type", "point"}, {"intensity", 100}}});
    for (int i = 0; i < 8; ++i) {
        doc["nodes"].push_back({{"translation", {i, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        doc["scenes"][0]["nodes"].push_back(i + 1);
    }
    GltfLoadOptions options;
    options.limits.render.shadowMapSize = 8192;
    const std::string message = loadError(writeScene(dir, "lights.gltf", doc), options);
    EXPECT_CONTAINS(message, "scene needs 12.9 GB of memory (shadow maps 12.9 GB");
    EXPECT_CONTAINS(message, "over the limit of 8.0 GB");

    options.limits.render.shadowMapSize = 1024;  // 201 MB: loads
    QuietLog log;
    EXPECT_EQ(loadGltf(writeScene(dir, "lights.gltf", doc), log, options).lights.size(), 1u);
    doc["extensionsUsed"].push_back("KHR_materials_transmission");
    doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
                                     {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}}});
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    options.limits.memoryBudgetBytes = 500'000'000;
    EXPECT_CONTAINS(loadError(writeScene(dir, "glass.gltf", doc), options), "(shadow maps 604.0 MB");
}

}  // namespace
}  // namespace lit
