// make-cornell-box OUTDIR — writes OUTDIR/cornell_box.gltf and OUTDIR/cornell_box.bin.
//
// The scene is Lit's built-in test scene: a Cornell box in metres (+Y up, right-handed, the
// camera looks down −Z into the box). The interior spans x ∈ [−1, 1], y ∈ [0, 2], z ∈ [−1, 1];
// the z = +1 side is open. Every wall and box is its own node and mesh with a clear name, so
// tests and the editor can find and move them. Walls face into the box (single-sided); the two
// boxes are closed and face outwards. See assets/README.md.
//
// The generator links only GLM and nlohmann_json: it must not depend on the renderer it feeds.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// glTF enums (the spec reuses GL values).
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint16_t> indices;
};

// Appends a quad grid spanning origin + s·edgeU + t·edgeV (s, t ∈ [0, 1]) in `cells`×`cells`
// quads, facing `normal`. Triangles are wound counter-clockwise seen from the normal side (the
// glTF front face), whichever way the edges were given.
void addQuadGrid(MeshData& mesh, glm::vec3 origin, glm::vec3 edgeU, glm::vec3 edgeV, glm::vec3 normal, int cells) {
    if (glm::dot(glm::cross(edgeU, edgeV), normal) < 0.0f) std::swap(edgeU, edgeV);
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    const int side = cells + 1;
    if (base + static_cast<std::uint32_t>(side * side) > 65535u)
        throw std::logic_error("mesh too large for 16-bit indices");
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            const float s = static_cast<float>(i) / static_cast<float>(cells);
            const float t = static_cast<float>(j) / static_cast<float>(cells);
            mesh.positions.push_back(origin + s * edgeU + t * edgeV);
            mesh.normals.push_back(normal);
            mesh.uvs.emplace_back(s, 1.0f - t);
        }
    }
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            const auto at = [&](int ii, int jj) { return static_cast<std::uint16_t>(base + static_cast<std::uint32_t>(jj * side + ii)); };
            // (s,t) → (s+1,t) → (s+1,t+1) is counter-clockwise around cross(edgeU, edgeV).
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
}

// A closed box with its base centred on the local origin: x, z ∈ [−size/2, size/2], y ∈ [0, size.y].
// The node places it on the floor; its faces point outwards.
MeshData makeBox(glm::vec3 size, int cells) {
    MeshData mesh;
    const glm::vec3 h{size.x * 0.5f, size.y, size.z * 0.5f};
    const glm::vec3 ex{size.x, 0, 0}, ey{0, size.y, 0}, ez{0, 0, size.z};
    addQuadGrid(mesh, {-h.x, 0, h.z}, ex, ey, {0, 0, 1}, cells);    // front (+Z)
    addQuadGrid(mesh, {-h.x, 0, -h.z}, ex, ey, {0, 0, -1}, cells);  // back (−Z)
    addQuadGrid(mesh, {h.x, 0, -h.z}, ez, ey, {1, 0, 0}, cells);    // right (+X)
    addQuadGrid(mesh, {-h.x, 0, -h.z}, ez, ey, {-1, 0, 0}, cells);  // left (−X)
    addQuadGrid(mesh, {-h.x, h.y, -h.z}, ex, ez, {0, 1, 0}, cells); // top (+Y)
    addQuadGrid(mesh, {-h.x, 0, -h.z}, ex, ez, {0, -1, 0}, cells);  // bottom (−Y): keeps the box closed for voxels and shadows
    return mesh;
}

// Accumulates the binary buffer and the glTF arrays that describe it.
class GltfBuilder {
public:
    Json doc = Json::object();
    std::vector<std::uint8_t> bin;

    GltfBuilder() {
        for (const char* key : {"bufferViews", "accessors", "meshes", "materials", "nodes", "cameras"})
            arrays_[key] = Json::array();
    }

    int addMaterial(const std::string& name, glm::dvec3 linearColor) {
        Json m;
        m["name"] = name;
        m["pbrMetallicRoughness"] = {{"baseColorFactor", {linearColor.r, linearColor.g, linearColor.b, 1.0}},
                                     {"metallicFactor", 0.0},
                                     {"roughnessFactor", 0.9}};
        return push("materials", std::move(m));
    }

