#pragma once
// Writes glTF files whose many textures share a few images, the shape of the files that made Lit
// allocate one GL texture per glTF texture: `textures` textures over `images` PNG images (round
// robin), every other texture with the clamping sampler, and `materials` materials whose base
// colour textures are spread over the whole list, one triangle primitive each. Used by the CPU
// tests (loader, budget, round trip) and the GL tests (upload).

#include "image/ImageIO.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace lit::testing {

struct SharedImageScene {
    int textures = 1;
    int images = 1;
    int imageSide = 4;  // pixels per side of each image
    int materials = 1;
};

// Image i is a grey of value 40 + 50·i (so no two are byte-identical and deduplicated).
inline std::filesystem::path writeSharedImageScene(const std::filesystem::path& folder, const std::string& name,
                                                   const SharedImageScene& shape) {
    using json = nlohmann::json;
    std::filesystem::create_directories(folder);
    const auto write = [](const std::filesystem::path& path, const void* data, std::size_t size) {
        std::ofstream out(path, std::ios::binary);
        out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
        if (!out) throw std::runtime_error("cannot write " + path.string());
    };
    // One triangle: positions, then UVs, then uint16 indices.
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const float uvs[6] = {0, 0, 1, 0, 0, 1};
    const std::uint16_t indices[3] = {0, 1, 2};
    std::vector<std::uint8_t> bin(36 + 24 + 8, 0);
    std::memcpy(bin.data(), positions, 36);
    std::memcpy(bin.data() + 36, uvs, 24);
    std::memcpy(bin.data() + 60, indices, 6);
    write(folder / (name + ".bin"), bin.data(), bin.size());

    json doc = {{"asset", {{"version", "2.0"}}},
                {"buffers", json::array({{{"uri", name + ".bin"}, {"byteLength", bin.size()}}})},
                {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                             {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}},
                                             {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 6}}})},
                {"accessors", json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 3},
                                            {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                                           {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}},
                                           {{"bufferView", 2}, {"componentType", 5123}, {"count", 3},
                                            {"type", "SCALAR"}}})},
                {"samplers", json::array({{{"wrapS", 10497}, {"wrapT", 10497}},
                                          {{"wrapS", 33071}, {"wrapT", 33071}, {"magFilter", 9728}}})},
                {"nodes", json::array({{{"mesh", 0}}})},
                {"scenes", json::array({{{"nodes", {0}}}})},
                {"scene", 0}};
    for (int i = 0; i < shape.images; ++i) {
        const std::string file = name + "_" + std::to_string(i) + ".png";
        const std::vector<std::uint8_t> rgba(
            static_cast<std::size_t>(shape.imageSide) * static_cast<std::size_t>(shape.imageSide) * 4,
            static_cast<std::uint8_t>(40 + 50 * i));
        const std::vector<std::uint8_t> png = encodePng(shape.imageSide, shape.imageSide, rgba);
        write(folder / file, png.data(), png.size());
        doc["images"].push_back({{"uri", file}});
    }
    json textures = json::array();
    for (int t = 0; t < shape.textures; ++t) textures.push_back({{"source", t % shape.images}, {"sampler", t % 2}});
    doc["textures"] = std::move(textures);
    json primitives = json::array();
    for (int m = 0; m < shape.materials; ++m) {
        const int texture = static_cast<int>(static_cast<long long>(m) * shape.textures / shape.materials);
        doc["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}});
        primitives.push_back(
            {{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", m}});
    }
    doc["meshes"] = json::array({{{"primitives", std::move(primitives)}}});
    const std::filesystem::path path = folder / (name + ".gltf");
    const std::string text = doc.dump();
    write(path, text.data(), text.size());
    return path;
}

}  // namespace lit::testing
