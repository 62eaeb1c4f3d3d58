// EXT_texture_webp (label cpu): WebP images encoded here with libwebp (lossless, so the decoded
// pixels must be exact) inside a glTF, with and without a PNG fallback; kept as WebP on save
// (validator clean when installed); bytes that are not WebP reported; and, in a build without
// libwebp, the file that requires the extension refused with a message naming it.
#include "GltfValidator.h"
#include "Log.h"
#include "TempDir.h"
#include "image/ImageIO.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/Scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#if LIT_HAS_WEBP
#include <webp/encode.h>
#endif

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace lit {
namespace {

namespace fs = std::filesystem;
using lit::testing::readText;
using lit::testing::TempDir;

constexpr int kWidth = 4, kHeight = 2;

// Eight distinct opaque colours, rows top-down.
std::vector<std::uint8_t> testPixels() {
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < kWidth * kHeight; ++i)
        rgba.insert(rgba.end(), {static_cast<std::uint8_t>(30 * i), static_cast<std::uint8_t>(255 - 20 * i),
                                 static_cast<std::uint8_t>(i % 2 ? 200 : 10), 255});
    return rgba;
}

std::vector<std::uint8_t> encodeWebp(const std::vector<std::uint8_t>& rgba) {
#if LIT_HAS_WEBP
    std::uint8_t* out = nullptr;
    const std::size_t size = WebPEncodeLosslessRGBA(rgba.data(), kWidth, kHeight, kWidth * 4, &out);
    std::vector<std::uint8_t> bytes(out, out + size);
    WebPFree(out);
    return bytes;
#else
    (void)rgba;
    // A valid lossless WebP is not needed where nothing decodes it: a RIFF/WEBP header will do.
    return {'R', 'I', 'F', 'F', 4, 0, 0, 0, 'W', 'E', 'B', 'P'};
#endif
}

// A glTF with one material whose base colour texture reads `webp` through EXT_texture_webp (and
// `fallback`, a PNG, through `source` when not empty), both embedded in scene.bin.
fs::path writeScene(const TempDir& dir, const std::vector<std::uint8_t>& webp, const std::vector<std::uint8_t>& fallback,
                    bool required) {
    std::vector<std::uint8_t> bin = webp;
    nlohmann::json views = nlohmann::json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", webp.size()}}});
    nlohmann::json images = nlohmann::json::array({{{"bufferView", 0}, {"mimeType", "image/webp"}}});
    nlohmann::json texture = {{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}};
    if (!fallback.empty()) {
        bin.resize((bin.size() + 3) & ~std::size_t(3), 0);
        views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", fallback.size()}});
        bin.insert(bin.end(), fallback.begin(), fallback.end());
        images.push_back({{"bufferView", 1}, {"mimeType", "image/png"}});
        texture["source"] = 1;
    }
    nlohmann::json doc = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"EXT_texture_webp"}},
        {"buffers", {{{"uri", "scene.bin"}, {"byteLength", bin.size()}}}},
        {"bufferViews", views},
        {"images", images},
        {"textures", {texture}},
        {"materials", {{{"name", "webp"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
    };
    if (required) doc["extensionsRequired"] = {"EXT_texture_webp"};
    std::ofstream(dir / "scene.bin", std::ios::binary).write(reinterpret_cast<const char*>(bin.data()),
                                                            static_cast<std::streamsize>(bin.size()));
    std::ofstream(dir / "scene.gltf") << doc.dump(1);
    return dir / "scene.gltf";
}

struct Captured {
    Log log;
    std::string warnings;
    Captured() {
        log.setSink([this](const LogMessage& m) {
            if (m.level == LogLevel::Warning) warnings += m.text + "\n";
        });
    }
};

const Image& baseColorImage(const Scene& scene) {
    const int texture = scene.materials.at(0).baseColorTexture;
    return scene.images.at(static_cast<std::size_t>(scene.textures.at(static_cast<std::size_t>(texture)).image));
}

#if LIT_HAS_WEBP

TEST(GltfWebp, DecodesTheExtensionsImage) {
    TempDir dir;
    Captured c;
    const Scene scene = loadGltf(writeScene(dir, encodeWebp(testPixels()), {}, true), c.log);
    EXPECT_EQ(c.warnings, "");
    const Image& image = baseColorImage(scene);
    EXPECT_EQ(image.width, kWidth);
    EXPECT_EQ(image.height, kHeight);
    EXPECT_EQ(image.rgba, testPixels());
    EXPECT_EQ(image.mimeType, "image/webp");
}

// With a PNG fallback (of other colours) in `source`, the WebP image is the one drawn.
TEST(GltfWebp, PreferredOverTheFallback) {
    TempDir dir;
    Captured c;
    const std::vector<std::uint8_t> grey(kWidth * kHeight * 4, 128);
    const Scene scene = loadGltf(writeScene(dir, encodeWebp(testPixels()), encodePng(kWidth, kHeight, grey), false),
                                 c.log);
    EXPECT_EQ(c.warnings, "");
    EXPECT_EQ(baseColorImage(scene).rgba, testPixels());
}

// A save writes the WebP bytes back into the extension, the fallback as `source`; the reload
// decodes the same pixels, and the validator accepts source and saved file.
TEST(GltfWebp, KeptOnSave) {
    TempDir dir;
    Captured c;
    const std::vector<std::uint8_t> webp = encodeWebp(testPixels());
    const std::vector<std::uint8_t> grey(kWidth * kHeight * 4, 128);
    const Scene scene = loadGltf(writeScene(dir, webp, encodePng(kWidth, kHeight, grey), true), c.log);
    saveGltf(scene, dir / "saved.gltf");
    const nlohmann::json saved = nlohmann::json::parse(readText(dir / "saved.gltf"));
    const nlohmann::json& texture = saved["textures"][0];
    ASSERT_TRUE(texture.contains("extensions")) << saved.dump(1);
    const int webpImage = texture["extensions"]["EXT_texture_webp"]["source"].get<int>();
    EXPECT_EQ(saved["images"][webpImage]["mimeType"], "image/webp");
    ASSERT_TRUE(texture.contains("source"));
    EXPECT_EQ(saved["images"][texture["source"].get<int>()]["mimeType"], "image/png");
    EXPECT_NE(saved["extensionsUsed"].dump().find("EXT_texture_webp"), std::string::npos);
    EXPECT_NE(saved["extensionsRequired"].dump().find("EXT_texture_webp"), std::string::npos);
    const Scene again = loadGltf(dir / "saved.gltf", c.log);
    EXPECT_EQ(baseColorImage(again).rgba, testPixels());
    EXPECT_EQ(baseColorImage(again).encoded, webp) << "the bytes are written back, not re-encoded";
    EXPECT_EQ(c.warnings, "");

    std::string whyNot;
    const fs::path validatorDir = lit::testing::findGltfValidator(whyNot);
    if (validatorDir.empty()) GTEST_SKIP() << whyNot;
    std::string report;
    const int status = lit::testing::runGltfValidator(validatorDir, {dir / "scene.gltf", dir / "saved.gltf"}, report,
                                                      dir / "report.txt");
    std::printf("%s", report.c_str());
    EXPECT_NE(report.find("scene.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_EQ(status, 0) << report;
}

// Bytes that claim to be WebP but do not decode: a warning naming libwebp, a white texture.
TEST(GltfWebp, UndecodableBytesAreReported) {
    TempDir dir;
    Captured c;
    std::vector<std::uint8_t> broken = encodeWebp(testPixels());
    broken.resize(broken.size() / 2);
    const Scene scene = loadGltf(writeScene(dir, broken, {}, true), c.log);
    EXPECT_NE(c.warnings.find("libwebp could not decode it"), std::string::npos) << c.warnings;
    EXPECT_EQ(baseColorImage(scene).rgba, (std::vector<std::uint8_t>{255, 255, 255, 255}));
}

#else

// Without libwebp a file that requires the extension is refused, naming it and why.
TEST(GltfWebp, RequiredWithoutLibwebpIsANamedError) {
    TempDir dir;
    Captured c;
    try {
        loadGltf(writeScene(dir, encodeWebp(testPixels()), {}, true), c.log);
        FAIL() << "loaded a file that requires EXT_texture_webp without libwebp";
    } catch (const SceneLoadError& e) {
        EXPECT_NE(std::string(e.what()).find("requires EXT_texture_webp, which Lit does not support (EXT_texture_webp: "
                                             "WebP textures; this build of Lit has no libwebp"),
                  std::string::npos)
            << e.what();
    }
}

// Only used, with a PNG fallback: the fallback is drawn, with a warning.
TEST(GltfWebp, FallbackWithoutLibwebp) {
    TempDir dir;
    Captured c;
    const std::vector<std::uint8_t> grey(kWidth * kHeight * 4, 128);
    const Scene scene =
        loadGltf(writeScene(dir, encodeWebp(testPixels()), encodePng(kWidth, kHeight, grey), false), c.log);
    EXPECT_EQ(baseColorImage(scene).rgba, grey);
    EXPECT_NE(c.warnings.find("EXT_texture_webp"), std::string::npos) << c.warnings;
}

#endif

}  // namespace
}  // namespace lit