    int addMesh(const std::string& name, const MeshData& data, int material) {
        const int count = static_cast<int>(data.positions.size());
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        for (const glm::vec3& p : data.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        Json position = accessor(view(data.positions.data(), data.positions.size() * sizeof(glm::vec3), kArrayBuffer),
                                 kFloat, count, "VEC3");
        position["min"] = {lo.x, lo.y, lo.z};  // POSITION min/max are required by the spec
        position["max"] = {hi.x, hi.y, hi.z};
        const int positionIndex = push("accessors", std::move(position));
        const int normalIndex = push("accessors", accessor(view(data.normals.data(), data.normals.size() * sizeof(glm::vec3), kArrayBuffer),
                                                           kFloat, count, "VEC3"));
        const int uvIndex = push("accessors", accessor(view(data.uvs.data(), data.uvs.size() * sizeof(glm::vec2), kArrayBuffer),
                                                       kFloat, count, "VEC2"));
        const int indexIndex = push("accessors", accessor(view(data.indices.data(), data.indices.size() * sizeof(std::uint16_t), kElementArrayBuffer),
                                                          kUnsignedShort, static_cast<int>(data.indices.size()), "SCALAR"));
        Json primitive = {{"attributes", {{"POSITION", positionIndex}, {"NORMAL", normalIndex}, {"TEXCOORD_0", uvIndex}}},
                          {"indices", indexIndex},
                          {"material", material},
                          {"mode", 4}};
        return push("meshes", {{"name", name}, {"primitives", Json::array({primitive})}});
    }

    int addNode(Json node) { return push("nodes", std::move(node)); }
    int addCamera(Json camera) { return push("cameras", std::move(camera)); }

    Json finish(const std::string& binUri, const Json& extensions, const Json& sceneNodes) {
        doc["asset"] = {{"version", "2.0"}, {"generator", "make-cornell-box (Lit)"}};
        doc["extensionsUsed"] = Json::array({"KHR_lights_punctual"});
        doc["extensions"] = extensions;
        doc["scene"] = 0;
        doc["scenes"] = Json::array({{{"name", "cornell_box"}, {"nodes", sceneNodes}}});
        for (auto& [key, value] : arrays_.items()) doc[key] = value;
        doc["buffers"] = Json::array({{{"uri", binUri}, {"byteLength", bin.size()}}});
        return doc;
    }

private:
    Json arrays_ = Json::object();

    int push(const char* array, Json value) {
        Json& a = arrays_[array];
        a.push_back(std::move(value));
        return static_cast<int>(a.size() - 1);
    }

    // Copies bytes into the buffer at a 4-byte aligned offset (accessor alignment rule) and
    // returns the new buffer view.
    int view(const void* data, std::size_t bytes, int target) {
        while (bin.size() % 4 != 0) bin.push_back(0);
        const std::size_t offset = bin.size();
        bin.resize(offset + bytes);
        std::memcpy(bin.data() + offset, data, bytes);
        return push("bufferViews", {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}});
    }

    static Json accessor(int bufferView, int componentType, int count, const char* type) {
        return {{"bufferView", bufferView}, {"componentType", componentType}, {"count", count}, {"type", type}};
    }
};

// glTF order x, y, z, w; adding +0.0 turns the −0.0 of sin(−θ/2)·0 into a plain 0.
Json quatJson(const glm::dquat& q) { return {q.x + 0.0, q.y + 0.0, q.z + 0.0, q.w + 0.0}; }

// Writes through a temporary file so a failed run never leaves a half-written asset.
void writeFileAtomic(const fs::path& path, const void* data, std::size_t bytes) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error("cannot open " + tmp.string() + " for writing");
        out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
        if (!out) throw std::runtime_error("cannot write " + tmp.string());
    }
    fs::rename(tmp, path);
}

void generate(const fs::path& outDir) {
    GltfBuilder gltf;
    const int white = gltf.addMaterial("white", {0.73, 0.73, 0.73});
    const int red = gltf.addMaterial("red", {0.63, 0.065, 0.05});
    const int green = gltf.addMaterial("green", {0.14, 0.45, 0.091});

    Json sceneNodes = Json::array();
    const auto addMeshNode = [&](const std::string& name, const MeshData& data, int material, Json transform) {
        Json node = {{"name", name}, {"mesh", gltf.addMesh(name, data, material)}};
        for (auto& [key, value] : transform.items()) node[key] = value;
        sceneNodes.push_back(gltf.addNode(std::move(node)));
    };

    // Walls: 8×8 quads each (denser geometry is not needed for rasterisation, but keeps per-
    // vertex debugging and any future vertex lighting reasonable). Normals point into the box.
    constexpr int kWallCells = 8;
    const auto wall = [&](glm::vec3 origin, glm::vec3 eu, glm::vec3 ev, glm::vec3 normal) {
        MeshData m;
        addQuadGrid(m, origin, eu, ev, normal, kWallCells);
        return m;
    };
    addMeshNode("floor", wall({-1, 0, -1}, {2, 0, 0}, {0, 0, 2}, {0, 1, 0}), white, Json::object());
    addMeshNode("ceiling", wall({-1, 2, -1}, {2, 0, 0}, {0, 0, 2}, {0, -1, 0}), white, Json::object());
    addMeshNode("back_wall", wall({-1, 0, -1}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}), white, Json::object());
    addMeshNode("left_wall_red", wall({-1, 0, -1}, {0, 0, 2}, {0, 2, 0}, {1, 0, 0}), red, Json::object());
    addMeshNode("right_wall_green", wall({1, 0, -1}, {0, 0, 2}, {0, 2, 0}, {-1, 0, 0}), green, Json::object());

    // The two boxes of the classic Cornell scene, scaled to this 2 m room: the tall one back-left
    // turned +17° about Y, the short one front-right turned −17°. Node origins sit on the floor.
    const double kTurn = 17.0 * std::numbers::pi / 180.0;  // radians
    const glm::dquat tallRotation = glm::angleAxis(kTurn, glm::dvec3(0, 1, 0));
    const glm::dquat shortRotation = glm::angleAxis(-kTurn, glm::dvec3(0, 1, 0));
    addMeshNode("tall_box", makeBox({0.6f, 1.2f, 0.6f}, 2), white,
                {{"rotation", quatJson(tallRotation)}, {"translation", {-0.33, 0.0, -0.3}}});
    addMeshNode("short_box", makeBox({0.6f, 0.6f, 0.6f}, 2), white,
                {{"rotation", quatJson(shortRotation)}, {"translation", {0.35, 0.0, 0.35}}});

    // Ceiling spot light, pointing straight down: rotating the node −90° about X turns its
    // local −Z (the light direction) to −Y. Intensity in candela as glTF wants it: 13 660 cd is
    // 20 W/sr at 683 lm/W (docs/UNITS.md). The floor point below is 1.9 m away, so
    // E = 20 / 1.9² ≈ 5.5 W/m² and the white floor's radiance is 0.73/π · E ≈ 1.3 W/(sr·m²),
    // bright but not clipped under ACES at exposure 1. The cone is wide (outer 1.05 rad ≈ 60°,
    // full intensity inside 0.6 rad): the whole floor and the walls below y ≈ 1.3 m are lit
    // directly, while the ceiling and the top of the walls see only bounced light (GI).
    const glm::dquat down = glm::angleAxis(-0.5 * std::numbers::pi, glm::dvec3(1, 0, 0));
    const Json lights = {{"KHR_lights_punctual",
                          {{"lights",
                            Json::array({{{"name", "ceiling_spot"},
                                          {"type", "spot"},
                                          {"color", {1.0, 1.0, 1.0}},
                                          {"intensity", 20.0 * 683.0},
                                          {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 1.05}}}}})}}}};
    sceneNodes.push_back(gltf.addNode({{"name", "ceiling_spot"},
                                       {"rotation", quatJson(down)},
                                       {"translation", {0.0, 1.9, 0.0}},
                                       {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));

    // Camera in front of the open side, looking down −Z; 39.3° vertical field of view as in the
    // original Cornell measurements. From z = 3.4 the walls just overfill the frame.
    const int camera = gltf.addCamera({{"name", "camera"},
                                       {"type", "perspective"},
                                       {"perspective", {{"yfov", 0.69}, {"aspectRatio", 1.0}, {"znear", 0.05}, {"zfar", 20.0}}}});
    sceneNodes.push_back(gltf.addNode({{"name", "camera"}, {"camera", camera}, {"translation", {0.0, 1.0, 3.4}}}));

    const Json doc = gltf.finish("cornell_box.bin", lights, sceneNodes);

    fs::create_directories(outDir);
    writeFileAtomic(outDir / "cornell_box.bin", gltf.bin.data(), gltf.bin.size());
    const std::string text = doc.dump(2) + "\n";
    writeFileAtomic(outDir / "cornell_box.gltf", text.data(), text.size());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 || std::strcmp(argv[1], "--help") == 0) {
        std::fprintf(stderr, "usage: make-cornell-box OUTDIR\n  writes OUTDIR/cornell_box.gltf and OUTDIR/cornell_box.bin\n");
        return argc == 2 ? 0 : 2;
    }
    try {
        generate(argv[1]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make-cornell-box: %s\n", e.what());
        return 1;
    }
    std::printf("wrote %s and %s\n", (fs::path(argv[1]) / "cornell_box.gltf").string().c_str(),
                (fs::path(argv[1]) / "cornell_box.bin").string().c_str());
    return 0;
}
