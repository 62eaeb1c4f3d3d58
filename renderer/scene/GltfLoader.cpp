// glTF 2.0 import. tinygltf parses the JSON/GLB container and loads buffers; everything it hands
// over is validated here before use (indices, offsets, lengths), because tinygltf 2.7 checks
// little of it and a bad file must give a SceneLoadError, never a crash.
//
// Decisions worth knowing:
// - The nodes of the chosen scene (the default scene, else scene 0, else every parentless node)
//   become Scene::nodes; the file's other nodes (other scenes' trees, nodes of no scene) become
//   Scene::keptNodes, kept for saving and not drawn. Both lists are in file order.
// - Missing NORMALs are computed as flat normals (the primitive is unwelded, as glTF requires);
//   missing TANGENTs are always computed (not only for normal-mapped materials), so every
//   vertex carries a valid tangent frame. A file's TANGENTs are ignored when its NORMALs are
//   missing (glTF 2.0 §3.7.2.1).
// - Images are decoded by stb_image to RGBA8 on up to hardware_concurrency threads (or
//   GltfLoadOptions::decodeThreads); progress is reported on the calling thread. An image that
//   is missing or cannot be decoded becomes 1×1 white with a warning, and materials that used it
//   as a normal map drop the normal map (normalTexture = -1) so they fall back to vertex normals.
// - Only mode TRIANGLES is drawn; primitives of other modes are kept for saving
//   (Mesh::otherPrimitives, warning). Orthographic cameras are drawn as perspective cameras with
//   yfov 0.8 (warning) and saved back as orthographic.
// - What Lit does not draw is kept as the file had it, for a lossless save (scene/Scene.h):
//   vertex attributes besides POSITION, NORMAL, TEXCOORD_0 and TANGENT, morph targets and
//   weights, skins, texture coordinate sets. Unreadable kept data is reported and left out; the
//   load goes on.

#include "scene/GltfLoader.h"

#include "Log.h"
#include "animation/CameraPathIO.h"
#include "io/GltfFile.h"
#include "scene/GltfKeep.h"
#include "scene/LightUnits.h"
#include "scene/Tangents.h"

#define GLM_ENABLE_EXPERIMENTAL
#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <condition_variable>
#include <exception>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <map>
#include <sstream>
#include <string_view>
#include <thread>
#include <tuple>

namespace lit {

namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Container detection

enum class Container { Json, Binary };

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::uint32_t readLittleEndian32(const unsigned char* p) {
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

// Decides how to parse `path` from its first bytes and extension, and checks a GLB's header
// against the file size so a truncated file is reported as such.
Container detectContainer(const fs::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) throw SceneLoadError(name + ": file not found");
    if (fs::is_directory(status)) throw SceneLoadError(name + ": is a directory, not a glTF file");
    const std::uintmax_t fileSize = fs::file_size(path, ec);
    if (ec) throw SceneLoadError(name + ": cannot read the file size (" + ec.message() + ")");

    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneLoadError(name + ": cannot open the file for reading");
    std::array<unsigned char, 20> head{};
    in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    if (got == 0) throw SceneLoadError(name + ": the file is empty, not a glTF file");

    const bool glbMagic = got >= 4 && std::memcmp(head.data(), "glTF", 4) == 0;
    // JSON starts with '{', possibly after whitespace and a UTF-8 byte order mark.
    std::size_t first = 0;
    if (got >= 3 && head[0] == 0xEF && head[1] == 0xBB && head[2] == 0xBF) first = 3;
    while (first < got && std::isspace(head[first])) ++first;
    const bool looksJson = first < got && head[first] == '{';

    const std::string ext = lowercase(path.extension().string());
    if (ext == ".glb" && !glbMagic) {
        if (looksJson)
            throw SceneLoadError(name + ": has the extension .glb but holds JSON text; was a .gltf file renamed?");
        throw SceneLoadError(name + ": not a glTF file (a .glb file must start with the magic bytes \"glTF\")");
    }
    if (ext == ".gltf" && glbMagic)
        throw SceneLoadError(name +
                             ": is a binary glTF (GLB) file but has the extension .gltf; was a .glb file renamed?");
    if (!glbMagic && !looksJson)
        throw SceneLoadError(name + ": not a glTF file (neither JSON text nor the GLB magic bytes \"glTF\")");
    if (!glbMagic) {
        // tinygltf reports a JSON syntax error without saying so; check the syntax here first
        // so a truncated or hand-broken file gets a message that names the problem and place.
        std::ifstream whole(path, std::ios::binary);
        const std::string text{std::istreambuf_iterator<char>(whole), std::istreambuf_iterator<char>()};
        if (nlohmann::json::accept(text)) return Container::Json;
        std::string reason = "syntax error";
        try {
            // Parse again only to get the error's position and reason.
            const nlohmann::json parsed = nlohmann::json::parse(text);
            (void)parsed;
        } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for 1e999
            reason = e.what();
            // "[json.exception.parse_error.101] parse error at line 3, ..." → "parse error at line 3, ..."
            if (const auto bracket = reason.find("] ");
                reason.starts_with("[json.exception") && bracket != std::string::npos)
                reason.erase(0, bracket + 2);
        }
        throw SceneLoadError(name + ": invalid JSON (is the file truncated?): " + reason);
    }

    // GLB header: magic, version, total length; then the JSON chunk's length and type.
    if (got < 12) throw SceneLoadError(name + ": truncated GLB: the file is shorter than the 12-byte header");
    const std::uint32_t version = readLittleEndian32(head.data() + 4);
    const std::uint32_t declared = readLittleEndian32(head.data() + 8);
    if (version != 2)
        throw SceneLoadError(name + ": GLB container version " + std::to_string(version) +
                             " is not supported (only 2)");
    if (declared > fileSize)
        throw SceneLoadError(name + ": truncated GLB: the header declares " + std::to_string(declared) +
                             " bytes but the file has " + std::to_string(fileSize));
    if (got < 20) throw SceneLoadError(name + ": truncated GLB: the file ends inside the JSON chunk header");
    const std::uint64_t jsonEnd = 20ull + readLittleEndian32(head.data() + 12);
    if (jsonEnd > declared)
        throw SceneLoadError(name + ": truncated GLB: the JSON chunk (" + std::to_string(jsonEnd - 20) +
                             " bytes) runs past the declared length of " + std::to_string(declared) + " bytes");
    return Container::Binary;
}

// ---------------------------------------------------------------------------------------------
// tinygltf image callback: keep the encoded bytes; decoding happens later, in parallel, by stb.

struct ImageCallbackContext {
    const tinygltf::Model* model = nullptr;  // being filled by tinygltf (buffers are parsed first)
    std::vector<std::string> problems;       // images whose bytes could not be taken safely
    ImageDeduplicator images;                // the encoded bytes, each distinct image once
};

bool keepEncodedImage(tinygltf::Image* image, const int imageIndex, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
    auto& context = *static_cast<ImageCallbackContext*>(user);
    // tinygltf 2.7 does not check that an image's buffer view lies inside its buffer before
    // handing us the pointer: check it here, before reading the bytes.
    if (image->bufferView >= 0 && context.model) {
        const auto& views = context.model->bufferViews;
        const auto& buffers = context.model->buffers;
        const auto view = static_cast<std::size_t>(image->bufferView);
        const bool inside =
            view < views.size() && views[view].buffer >= 0 &&
            static_cast<std::size_t>(views[view].buffer) < buffers.size() &&
            views[view].byteOffset <= buffers[static_cast<std::size_t>(views[view].buffer)].data.size() &&
            views[view].byteLength <=
                buffers[static_cast<std::size_t>(views[view].buffer)].data.size() - views[view].byteOffset;
        if (!inside) {
            context.problems.push_back("image " + std::to_string(imageIndex) + ": buffer view " +
                                       std::to_string(image->bufferView) + " lies outside its buffer");
            image->image.clear();
            image->as_is = true;
            return true;
        }
    }
    // Kept once per distinct content (io/GltfGuard.h); put into the model after parsing.
    context.images.add(imageIndex, bytes, bytes && size > 0 ? static_cast<std::size_t>(size) : 0);
    image->image.clear();
    image->as_is = true;  // encoded bytes, not pixels
    return true;
}

// ---------------------------------------------------------------------------------------------
// The loader proper

class Loader {
public:
    // `sparseKept`: by accessor index, the extras and extensions of its `sparse`, `sparse.indices`
    // and `sparse.values` objects (readWhatTinygltfSkips). `doc`: the file's JSON (null when it
    // does not parse as JSON here), for what tinygltf does not tell: which optional fields the
    // file wrote (materials, samplers).
    Loader(const fs::path& path, const tinygltf::Model& model, Log& log, const GltfLoadOptions& options,
           const ImageDeduplicator& images, const std::map<int, std::array<KeptGltf, 3>>& sparseKept,
           const nlohmann::json& doc)
        : path_(path), model_(model), log_(log), options_(options), images_(images), sparseKept_(sparseKept), doc_(doc) {}

    Scene run();

private:
    [[noreturn]] void fail(const std::string& problem) const { throw SceneLoadError(path_.string() + ": " + problem); }
    void warn(const std::string& problem) const { log_.warning(path_.filename().string() + ": " + problem); }
    void report(const char* stage, std::size_t done, std::size_t total) const {
        if (options_.progress) options_.progress({stage, static_cast<int>(done), static_cast<int>(total)});
    }

    // A validated view of an accessor's elements.
    struct AccessorData {
        const unsigned char* first = nullptr;  // first element
        std::size_t count = 0;
        std::size_t stride = 0;  // bytes between consecutive elements
        int componentType = 0;
        int components = 0;
        bool normalized = false;

        // Component c of element i as float, normalised integers mapped to [0,1] / [-1,1].
        float component(std::size_t i, int c) const;
        // Component 0 of element i as an unsigned integer (index data).
        std::uint32_t index(std::size_t i) const;
    };

    AccessorData accessor(int index, int expectedType, const std::string& role) const;
    void checkExtensions() const;
    void loadNodes(Scene& scene) const;
    void loadMeshes(Scene& scene) const;
    void loadPrimitive(const tinygltf::Primitive& in, const std::string& meshName, std::size_t primitiveIndex,
                       Primitive& out) const;
    void loadMaterials(Scene& scene) const;
    void loadTextures(Scene& scene) const;
    void loadImages(Scene& scene) const;
    void loadLights(Scene& scene) const;
    void loadCameras(Scene& scene) const;
    void loadAnimations(Scene& scene) const;
    void loadSkins(Scene& scene) const;
    // An accessor's elements, any type, sparse ones expanded, for data Lit keeps without using.
    // `expectedCount`: the element count the accessor must have (attributes: the vertex count);
    // without one the accessor must have a buffer view (so its size is bounded by the file).
    KeptAccessor keptAccessor(int index, const std::string& role, std::optional<std::size_t> expectedCount) const;
    // A buffer view's / an accessor's name, extras and extensions (empty for an invalid index).
    KeptObject keptView(int index) const;
    KeptAccessorInfo accessorInfo(int index) const;
    // The attributes of `attributes` except those named in `skip`; an unreadable one is reported
    // and left out.
    KeptAttributes keptAttributes(const std::map<std::string, int>& attributes, std::initializer_list<std::string_view> skip,
                                  const std::string& where, std::size_t vertexCount) const;
    std::vector<KeptAttributes> keptTargets(const tinygltf::Primitive& in, const std::string& where,
                                            std::size_t vertexCount) const;
    std::optional<KeptPrimitive> keptPrimitive(const tinygltf::Primitive& in, const std::string& where) const;
    void keepFileData(Scene& scene) const;
    int textureIndex(int index, const std::string& what) const;

    const fs::path& path_;
    const tinygltf::Model& model_;
    Log& log_;
    const GltfLoadOptions& options_;
    const ImageDeduplicator& images_;  // which images are byte-identical to an earlier one
    const std::map<int, std::array<KeptGltf, 3>>& sparseKept_;
    const nlohmann::json& doc_;
    // The file's JSON object `index` of the top-level array `array` (null when absent).
    const nlohmann::json& fileObject(const char* array, std::size_t index) const {
        static const nlohmann::json none;
        if (!doc_.is_object()) return none;
        const auto found = doc_.find(array);
        if (found == doc_.end() || !found->is_array() || index >= found->size() || !(*found)[index].is_object()) return none;
        return (*found)[index];
    }
    mutable std::vector<int> nodeRemap_;  // file node → node reference (scene/Scene.h: keptNodeRef), set by loadNodes
};

std::string describeNode(const tinygltf::Model& model, std::size_t index) {
    const std::string& name = model.nodes[index].name;
    return "node " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
}

// An integer index from a JSON number, or `fallback` for anything that is not an exact int.
int integerOr(const tinygltf::Value& value, int fallback) {
    if (!value.IsNumber()) return fallback;
    const double d = value.GetNumberAsDouble();
    if (!std::isfinite(d) || d != std::floor(d) || d < std::numeric_limits<int>::min() ||
        d > std::numeric_limits<int>::max())
        return fallback;
    return static_cast<int>(d);
}

// A JSON value for a message: "2", "2.5", or "(missing)".
std::string numberText(const tinygltf::Value& value) {
    if (!value.IsNumber()) return "(missing)";
    std::ostringstream out;
    out << value.GetNumberAsDouble();
    return out.str();
}

// A number for a message: "2", "2.5", "-0.3".
std::string numberText(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// "(0.5, -1, 2)" for a message.
std::string listText(const std::vector<double>& values) {
    std::string text = "(";
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + numberText(values[i]);
    return text + ")";
}

// Factors the spec bounds to 0..1 (baseColorFactor, metallic/roughnessFactor, emissiveFactor,
// a light's color): true when every value is inside; `clamped` gets the values Lit uses.
bool insideUnitRange(const std::vector<double>& values, std::vector<double>& clamped) {
    clamped = values;
    bool inside = true;
    for (double& v : clamped) {
        if (!(v >= 0.0 && v <= 1.0)) inside = false;
        v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0);
    }
    return inside;
}

float Loader::AccessorData::component(std::size_t i, int c) const {
    const unsigned char* p = first + i * stride;
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p + 4 * c, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const float v = p[c];
            return normalized ? v / 255.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const float v = static_cast<std::int8_t>(p[c]);
            return normalized ? std::max(v / 127.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p + 2 * c, 2);
            return normalized ? float(v) / 65535.0f : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p + 2 * c, 2);
            return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p + 4 * c, 4);
            return float(v);
        }
        default:
            return 0.0f;  // rejected in accessor()
    }
}

std::uint32_t Loader::AccessorData::index(std::size_t i) const {
    const unsigned char* p = first + i * stride;
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return p[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        default:
            return 0;  // rejected in accessor()
    }
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "unknown";
    }
}

int componentsOf(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        default:
            return 0;
    }
}

Loader::AccessorData Loader::accessor(int index, int expectedType, const std::string& role) const {
    const std::string what = "accessor " + std::to_string(index) + " (" + role + ")";
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size())
        fail("accessor index " + std::to_string(index) + " (" + role + ") is out of range: the file has " +
             std::to_string(model_.accessors.size()) + " accessors");
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) fail(what + " is a sparse accessor, which Lit does not support");
    if (a.type != expectedType) fail(what + " has type " + typeName(a.type) + ", expected " + typeName(expectedType));
    const int size = gltfkeep::componentBytes(a.componentType);
    if (size == 0) fail(what + " has unsupported component type " + std::to_string(a.componentType));
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT && expectedType != TINYGLTF_TYPE_SCALAR)
        fail(what + " has component type UNSIGNED_INT, which glTF allows only for indices");

    AccessorData data;
    data.count = a.count;
    data.componentType = a.componentType;
    data.components = componentsOf(a.type);
    data.normalized = a.normalized;
    if (a.count == 0) return data;
    if (a.bufferView < 0) fail(what + " has no buffer view (all-zero accessors are not supported)");
    if (static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size())
        fail(what + " refers to buffer view " + std::to_string(a.bufferView) + ", which does not exist (the file has " +
             std::to_string(model_.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::string viewName = "buffer view " + std::to_string(a.bufferView);
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size())
        fail(viewName + " (used by " + what + ") refers to buffer " + std::to_string(view.buffer) +
             ", which does not exist (the file has " + std::to_string(model_.buffers.size()) + ")");
    const tinygltf::Buffer& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
        fail(viewName + " (used by " + what + ") extends past the end of buffer " + std::to_string(view.buffer) +
             " (offset " + std::to_string(view.byteOffset) + " + length " + std::to_string(view.byteLength) + " > " +
             std::to_string(buffer.data.size()) + " bytes)");

    const std::size_t elementSize = static_cast<std::size_t>(size) * static_cast<std::size_t>(data.components);
    data.stride = view.byteStride ? view.byteStride : elementSize;
    if (data.stride < elementSize)
        fail(viewName + " (used by " + what + ") has byteStride " + std::to_string(view.byteStride) +
             ", smaller than one element (" + std::to_string(elementSize) + " bytes)");
    // The last byte read is byteOffset + (count − 1)·stride + elementSize; compare without overflow.
    const std::size_t available = view.byteLength;
    const bool fits = a.byteOffset <= available && elementSize <= available - a.byteOffset &&
                      (a.count - 1) <= (available - a.byteOffset - elementSize) / data.stride;
    if (!fits)
        fail(what + " reads past the end of " + viewName + " (offset " + std::to_string(a.byteOffset) + ", " +
             std::to_string(a.count) + " elements of " + std::to_string(elementSize) + " bytes every " +
             std::to_string(data.stride) + " bytes; the view has " + std::to_string(available) + " bytes)");
    data.first = buffer.data.data() + view.byteOffset + a.byteOffset;
    return data;
}

void Loader::checkExtensions() const {
    // Extensions whose data the loader reads. KHR_mesh_quantization only widens the accessor
    // types allowed for attributes, which the generic accessor reader handles.
    static const std::array<std::string_view, 3> supported = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                              "KHR_mesh_quantization"};
    const auto isSupported = [&](const std::string& e) {
        return std::find(supported.begin(), supported.end(), e) != supported.end();
    };
    for (const std::string& e : model_.extensionsRequired)
        if (!isSupported(e)) fail("requires the glTF extension " + e + ", which Lit does not support");
    for (const std::string& e : model_.extensionsUsed)
        if (!isSupported(e)) warn("ignores the glTF extension " + e + " (not supported; its data is kept and saved back as it was)");
}

// Notes a file's number that a float cannot hold exactly (scene/Scene.h: FileNumbers).
void noteNumber(FileNumbers& numbers, const std::string& key, double file) {
    if (std::isfinite(file) && static_cast<double>(static_cast<float>(file)) != file) numbers[key] = file;
}

// How far from 1 a rotation's length may be and still count as unit: float32 rounding of the
// components (Blender writes float32 values) is a few 1e-8; well inside the glTF validator's
// unit-length tolerance.
constexpr float kUnitQuaternionTolerance = 1e-6f;

void Loader::loadNodes(Scene& scene) const {
    const std::size_t n = model_.nodes.size();
    // Parents, with every index checked, and the tree property (one parent per node) enforced.
    std::vector<int> parent(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        for (int child : model_.nodes[i].children) {
            if (child < 0 || static_cast<std::size_t>(child) >= n)
                fail(describeNode(model_, i) + " has child index " + std::to_string(child) +
                     ", which is out of range (the file has " + std::to_string(n) + " nodes)");
            const auto c = static_cast<std::size_t>(child);
            if (c == i) fail("node cycle: " + describeNode(model_, i) + " is its own child");
            if (parent[c] >= 0)
                fail(describeNode(model_, c) + " is a child of both node " + std::to_string(parent[c]) + " and node " +
                     std::to_string(i) + " (a node may have only one parent)");
            parent[c] = static_cast<int>(i);
        }
    }
    // With one parent per node, a cycle is a parent chain that never reaches a root. Walk each
    // chain once: state 1 = on the current walk, 2 = known to reach a root.
    std::vector<std::uint8_t> state(n, 0);
    std::vector<std::size_t> walk;
    for (std::size_t start = 0; start < n; ++start) {
        walk.clear();
        std::size_t i = start;
        while (true) {
            if (state[i] == 2) break;
            if (state[i] == 1) {
                std::string cycle = describeNode(model_, i);
                for (std::size_t j = static_cast<std::size_t>(parent[i]); j != i;
                     j = static_cast<std::size_t>(parent[j]))
                    cycle = describeNode(model_, j) + " → " + cycle;
                fail("node cycle: " + describeNode(model_, i) + " is its own ancestor (" + cycle + ")");
            }
            state[i] = 1;
            walk.push_back(i);
            if (parent[i] < 0) break;
            i = static_cast<std::size_t>(parent[i]);
        }
        for (std::size_t j : walk) state[j] = 2;
    }

    // The scene's roots.
    std::vector<int> roots;
    const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : (model_.scenes.empty() ? -1 : 0);
    if (sceneIndex >= 0) {
        if (static_cast<std::size_t>(sceneIndex) >= model_.scenes.size())
            fail("the default scene " + std::to_string(sceneIndex) + " does not exist (the file has " +
                 std::to_string(model_.scenes.size()) + " scenes)");
        const tinygltf::Scene& s = model_.scenes[static_cast<std::size_t>(sceneIndex)];
        scene.name = s.name;
        for (int root : s.nodes) {
            if (root < 0 || static_cast<std::size_t>(root) >= n)
                fail("scene " + std::to_string(sceneIndex) + " lists node " + std::to_string(root) +
                     ", which is out of range (the file has " + std::to_string(n) + " nodes)");
            if (parent[static_cast<std::size_t>(root)] >= 0)
                fail("scene " + std::to_string(sceneIndex) + " lists " +
                     describeNode(model_, static_cast<std::size_t>(root)) + " as a root, but it is a child of node " +
                     std::to_string(parent[static_cast<std::size_t>(root)]));
            if (std::find(roots.begin(), roots.end(), root) == roots.end()) roots.push_back(root);
        }
    } else {
        for (std::size_t i = 0; i < n; ++i)
            if (parent[i] < 0) roots.push_back(static_cast<int>(i));
    }

    // The nodes reachable from the roots become Scene::nodes, the others Scene::keptNodes (kept
    // for saving, not drawn), each in file order; `reference` maps a file node to its node
    // reference (scene/Scene.h: keptNodeRef).
    std::vector<int> remap(n, -1);  // file node → index in its list (nodes or keptNodes)
    std::vector<int> reference(n, -1);
    std::vector<std::uint8_t> reachable(n, 0);
    {
        std::vector<int> stack(roots.begin(), roots.end());
        while (!stack.empty()) {
            const auto i = static_cast<std::size_t>(stack.back());
            stack.pop_back();
            reachable[i] = 1;
            for (int child : model_.nodes[i].children) stack.push_back(child);
        }
        int shown = 0, kept = 0;
        for (std::size_t i = 0; i < n; ++i) {
            remap[i] = reachable[i] ? shown++ : kept++;
            reference[i] = reachable[i] ? remap[i] : keptNodeRef(remap[i]);
        }
        if (kept > 0)
            log_.info(path_.filename().string() + ": " + std::to_string(kept) +
                      " nodes are not part of the shown scene; they are kept for saving, not drawn");
    }

    for (std::size_t i = 0; i < n; ++i) {
        const tinygltf::Node& in = model_.nodes[i];
        const std::string what = describeNode(model_, i);
        Node node;
        node.name = in.name;
        node.fileIndex = static_cast<int>(i);
        // A node's parent and children are in its own list (a shown node's parent is shown).
        node.parent = parent[i] >= 0 ? remap[static_cast<std::size_t>(parent[i])] : -1;
        for (int child : in.children) node.children.push_back(remap[static_cast<std::size_t>(child)]);

        if (in.mesh >= 0 && static_cast<std::size_t>(in.mesh) >= model_.meshes.size())
            fail(what + " refers to mesh " + std::to_string(in.mesh) + ", which is out of range (the file has " +
                 std::to_string(model_.meshes.size()) + " meshes)");
        node.mesh = in.mesh;
        if (in.camera >= 0 && static_cast<std::size_t>(in.camera) >= model_.cameras.size())
            fail(what + " refers to camera " + std::to_string(in.camera) + ", which is out of range (the file has " +
                 std::to_string(model_.cameras.size()) + " cameras)");
        node.camera = in.camera;
        if (auto it = in.extensions.find("KHR_lights_punctual"); it != in.extensions.end()) {
            const int light = integerOr(it->second.Get("light"), -1);
            if (light < 0 || static_cast<std::size_t>(light) >= model_.lights.size())
                fail(what + " refers to light " + numberText(it->second.Get("light")) +
                     ", which is out of range (the file has " + std::to_string(model_.lights.size()) + " lights)");
            node.light = light;
        }
        if (in.skin >= 0) {
            if (static_cast<std::size_t>(in.skin) < model_.skins.size()) {
                warn(what + " is skinned; skinning is not supported and the mesh is drawn in its bind pose (the skin is "
                            "kept and saved back)");
                node.skin = in.skin;
            } else {
                warn(what + " refers to skin " + std::to_string(in.skin) + ", which does not exist; ignored");
            }
        }
        node.weights = in.weights;

        if (!in.matrix.empty()) {
            if (in.matrix.size() != 16)
                fail(what + " has a 'matrix' with " + std::to_string(in.matrix.size()) + " numbers, expected 16");
            std::array<float, 16> m{};
            for (std::size_t k = 0; k < 16; ++k) m[k] = static_cast<float>(in.matrix[k]);
            const glm::mat4 local = glm::make_mat4(m.data());  // glTF matrices are column-major, as GLM's
            glm::vec3 skew;
            glm::vec4 perspective;
            if (!glm::decompose(local, node.scale, node.rotation, node.translation, skew, perspective)) {
                // Singular (a zero scale hides a node): keep translation and column lengths.
                warn(what + " has a singular matrix; its rotation is dropped");
                node.translation = glm::vec3(local[3]);
                node.rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
                node.scale = {glm::length(glm::vec3(local[0])), glm::length(glm::vec3(local[1])),
                              glm::length(glm::vec3(local[2]))};
            }
            // Saved back as this matrix while the transform stays as decomposed here.
            node.fileMatrix = in.matrix;
            node.matrixTranslation = node.translation;
            node.matrixRotation = node.rotation;
            node.matrixScale = node.scale;
        } else {
            if (!in.translation.empty()) {
                if (in.translation.size() != 3)
                    fail(what + " has a 'translation' with " + std::to_string(in.translation.size()) +
                         " numbers, expected 3");
                node.translation = glm::vec3(in.translation[0], in.translation[1], in.translation[2]);
            }
            if (!in.rotation.empty()) {
                if (in.rotation.size() != 4)
                    fail(what + " has a 'rotation' with " + std::to_string(in.rotation.size()) +
                         " numbers, expected 4");
                // glTF stores x, y, z, w; glm::quat's constructor takes w first.
                const glm::quat q(static_cast<float>(in.rotation[3]), static_cast<float>(in.rotation[0]),
                                  static_cast<float>(in.rotation[1]), static_cast<float>(in.rotation[2]));
                const float len = glm::length(q);
                if (std::isfinite(len) && len > 1e-6f) {
                    // A unit quaternion as float32 (a few ulp off 1) is kept as the file wrote it,
                    // so a save writes the same numbers; others are normalized.
                    node.rotation = std::abs(len - 1.0f) <= kUnitQuaternionTolerance ? q : q / len;
                } else {
                    warn(what + " has a zero rotation quaternion; using the identity");
                }
            }
            if (!in.scale.empty()) {
                if (in.scale.size() != 3)
                    fail(what + " has a 'scale' with " + std::to_string(in.scale.size()) + " numbers, expected 3");
                node.scale = glm::vec3(in.scale[0], in.scale[1], in.scale[2]);
            }
            for (std::size_t k = 0; k < in.translation.size(); ++k) noteNumber(node.fileNumbers, "t" + std::to_string(k), in.translation[k]);
            for (std::size_t k = 0; k < in.rotation.size(); ++k) noteNumber(node.fileNumbers, "r" + std::to_string(k), in.rotation[k]);
            for (std::size_t k = 0; k < in.scale.size(); ++k) noteNumber(node.fileNumbers, "s" + std::to_string(k), in.scale[k]);
        }
        node.kept = gltfkeep::keep(in.extras, in.extensions, {"KHR_lights_punctual"});
        (reachable[i] ? scene.nodes : scene.keptNodes).push_back(std::move(node));
    }
    for (int root : roots) scene.roots.push_back(remap[static_cast<std::size_t>(root)]);
    nodeRemap_ = reference;
}

// How far from 1 a tangent's length may be and still count as unit (float32 rounding of its
// components is a few 1e-8; exporters write normalized float32 tangents).
constexpr float kUnitTangentTolerance = 1e-6f;

void Loader::loadPrimitive(const tinygltf::Primitive& in, const std::string& meshName, std::size_t primitiveIndex,
                           Primitive& out) const {
    const std::string where = "mesh '" + meshName + "' primitive " + std::to_string(primitiveIndex);
    const auto attribute = [&](const char* name) {
        auto it = in.attributes.find(name);
        return it == in.attributes.end() ? -1 : it->second;
    };
    const int positionIndex = attribute("POSITION");
    if (positionIndex < 0) fail(where + " has no POSITION attribute");
    const AccessorData positions = accessor(positionIndex, TINYGLTF_TYPE_VEC3, "POSITION of " + where);
    const std::size_t vertexCount = positions.count;
    if (vertexCount > std::numeric_limits<std::uint32_t>::max())
        fail(where + " has " + std::to_string(vertexCount) + " vertices, more than 32-bit indices can address");

    out.vertices.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i)
        out.vertices[i].position = {positions.component(i, 0), positions.component(i, 1), positions.component(i, 2)};

    const auto checkCount = [&](const AccessorData& a, int index, const char* name) {
        if (a.count != vertexCount)
            fail("accessor " + std::to_string(index) + " (" + name + " of " + where + ") has " +
                 std::to_string(a.count) + " elements, but POSITION has " + std::to_string(vertexCount));
    };

    const int normalIndex = attribute("NORMAL");
    if (normalIndex >= 0) {
        const AccessorData normals = accessor(normalIndex, TINYGLTF_TYPE_VEC3, "NORMAL of " + where);
        checkCount(normals, normalIndex, "NORMAL");
        for (std::size_t i = 0; i < vertexCount; ++i)
            out.vertices[i].normal = {normals.component(i, 0), normals.component(i, 1), normals.component(i, 2)};
    }
    const int uvIndex = attribute("TEXCOORD_0");
    if (uvIndex >= 0) {
        const AccessorData uvs = accessor(uvIndex, TINYGLTF_TYPE_VEC2, "TEXCOORD_0 of " + where);
        checkCount(uvs, uvIndex, "TEXCOORD_0");
        for (std::size_t i = 0; i < vertexCount; ++i) out.vertices[i].uv = {uvs.component(i, 0), uvs.component(i, 1)};
    }
    // A file's tangents are only meaningful with the file's normals (glTF 2.0 §3.7.2.1).
    const int tangentIndex = normalIndex >= 0 ? attribute("TANGENT") : -1;
    bool haveTangents = false;
    if (tangentIndex >= 0) {
        const AccessorData tangents = accessor(tangentIndex, TINYGLTF_TYPE_VEC4, "TANGENT of " + where);
        checkCount(tangents, tangentIndex, "TANGENT");
        haveTangents = true;
        bool allUnit = true;
        for (std::size_t i = 0; i < vertexCount; ++i) {
            const glm::vec3 t{tangents.component(i, 0), tangents.component(i, 1), tangents.component(i, 2)};
            const float len = glm::length(t);
            if (!std::isfinite(len) || len < 1e-12f || !std::isfinite(tangents.component(i, 3))) {
                haveTangents = false;  // unusable data: recompute the whole primitive below
                break;
            }
            // A tangent already unit within float rounding is kept as the file wrote it, so a
            // save writes the same numbers; others are normalized for drawing, and the file's
            // values kept for a save (Primitive::fileTangents).
            const bool unit = std::abs(len - 1.0f) <= kUnitTangentTolerance;
            allUnit = allUnit && unit && std::abs(tangents.component(i, 3)) == 1.0f;
            out.vertices[i].tangent = glm::vec4(unit ? t : t / len, tangents.component(i, 3) < 0.0f ? -1.0f : 1.0f);
        }
        if (!haveTangents) warn(where + " has zero or non-finite TANGENTs; they are recomputed");
        if (haveTangents && !allUnit) {
            out.fileTangents.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i)
                for (int c = 0; c < 4; ++c) out.fileTangents[i][c] = tangents.component(i, c);
        }
    }

    // Indices: from the accessor, or 0..n−1 for non-indexed geometry.
    if (in.indices >= 0) {
        // The type first: a float index accessor would otherwise be reported as reading past its view.
        const int indexType = static_cast<std::size_t>(in.indices) < model_.accessors.size()
                                  ? model_.accessors[static_cast<std::size_t>(in.indices)].componentType
                                  : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail("accessor " + std::to_string(in.indices) + " (indices of " + where +
                 ") must have an unsigned integer component type (5121, 5123 or 5125), not " + std::to_string(indexType));
        const AccessorData indices = accessor(in.indices, TINYGLTF_TYPE_SCALAR, "indices of " + where);
        out.indices.resize(indices.count);
        for (std::size_t i = 0; i < indices.count; ++i) {
            const std::uint32_t value = indices.index(i);
            if (value >= vertexCount)
                fail(where + ": index " + std::to_string(i) + " has the value " + std::to_string(value) +
                     ", which is out of range (the primitive has " + std::to_string(vertexCount) + " vertices)");
            out.indices[i] = value;
        }
    } else {
        out.indices.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) out.indices[i] = static_cast<std::uint32_t>(i);
    }
    if (out.indices.size() % 3 != 0) {
        warn(where + " has " + std::to_string(out.indices.size()) +
             " indices, not a multiple of 3; the incomplete last triangle is dropped");
        out.indices.resize(out.indices.size() - out.indices.size() % 3);
    }
    // A NaN or infinite position would poison the bounds, the culling and the voxelization: the
    // triangles that use one are dropped (the vertices stay, so kept attributes still line up).
    std::size_t nonFinite = 0;
    for (const Vertex& v : out.vertices)
        if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z)) ++nonFinite;
    if (nonFinite > 0) {
        const auto finite = [&](std::uint32_t i) {
            const glm::vec3& p = out.vertices[i].position;
            return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        };
        std::vector<std::uint32_t> kept;
        kept.reserve(out.indices.size());
        for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3)
            if (finite(out.indices[t]) && finite(out.indices[t + 1]) && finite(out.indices[t + 2]))
                kept.insert(kept.end(), {out.indices[t], out.indices[t + 1], out.indices[t + 2]});
        warn(where + " has " + std::to_string(nonFinite) + " vertex position" + (nonFinite == 1 ? "" : "s") +
             " that are not finite (NaN or infinity); the " + std::to_string((out.indices.size() - kept.size()) / 3) +
             " triangle(s) using them are dropped");
        out.indices = std::move(kept);
    }

    // The attributes and morph targets Lit does not draw with, kept for a save.
    out.keptAttributes = keptAttributes(in.attributes, {"POSITION", "NORMAL", "TEXCOORD_0", "TANGENT"}, where, vertexCount);
    out.morphTargets = keptTargets(in, where, vertexCount);
    if (normalIndex < 0) {
        // computeNormals unwelds: new vertex i is old vertex indices[i]. The kept data follows.
        const std::vector<std::uint32_t> order = out.indices;
        computeNormals(out);
        const auto reorder = [&](KeptAccessor& a) {
            const std::size_t elementSize = a.count ? a.bytes.size() / a.count : 0;
            std::vector<std::uint8_t> bytes(order.size() * elementSize);
            for (std::size_t i = 0; i < order.size(); ++i)
                std::memcpy(bytes.data() + i * elementSize, a.bytes.data() + order[i] * elementSize, elementSize);
            a.bytes = std::move(bytes);
            a.count = order.size();
        };
        for (auto& [name, a] : out.keptAttributes) reorder(a);
        for (KeptAttributes& target : out.morphTargets)
            for (auto& [name, a] : target) reorder(a);
    }
    if (!haveTangents) computeTangents(out);
    out.fileHasTangents = haveTangents;
    out.kept = gltfkeep::keep(in.extras, in.extensions);
    // How the file stored the drawn data and what its accessors held besides the values, for a
    // save (scene/Scene.h: Primitive::fileAccessors).
    {
        // Every drawn attribute in a buffer view (not sparse): written in the file's views again.
        bool inViews = true;
        const auto keepInfo = [&](const char* name, int index) {
            if (index < 0) return;
            const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
            inViews = inViews && a.bufferView >= 0 && !a.sparse.isSparse;
            out.fileAccessors[name] = accessorInfo(index);
        };
        keepInfo("POSITION", positionIndex);
        keepInfo("NORMAL", normalIndex);
        keepInfo("TEXCOORD_0", uvIndex);
        keepInfo("TANGENT", haveTangents ? tangentIndex : -1);
        out.fileViews = inViews;
        if (in.indices >= 0) {
            out.fileIndexType = model_.accessors[static_cast<std::size_t>(in.indices)].componentType;
            out.fileAccessors["indices"] = accessorInfo(in.indices);
        } else {
            out.fileIndexType = 0;
        }
    }
    for (const Vertex& v : out.vertices)
        if (std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z))
            out.bounds.extend(v.position);  // the non-finite ones belong to no triangle (above)
}

void Loader::loadMeshes(Scene& scene) const {
    scene.meshes.reserve(model_.meshes.size());
    report("meshes", 0, model_.meshes.size());
    for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
        const tinygltf::Mesh& in = model_.meshes[m];
        Mesh mesh;
        mesh.name = in.name.empty() ? "mesh " + std::to_string(m) : in.name;
        for (std::size_t p = 0; p < in.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = in.primitives[p];
            const std::string where = "mesh '" + mesh.name + "' primitive " + std::to_string(p);
            // tinygltf reports an absent mode as -1; glTF's default is TRIANGLES.
            if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES) {
                std::optional<KeptPrimitive> kept = keptPrimitive(prim, where);
                warn(where + " has mode " + std::to_string(prim.mode) + " (only TRIANGLES is drawn); " +
                     (kept ? "not drawn, kept for saving" : "skipped"));
                if (kept) mesh.otherPrimitives.push_back(std::move(*kept));
                continue;
            }
            if (prim.material >= 0 && static_cast<std::size_t>(prim.material) >= model_.materials.size())
                fail(where + " refers to material " + std::to_string(prim.material) +
                     ", which is out of range (the file has " + std::to_string(model_.materials.size()) +
                     " materials)");
            if (!prim.targets.empty())
                warn(where + " has morph targets; Lit draws the base shape (the targets are kept and saved back)");
            Primitive out;
            out.material = prim.material;
            loadPrimitive(prim, mesh.name, p, out);
            if (out.indices.empty()) {
                warn(where + " has no triangles; skipped");
                continue;
            }
            mesh.primitives.push_back(std::move(out));
        }
        mesh.weights = in.weights;
        mesh.kept = gltfkeep::keep(in.extras, in.extensions);
        scene.meshes.push_back(std::move(mesh));
        report("meshes", m + 1, model_.meshes.size());
    }
}

int Loader::textureIndex(int index, const std::string& what) const {
    if (index < -1 || index >= static_cast<int>(model_.textures.size()))
        fail(what + " refers to texture " + std::to_string(index) + ", which is out of range (the file has " +
             std::to_string(model_.textures.size()) + " textures)");
    return index;
}

void Loader::loadMaterials(Scene& scene) const {
    for (std::size_t m = 0; m < model_.materials.size(); ++m) {
        const tinygltf::Material& in = model_.materials[m];
        const std::string what = "material " + std::to_string(m) + (in.name.empty() ? "" : " ('" + in.name + "')");
        const auto texture = [&](int index, int texCoord, const char* slot) {
            const int t = textureIndex(index, what + " " + slot);
            if (t >= 0 && texCoord != 0)
                warn(what + " " + slot + " uses TEXCOORD_" + std::to_string(texCoord) +
                     "; Lit draws it with TEXCOORD_0 (the file's choice is saved back)");
            return t;
        };
        Material out;
        out.name = in.name;
        const tinygltf::PbrMetallicRoughness& pbr = in.pbrMetallicRoughness;
        // The spec bounds these factors to 0..1; outside, Lit warns and uses the nearest valid
        // value (which a save writes).
        const auto unitFactors = [&](const std::vector<double>& values, const char* name) {
            std::vector<double> clamped;
            if (!insideUnitRange(values, clamped))
                warn(what + " has " + name + " " + listText(values) + " outside 0..1; Lit uses " + listText(clamped));
            return clamped;
        };
        if (pbr.baseColorFactor.size() == 4) {
            const std::vector<double> f = unitFactors(pbr.baseColorFactor, "baseColorFactor");
            out.baseColorFactor = glm::vec4(f[0], f[1], f[2], f[3]);
        }
        out.baseColorTexture = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, "baseColorTexture");
        out.metallic = static_cast<float>(unitFactors({pbr.metallicFactor}, "metallicFactor")[0]);
        out.roughness = static_cast<float>(unitFactors({pbr.roughnessFactor}, "roughnessFactor")[0]);
        out.metallicRoughnessTexture = texture(pbr.metallicRoughnessTexture.index,
                                               pbr.metallicRoughnessTexture.texCoord, "metallicRoughnessTexture");
        out.normalTexture = texture(in.normalTexture.index, in.normalTexture.texCoord, "normalTexture");
        out.normalScale = static_cast<float>(in.normalTexture.scale);
        if (in.emissiveFactor.size() == 3) {
            const std::vector<double> f = unitFactors(in.emissiveFactor, "emissiveFactor");
            out.emissiveFactor = glm::vec3(f[0], f[1], f[2]);
        }
        out.emissiveTexture = texture(in.emissiveTexture.index, in.emissiveTexture.texCoord, "emissiveTexture");
        out.occlusionTexture = texture(in.occlusionTexture.index, in.occlusionTexture.texCoord, "occlusionTexture");
        out.occlusionStrength = static_cast<float>(in.occlusionTexture.strength);
        if (auto it = in.extensions.find("KHR_materials_emissive_strength"); it != in.extensions.end()) {
            const tinygltf::Value& strength = it->second.Get("emissiveStrength");
            if (strength.IsNumber()) out.emissiveStrength = static_cast<float>(strength.GetNumberAsDouble());
        }
        if (in.alphaMode == "OPAQUE" || in.alphaMode.empty()) {
            out.alphaMode = AlphaMode::Opaque;
        } else if (in.alphaMode == "MASK") {
            out.alphaMode = AlphaMode::Mask;
        } else if (in.alphaMode == "BLEND") {
            out.alphaMode = AlphaMode::Blend;
        } else {
            warn(what + " has unknown alphaMode '" + in.alphaMode + "'; treated as OPAQUE");
        }
        out.alphaCutoff = static_cast<float>(in.alphaCutoff);
        out.doubleSided = in.doubleSided;
        out.kept = gltfkeep::keep(in.extras, in.extensions, {"KHR_materials_emissive_strength"});
        out.textureTexCoord = {pbr.baseColorTexture.texCoord, pbr.metallicRoughnessTexture.texCoord,
                               in.normalTexture.texCoord, in.emissiveTexture.texCoord, in.occlusionTexture.texCoord};
        out.textureExtensions = {gltfkeep::extensionsText(pbr.baseColorTexture.extensions),
                                 gltfkeep::extensionsText(pbr.metallicRoughnessTexture.extensions),
                                 gltfkeep::extensionsText(in.normalTexture.extensions),
                                 gltfkeep::extensionsText(in.emissiveTexture.extensions),
                                 gltfkeep::extensionsText(in.occlusionTexture.extensions)};
        out.textureExtras = {gltfkeep::extrasText(pbr.baseColorTexture.extras),
                             gltfkeep::extrasText(pbr.metallicRoughnessTexture.extras),
                             gltfkeep::extrasText(in.normalTexture.extras), gltfkeep::extrasText(in.emissiveTexture.extras),
                             gltfkeep::extrasText(in.occlusionTexture.extras)};
        out.pbrKept = gltfkeep::keep(pbr.extras, pbr.extensions);
        // What tinygltf does not report: which optional fields the file wrote (a save writes
        // them again, defaults included), and its exact numbers (scene/Scene.h: Material).
        if (const nlohmann::json& file = fileObject("materials", m); file.is_object())
            for (const char* field : gltfkeep::kMaterialFields)
                if (file.contains(nlohmann::json::json_pointer(std::string("/") + field)))
                    out.fileFields.emplace_back(field);
        for (std::size_t c = 0; c < pbr.baseColorFactor.size() && c < 4; ++c)
            noteNumber(out.fileNumbers, "baseColorFactor" + std::to_string(c), pbr.baseColorFactor[c]);
        for (std::size_t c = 0; c < in.emissiveFactor.size() && c < 3; ++c)
            noteNumber(out.fileNumbers, "emissiveFactor" + std::to_string(c), in.emissiveFactor[c]);
        noteNumber(out.fileNumbers, "metallicFactor", pbr.metallicFactor);
        noteNumber(out.fileNumbers, "roughnessFactor", pbr.roughnessFactor);
        noteNumber(out.fileNumbers, "normalScale", in.normalTexture.scale);
        noteNumber(out.fileNumbers, "occlusionStrength", in.occlusionTexture.strength);
        noteNumber(out.fileNumbers, "alphaCutoff", in.alphaCutoff);
        if (auto it = in.extensions.find("KHR_materials_emissive_strength"); it != in.extensions.end())
            if (const tinygltf::Value& strength = it->second.Get("emissiveStrength"); strength.IsNumber())
                noteNumber(out.fileNumbers, "emissiveStrength", strength.GetNumberAsDouble());
        scene.materials.push_back(std::move(out));
    }
}

void Loader::loadTextures(Scene& scene) const {
    for (std::size_t t = 0; t < model_.textures.size(); ++t) {
        const tinygltf::Texture& in = model_.textures[t];
        Texture out;
        out.name = in.name;
        if (in.source >= 0) {
            if (static_cast<std::size_t>(in.source) >= model_.images.size())
                fail("texture " + std::to_string(t) + " refers to image " + std::to_string(in.source) +
                     ", which is out of range (the file has " + std::to_string(model_.images.size()) + " images)");
            out.image = images_.canonical(in.source);  // identical images are decoded once and shared
            out.fileImage = in.source;
        }
        if (in.sampler >= 0) {
            if (static_cast<std::size_t>(in.sampler) >= model_.samplers.size())
                fail("texture " + std::to_string(t) + " refers to sampler " + std::to_string(in.sampler) +
                     ", which is out of range (the file has " + std::to_string(model_.samplers.size()) + " samplers)");
            const tinygltf::Sampler& s = model_.samplers[static_cast<std::size_t>(in.sampler)];
            // Values glTF allows (§5.26); anything else would be a GL error at upload.
            const auto allowed = [&](int value, std::initializer_list<int> values, const char* field, int& target) {
                if (value < 0) return;  // tinygltf reports an unset filter as -1: keep the default
                if (std::find(values.begin(), values.end(), value) != values.end()) {
                    target = value;
                } else {
                    warn("sampler " + std::to_string(in.sampler) + " has an invalid " + field + " " +
                         std::to_string(value) + "; using " + std::to_string(target));
                }
            };
            allowed(s.wrapS, {10497, 33071, 33648}, "wrapS", out.wrapS);
            allowed(s.wrapT, {10497, 33071, 33648}, "wrapT", out.wrapT);
            allowed(s.minFilter, {9728, 9729, 9984, 9985, 9986, 9987}, "minFilter", out.minFilter);
            allowed(s.magFilter, {9728, 9729}, "magFilter", out.magFilter);
            out.samplerName = s.name;
            out.samplerKept = gltfkeep::keep(s.extras, s.extensions);
            // Which fields the sampler wrote (tinygltf reports absent filters as -1 but fills in
            // absent wraps with REPEAT): a save leaves out what the file left out.
            const nlohmann::json& file = fileObject("samplers", static_cast<std::size_t>(in.sampler));
            out.samplerFields = {!file.is_object() || file.contains("wrapS"), !file.is_object() || file.contains("wrapT"),
                                 s.minFilter >= 0, s.magFilter >= 0};
        } else {
            out.hasSampler = false;
        }
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        scene.textures.push_back(out);
    }
}

// Pixels decoded from one image, or why not.
struct DecodedImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
    std::string error;  // empty on success
};

DecodedImage decodeImage(const std::vector<unsigned char>& encoded) {
    DecodedImage out;
    if (encoded.empty()) {
        out.error = "the file is missing or could not be read";
        return out;
    }
    if (encoded.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        out.error = "the image is larger than 2 GiB";
        return out;
    }
    int width = 0, height = 0, channels = 0;
    // stb_image's failure reason is thread-local in stb 2.27, so workers do not race on it.
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(encoded.data(), static_cast<int>(encoded.size()), &width, &height, &channels, 4),
        stbi_image_free);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        out.error = std::string("stb_image could not decode it (") + (reason ? reason : "unknown reason") + ")";
        return out;
    }
    out.width = width;
    out.height = height;
    out.rgba.assign(pixels.get(),
                    pixels.get() + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4u);
    return out;
}

// The MIME type of an embedded image without a mimeType (a data URI): from the URI
// ("data:image/png;base64,...") or else from the bytes' signature.
std::string mimeTypeOf(const std::string& uri, const std::vector<unsigned char>& bytes) {
    if (uri.starts_with("data:")) {
        const std::size_t end = uri.find_first_of(";,", 5);
        if (end != std::string::npos && end > 5) return uri.substr(5, end - 5);
    }
    const auto starts = [&](std::initializer_list<unsigned char> magic) {
        return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
    };
    if (starts({0x89, 'P', 'N', 'G'})) return "image/png";
    if (starts({0xFF, 0xD8, 0xFF})) return "image/jpeg";
    if (starts({0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB})) return "image/ktx2";
    if (bytes.size() >= 12 && std::equal(bytes.begin() + 8, bytes.begin() + 12, "WEBP")) return "image/webp";
    return "application/octet-stream";
}

void Loader::loadImages(Scene& scene) const {
    const std::size_t count = model_.images.size();
    std::vector<DecodedImage> decoded(count);
    report("images", 0, count);
    const std::size_t threads = std::min<std::size_t>(
        count, options_.decodeThreads > 0 ? static_cast<std::size_t>(options_.decodeThreads)
                                          : std::max(1u, std::thread::hardware_concurrency()));
    if (threads <= 1) {
        for (std::size_t i = 0; i < count; ++i) {
            decoded[i] = decodeImage(model_.images[i].image);
            report("images", i + 1, count);
        }
    } else {
        // Workers pull image indices from a shared counter (Sponza has 69 1024² JPEGs; decoding
        // dominates its load time) and each writes only its own slot, so the result does not
        // depend on the thread count. The calling thread only waits and reports progress, so the
        // callback runs on it.
        std::atomic<std::size_t> next{0};
        std::mutex mutex;
        std::condition_variable imageDone;
        std::size_t finished = 0;
        std::exception_ptr error;  // the first worker exception (std::bad_alloc), rethrown here
        const auto work = [&] {
            for (std::size_t i = next++; i < count; i = next++) {
                try {
                    decoded[i] = decodeImage(model_.images[i].image);
                } catch (...) {
                    const std::lock_guard lock(mutex);
                    if (!error) error = std::current_exception();
                }
                {
                    const std::lock_guard lock(mutex);
                    ++finished;
                }
                imageDone.notify_one();
            }
        };
        {
            std::vector<std::jthread> workers;
            for (std::size_t w = 0; w < threads; ++w) workers.emplace_back(work);
            std::unique_lock lock(mutex);
            for (std::size_t reported = 0; reported < count;) {
                imageDone.wait(lock, [&] { return finished != reported; });
                reported = finished;
                lock.unlock();
                report("images", reported, count);
                lock.lock();
            }
        }  // joins the workers
        if (error) std::rethrow_exception(error);
    }

    // How materials use each image: colour slots are sRGB; normal maps need care on failure.
    std::vector<std::uint8_t> usedAsColour(count, 0), usedAsData(count, 0);
    const auto imageOf = [&](int texture) {
        return texture >= 0 ? scene.textures[static_cast<std::size_t>(texture)].image : -1;
    };
    for (const Material& m : scene.materials) {
        for (int t : {m.baseColorTexture, m.emissiveTexture})
            if (int i = imageOf(t); i >= 0) usedAsColour[static_cast<std::size_t>(i)] = 1;
        for (int t : {m.metallicRoughnessTexture, m.normalTexture, m.occlusionTexture})
            if (int i = imageOf(t); i >= 0) usedAsData[static_cast<std::size_t>(i)] = 1;
    }

    std::vector<std::uint8_t> failed(count, 0);
    scene.images.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const tinygltf::Image& in = model_.images[i];
        Image& out = scene.images[i];
        out.name = in.name;
        out.uri = in.uri;
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        // Optional for an image by URI (tinygltf reads it only beside a bufferView); set below for
        // embedded ones.
        if (const nlohmann::json& file = fileObject("images", i); file.is_object())
            if (const auto mime = file.find("mimeType"); mime != file.end() && mime->is_string())
                out.mimeType = mime->get<std::string>();
        if (in.uri.empty() || isDataUri(in.uri)) {
            // Embedded: keep the file's bytes for a save (a copy of an earlier image shares its
            // bytes, which the canonical entry holds).
            out.encoded = model_.images[static_cast<std::size_t>(images_.canonical(static_cast<int>(i)))].image;
            out.mimeType = in.mimeType.empty() ? mimeTypeOf(in.uri, out.encoded) : in.mimeType;
            out.view = keptView(in.bufferView);
        }
        if (images_.canonical(static_cast<int>(i)) != static_cast<int>(i)) {
            // A copy of an earlier image: textures use that one; this entry keeps its name and
            // uri but no pixels of its own.
            out.sameAs = images_.canonical(static_cast<int>(i));
            out.width = 1;
            out.height = 1;
            out.rgba = {255, 255, 255, 255};
            continue;
        }
        out.srgb = usedAsColour[i] != 0;
        if (usedAsColour[i] && usedAsData[i])
            warn("image " + std::to_string(i) + " is used both as colour and as data; it is treated as sRGB colour");
        if (decoded[i].error.empty()) {
            out.width = decoded[i].width;
            out.height = decoded[i].height;
            out.rgba = std::move(decoded[i].rgba);
            continue;
        }
        failed[i] = 1;
        const std::string label =
            !in.uri.empty() ? "'" + in.uri + "'" : (in.name.empty() ? "(embedded)" : "'" + in.name + "'");
        warn("image " + std::to_string(i) + " " + label + ": " + decoded[i].error + "; using a 1x1 white texture");
        out.width = 1;
        out.height = 1;
        out.rgba = {255, 255, 255, 255};
    }

    // Textures without a source (only an unsupported extension's image) get one white image.
    int neutral = -1;
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        if (scene.textures[t].image >= 0) continue;
        if (neutral < 0) {
            neutral = static_cast<int>(scene.images.size());
            scene.images.push_back(Image{"neutral", "", 1, 1, {255, 255, 255, 255}, false});
            scene.images.back().generated = true;  // not in the file: a save leaves it out
            failed.push_back(1);
        }
        warn("texture " + std::to_string(t) + " has no image Lit can read; using a 1x1 white texture");
        scene.textures[t].image = neutral;
    }

    // A white normal map would tilt every normal; drop it so the material uses vertex normals.
    for (Material& m : scene.materials) {
        const int image = imageOf(m.normalTexture);
        if (image >= 0 && failed[static_cast<std::size_t>(image)]) m.normalTexture = -1;
    }
}

void Loader::loadLights(Scene& scene) const {
    for (std::size_t l = 0; l < model_.lights.size(); ++l) {
        const tinygltf::Light& in = model_.lights[l];
        Light out;
        out.name = in.name;
        const std::string what = "light " + std::to_string(l) + (in.name.empty() ? "" : " ('" + in.name + "')");
        // Values outside KHR_lights_punctual's ranges are warnings; Lit uses (and a save writes)
        // the nearest valid value.
        if (in.type == "directional") {
            out.type = LightType::Directional;
        } else if (in.type == "point") {
            out.type = LightType::Point;
        } else if (in.type == "spot") {
            out.type = LightType::Spot;
            constexpr double kQuarterTurn = 1.5707963267948966;  // the largest outerConeAngle
            const double outer = std::isnan(in.spot.outerConeAngle) ? kQuarterTurn : std::clamp(in.spot.outerConeAngle, 1e-4, kQuarterTurn);
            const double inner = std::isnan(in.spot.innerConeAngle) ? 0.0 : std::clamp(in.spot.innerConeAngle, 0.0, outer * 0.999);
            if (outer != in.spot.outerConeAngle || inner != in.spot.innerConeAngle)
                warn(what + " has cone angles inner " + numberText(in.spot.innerConeAngle) + ", outer " +
                     numberText(in.spot.outerConeAngle) + " rad (the spec wants 0 <= inner < outer <= pi/2); Lit uses inner " +
                     numberText(inner) + ", outer " + numberText(outer));
            out.innerConeAngle = static_cast<float>(inner);
            out.outerConeAngle = static_cast<float>(outer);
            noteNumber(out.fileNumbers, "innerConeAngle", in.spot.innerConeAngle);
            noteNumber(out.fileNumbers, "outerConeAngle", in.spot.outerConeAngle);
        } else {
            fail(what + " has unknown type '" + in.type + "'");
        }
        if (in.color.size() == 3) {
            std::vector<double> c;
            if (!insideUnitRange(in.color, c))
                warn(what + " has color " + listText(in.color) + " outside 0..1; Lit uses " + listText(c));
            out.color = glm::vec3(c[0], c[1], c[2]);
            for (std::size_t k = 0; k < 3; ++k) noteNumber(out.fileNumbers, "color" + std::to_string(k), in.color[k]);
        }
        double fileIntensity = in.intensity;
        if (!(fileIntensity >= 0.0)) {
            warn(what + " has intensity " + numberText(fileIntensity) + "; Lit uses 0 (it must not be negative)");
            fileIntensity = 0.0;
        }
        // Photometric in the file (cd, lx), radiometric in the Scene (W/sr, W/m²).
        out.intensity = radiometricFromPhotometric(fileIntensity);
        out.fileIntensity = fileIntensity;
        out.fileIntensityAsLoaded = out.intensity;
        out.range = static_cast<float>(in.range);
        noteNumber(out.fileNumbers, "range", in.range);
        // Lit's own flag (scene/GltfWriter.cpp writes it); glTF has no shadow switch.
        if (in.extras.Has("litCastsShadow") && in.extras.Get("litCastsShadow").IsBool())
            out.castsShadow = in.extras.Get("litCastsShadow").Get<bool>();
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        if (nlohmann::json extras = nlohmann::json::parse(out.kept.extras, nullptr, false); extras.is_object()) {
            extras.erase("litCastsShadow");  // Lit's own flag: written from castsShadow
            out.kept.extras = extras.empty() ? std::string() : extras.dump();
        }
        scene.lights.push_back(std::move(out));
    }
}

void Loader::loadCameras(Scene& scene) const {
    for (std::size_t c = 0; c < model_.cameras.size(); ++c) {
        const tinygltf::Camera& in = model_.cameras[c];
        Camera out;
        out.name = in.name;
        if (in.type == "perspective") {
            const std::string what = "camera " + std::to_string(c) + (in.name.empty() ? "" : " ('" + in.name + "')");
            const tinygltf::PerspectiveCamera& p = in.perspective;
            // The spec: yfov > 0, znear > 0, zfar > znear when present (0 here: absent, infinite).
            if (p.yfov > 0.0 && p.yfov < 3.14159) out.yfov = static_cast<float>(p.yfov);
            else warn(what + " has yfov " + numberText(p.yfov) + " rad; Lit uses " + numberText(out.yfov));
            out.aspectRatio = static_cast<float>(std::max(p.aspectRatio, 0.0));
            if (p.znear > 0.0) out.znear = static_cast<float>(p.znear);
            else warn(what + " has znear " + numberText(p.znear) + "; Lit uses " + numberText(out.znear));
            if (p.zfar > 0.0 && !(p.zfar > out.znear))
                warn(what + " has zfar " + numberText(p.zfar) + " not beyond znear " + numberText(out.znear) +
                     "; Lit uses an infinite far plane");
            out.zfar = p.zfar > out.znear ? static_cast<float>(p.zfar) : 0.0f;
            noteNumber(out.fileNumbers, "yfov", p.yfov);
            noteNumber(out.fileNumbers, "aspectRatio", p.aspectRatio);
            noteNumber(out.fileNumbers, "znear", p.znear);
            noteNumber(out.fileNumbers, "zfar", p.zfar);
        } else {
            warn("camera " + std::to_string(c) + " is " + (in.type.empty() ? std::string("untyped") : in.type) +
                 "; Lit renders it as a perspective camera with yfov 0.8 (it is saved back as it was)");
            if (in.type == "orthographic") {
                out.orthographic = true;
                out.xmag = static_cast<float>(in.orthographic.xmag);
                out.ymag = static_cast<float>(in.orthographic.ymag);
            }
            if (in.orthographic.znear > 0.0) out.znear = static_cast<float>(in.orthographic.znear);
            if (in.orthographic.zfar > in.orthographic.znear) out.zfar = static_cast<float>(in.orthographic.zfar);
            noteNumber(out.fileNumbers, "xmag", in.orthographic.xmag);
            noteNumber(out.fileNumbers, "ymag", in.orthographic.ymag);
            noteNumber(out.fileNumbers, "znear", in.orthographic.znear);
            noteNumber(out.fileNumbers, "zfar", in.orthographic.zfar);
        }
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        scene.cameras.push_back(std::move(out));
    }
}

// Components per element of an accessor type (matrices included), 0 for an unknown type.
int elementComponents(int type) {
    switch (type) {
        case TINYGLTF_TYPE_MAT2:
            return 4;
        case TINYGLTF_TYPE_MAT3:
            return 9;
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return componentsOf(type);
    }
}

KeptObject Loader::keptView(int index) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.bufferViews.size()) return {};
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(index)];
    return KeptObject{view.name, gltfkeep::keep(view.extras, view.extensions)};
}

KeptAccessorInfo Loader::accessorInfo(int index) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) return {};
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const std::size_t stride = a.bufferView >= 0 && static_cast<std::size_t>(a.bufferView) < model_.bufferViews.size()
                                   ? model_.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride
                                   : 0;
    return KeptAccessorInfo{a.name, gltfkeep::keep(a.extras, a.extensions), keptView(a.bufferView), a.minValues, a.maxValues,
                            index, stride, a.bufferView, a.byteOffset};
}

KeptAccessor Loader::keptAccessor(int index, const std::string& role, std::optional<std::size_t> expectedCount) const {
    const std::string what = "accessor " + std::to_string(index) + " (" + role + ")";
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size())
        fail("accessor index " + std::to_string(index) + " (" + role + ") is out of range: the file has " +
             std::to_string(model_.accessors.size()) + " accessors");
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const int size = gltfkeep::componentBytes(a.componentType);
    if (size == 0) fail(what + " has unsupported component type " + std::to_string(a.componentType));
    const int components = elementComponents(a.type);
    if (components == 0) fail(what + " has an unknown type");
    // Matrices of 1- or 2-byte components have padded columns; glTF uses none for attributes.
    if ((a.type == TINYGLTF_TYPE_MAT2 || a.type == TINYGLTF_TYPE_MAT3) && size < 4)
        fail(what + " is a " + typeName(a.type) + " of " + std::to_string(size) + "-byte components, which Lit does not keep");
    if (expectedCount && a.count != *expectedCount)
        fail(what + " has " + std::to_string(a.count) + " elements, expected " + std::to_string(*expectedCount));
    if (!expectedCount && a.bufferView < 0) fail(what + " has no buffer view");

    // A validated pointer to `count` elements of `elementSize` bytes, `stride` apart, in a view.
    const auto viewData = [&](int viewIndex, std::size_t byteOffset, std::size_t elementSize, std::size_t count,
                              bool strided) -> std::pair<const unsigned char*, std::size_t> {
        if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model_.bufferViews.size())
            fail(what + " refers to buffer view " + std::to_string(viewIndex) + ", which does not exist (the file has " +
                 std::to_string(model_.bufferViews.size()) + ")");
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(viewIndex)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size())
            fail(what + ": buffer view " + std::to_string(viewIndex) + " refers to buffer " + std::to_string(view.buffer) +
                 ", which does not exist");
        const tinygltf::Buffer& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)];
        if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
            fail(what + ": buffer view " + std::to_string(viewIndex) + " extends past the end of its buffer");
        const std::size_t stride = strided && view.byteStride ? view.byteStride : elementSize;
        if (stride < elementSize) fail(what + ": buffer view " + std::to_string(viewIndex) + " has a byteStride smaller than one element");
        const std::size_t available = view.byteLength;
        const bool fits = count == 0 || (byteOffset <= available && elementSize <= available - byteOffset &&
                                         (count - 1) <= (available - byteOffset - elementSize) / stride);
        if (!fits) fail(what + " reads past the end of buffer view " + std::to_string(viewIndex));
        return {buffer.data.data() + view.byteOffset + byteOffset, stride};
    };

    const std::size_t elementSize = static_cast<std::size_t>(size) * static_cast<std::size_t>(components);
    KeptAccessor out;
    out.type = typeName(a.type);
    out.componentType = a.componentType;
    out.normalized = a.normalized;
    out.count = a.count;
    out.info = accessorInfo(index);
    std::pair<const unsigned char*, std::size_t> base{nullptr, 0};
    if (a.bufferView >= 0 && a.count > 0) base = viewData(a.bufferView, a.byteOffset, elementSize, a.count, true);
    out.bytes.assign(a.count * elementSize, 0);  // no buffer view: zeros (glTF §3.6.2.3)
    if (base.first) {
        const auto [first, stride] = base;
        for (std::size_t i = 0; i < a.count; ++i) std::memcpy(out.bytes.data() + i * elementSize, first + i * stride, elementSize);
    }
    if (a.sparse.isSparse && a.sparse.count > 0) {
        const auto count = static_cast<std::size_t>(a.sparse.count);
        if (count > a.count) fail(what + " has more sparse elements (" + std::to_string(count) + ") than elements");
        const int indexSize = gltfkeep::componentBytes(a.sparse.indices.componentType);
        if (a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(what + "'s sparse indices must be unsigned integers");
        const auto indices = viewData(a.sparse.indices.bufferView, static_cast<std::size_t>(std::max(a.sparse.indices.byteOffset, 0)),
                                      static_cast<std::size_t>(indexSize), count, false);
        const auto values = viewData(a.sparse.values.bufferView, static_cast<std::size_t>(std::max(a.sparse.values.byteOffset, 0)),
                                     elementSize, count, false);
        KeptAccessor::Sparse sparse;
        sparse.indexComponentType = a.sparse.indices.componentType;
        sparse.indicesView = keptView(a.sparse.indices.bufferView);
        sparse.valuesView = keptView(a.sparse.values.bufferView);
        if (const auto found = sparseKept_.find(index); found != sparseKept_.end())
            std::tie(sparse.sparseKept, sparse.indicesKept, sparse.valuesKept) =
                std::tie(found->second[0], found->second[1], found->second[2]);
        sparse.hasBase = base.first != nullptr;
        sparse.indices.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
            std::uint32_t target = 0;
            const unsigned char* p = indices.first + i * static_cast<std::size_t>(indexSize);
            if (indexSize == 1) target = p[0];
            if (indexSize == 2) {
                std::uint16_t v;
                std::memcpy(&v, p, 2);
                target = v;
            }
            if (indexSize == 4) std::memcpy(&target, p, 4);
            if (target >= a.count)
                fail(what + " has the sparse index " + std::to_string(target) + ", out of range (" +
                     std::to_string(a.count) + " elements)");
            sparse.indices.push_back(target);
            if (sparse.hasBase) {
                const std::uint8_t* element = out.bytes.data() + target * elementSize;
                sparse.baseBytes.insert(sparse.baseBytes.end(), element, element + elementSize);
            }
            std::memcpy(out.bytes.data() + target * elementSize, values.first + i * elementSize, elementSize);
        }
        out.sparse = std::move(sparse);
    }
    return out;
}

KeptAttributes Loader::keptAttributes(const std::map<std::string, int>& attributes,
                                      std::initializer_list<std::string_view> skip, const std::string& where,
                                      std::size_t vertexCount) const {
    KeptAttributes out;
    for (const auto& [name, index] : attributes) {
        if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
        try {
            out[name] = keptAccessor(index, name + " of " + where, vertexCount);
        } catch (const SceneLoadError& e) {
            warn(std::string(e.what()) + "; the attribute is not kept");
        }
    }
    return out;
}

std::vector<KeptAttributes> Loader::keptTargets(const tinygltf::Primitive& in, const std::string& where,
                                                std::size_t vertexCount) const {
    std::vector<KeptAttributes> out;
    for (std::size_t t = 0; t < in.targets.size(); ++t)
        out.push_back(keptAttributes(in.targets[t], {}, "morph target " + std::to_string(t) + " of " + where, vertexCount));
    return out;
}

// A primitive of a mode Lit does not draw, as the file had it; none when its data is unusable.
std::optional<KeptPrimitive> Loader::keptPrimitive(const tinygltf::Primitive& in, const std::string& where) const {
    const auto position = in.attributes.find("POSITION");
    if (position == in.attributes.end() || position->second < 0 ||
        static_cast<std::size_t>(position->second) >= model_.accessors.size())
        return std::nullopt;
    const tinygltf::Accessor& positions = model_.accessors[static_cast<std::size_t>(position->second)];
    if (positions.bufferView < 0) return std::nullopt;  // its count is not bounded by the file's data
    KeptPrimitive out;
    out.mode = in.mode;
    out.material = in.material;
    try {
        // All attributes must be readable here: a line primitive missing one is worse than none.
        for (const auto& [name, index] : in.attributes) out.attributes[name] = keptAccessor(index, name + " of " + where, positions.count);
        if (in.indices >= 0) out.indices = keptAccessor(in.indices, "indices of " + where, std::nullopt);
        for (std::size_t t = 0; t < in.targets.size(); ++t) {
            KeptAttributes target;
            for (const auto& [name, index] : in.targets[t])
                target[name] = keptAccessor(index, name + " of morph target " + std::to_string(t) + " of " + where, positions.count);
            out.morphTargets.push_back(std::move(target));
        }
    } catch (const SceneLoadError& e) {
        warn(e.what());
        return std::nullopt;
    }
    out.kept = gltfkeep::keep(in.extras, in.extensions);
    return out;
}

// Skins, kept for saving: joints as Scene node indices, inverse bind matrices as floats. A skin
// whose joints are not all imported keeps a joint of -1, and a save leaves it out.
void Loader::loadSkins(Scene& scene) const {
    for (std::size_t s = 0; s < model_.skins.size(); ++s) {
        const tinygltf::Skin& in = model_.skins[s];
        const std::string what = "skin " + std::to_string(s) + (in.name.empty() ? "" : " ('" + in.name + "')");
        Skin out;
        out.name = in.name;
        const auto node = [&](int index) {
            return index >= 0 && static_cast<std::size_t>(index) < nodeRemap_.size() ? nodeRemap_[static_cast<std::size_t>(index)] : -1;
        };
        for (int joint : in.joints) out.joints.push_back(node(joint));
        if (std::find(out.joints.begin(), out.joints.end(), -1) != out.joints.end())
            warn(what + " has joints that do not exist; it is not saved back");
        out.skeleton = node(in.skeleton);
        if (in.inverseBindMatrices >= 0) {
            try {
                const KeptAccessor matrices = keptAccessor(in.inverseBindMatrices, "inverseBindMatrices of " + what, in.joints.size());
                if (matrices.type != "MAT4" || matrices.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                    fail(what + "'s inverseBindMatrices are not MAT4 floats");
                out.inverseBindMatrices.resize(matrices.bytes.size() / sizeof(float));
                out.inverseBindMatricesInfo = matrices.info;
                std::memcpy(out.inverseBindMatrices.data(), matrices.bytes.data(), matrices.bytes.size());
            } catch (const SceneLoadError& e) {
                warn(std::string(e.what()) + "; the skin is not saved back");
                out.joints.assign(out.joints.size(), -1);
            }
        }
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        scene.skins.push_back(std::move(out));
    }
}

// Every animation, as floats, for the writer to save back (Lit plays camera paths only). One
// that cannot be read is reported and left out; the load goes on.
void Loader::loadAnimations(Scene& scene) const {
    for (std::size_t a = 0; a < model_.animations.size(); ++a) {
        const tinygltf::Animation& in = model_.animations[a];
        const std::string what = "animation " + std::to_string(a) + (in.name.empty() ? "" : " ('" + in.name + "')");
        Animation out;
        out.name = in.name;
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        try {
            for (std::size_t i = 0; i < in.samplers.size(); ++i) {
                const tinygltf::AnimationSampler& s = in.samplers[i];
                const std::string where = what + " sampler " + std::to_string(i);
                if (s.output < 0 || static_cast<std::size_t>(s.output) >= model_.accessors.size())
                    fail(where + " has no valid output accessor");
                const int outputType = model_.accessors[static_cast<std::size_t>(s.output)].type;
                const AccessorData input = accessor(s.input, TINYGLTF_TYPE_SCALAR, "input of " + where);
                const AccessorData output = accessor(s.output, outputType, "output of " + where);
                Animation::Sampler sampler;
                sampler.interpolation = s.interpolation.empty() ? "LINEAR" : s.interpolation;
                sampler.components = output.components;
                sampler.kept = gltfkeep::keep(s.extras, s.extensions);
                sampler.inputInfo = accessorInfo(s.input);
                sampler.outputInfo = accessorInfo(s.output);
                sampler.fileInput = s.input;
                sampler.fileOutput = s.output;
                sampler.outputComponentType = output.componentType;
                sampler.outputNormalized = output.normalized;
                for (std::size_t k = 0; k < input.count; ++k) sampler.input.push_back(input.component(k, 0));
                for (std::size_t k = 0; k < output.count; ++k)
                    for (int c = 0; c < output.components; ++c) sampler.output.push_back(output.component(k, c));
                out.samplers.push_back(std::move(sampler));
            }
            for (const tinygltf::AnimationChannel& c : in.channels) {
                if (c.sampler < 0 || static_cast<std::size_t>(c.sampler) >= out.samplers.size())
                    fail(what + " has a channel with sampler " + std::to_string(c.sampler) + ", which does not exist");
                if (c.target_node < 0 || static_cast<std::size_t>(c.target_node) >= nodeRemap_.size()) continue;
                const int node = nodeRemap_[static_cast<std::size_t>(c.target_node)];
                if (node == -1) continue;
                out.channels.push_back({c.sampler, node, c.target_path, gltfkeep::keep(c.extras, c.extensions)});
            }
        } catch (const SceneLoadError& e) {
            warn(std::string(e.what()) + "; the animation is not kept");
            continue;
        }
        scene.animations.push_back(std::move(out));
    }
    scene.cameraAnimationNames = cameraAnimationNames(model_);
}

// The file-level data Lit does not use, for a lossless save.
void Loader::keepFileData(Scene& scene) const {
    const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : (model_.scenes.empty() ? -1 : 0);
    if (sceneIndex >= 0) {
        const tinygltf::Scene& s = model_.scenes[static_cast<std::size_t>(sceneIndex)];
        scene.kept = gltfkeep::keep(s.extras, s.extensions);
    }
    scene.fileKept = gltfkeep::keep(model_.extras, model_.extensions, {"KHR_lights_punctual"});
    scene.copyright = model_.asset.copyright;
    scene.generator = model_.asset.generator;
    for (const tinygltf::Buffer& buffer : model_.buffers) {
        scene.buffers.push_back(KeptObject{buffer.name, gltfkeep::keep(buffer.extras, buffer.extensions)});
        scene.fileBufferSizes.push_back(buffer.data.size());
    }
    for (const tinygltf::BufferView& view : model_.bufferViews) {
        Scene::FileBufferView place{view.buffer, view.byteOffset, view.byteLength, 0};
        const std::vector<unsigned char>* data =
            view.buffer >= 0 && static_cast<std::size_t>(view.buffer) < model_.buffers.size()
                ? &model_.buffers[static_cast<std::size_t>(view.buffer)].data
                : nullptr;
        if (data && view.byteOffset <= data->size() && view.byteLength <= data->size() - view.byteOffset)
            place.hash = gltfkeep::hashBytes(data->data() + view.byteOffset, view.byteLength);
        else
            place.buffer = -1;  // never matched (the loader reports views it reads past their buffer)
        scene.fileBufferViews.push_back(place);
    }
    scene.assetKept = gltfkeep::keep(model_.asset.extras, model_.asset.extensions);
    // The other scenes.
    scene.sceneIndex = std::max(sceneIndex, 0);
    for (std::size_t i = 0; i < model_.scenes.size(); ++i) {
        if (static_cast<int>(i) == sceneIndex) continue;
        const tinygltf::Scene& s = model_.scenes[i];
        Scene::OtherScene other{s.name, {}, gltfkeep::keep(s.extras, s.extensions)};
        // Its roots: nodes the shown scene shares, or kept nodes (scene/Scene.h: keptNodeRef).
        for (int root : s.nodes) {
            const int mapped = root >= 0 && static_cast<std::size_t>(root) < nodeRemap_.size()
                                   ? nodeRemap_[static_cast<std::size_t>(root)]
                                   : -1;
            if (mapped == -1)
                warn("scene " + std::to_string(i) + (s.name.empty() ? "" : " ('" + s.name + "')") + " lists node " +
                     std::to_string(root) + ", which does not exist; a save leaves it out");
            else if (std::find(other.roots.begin(), other.roots.end(), mapped) == other.roots.end())
                other.roots.push_back(mapped);
        }
        scene.otherScenes.push_back(std::move(other));
    }
    static const std::array<std::string_view, 2> own = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
    for (const std::string& e : model_.extensionsUsed)
        if (std::find(own.begin(), own.end(), e) == own.end()) scene.unknownExtensionsUsed.push_back(e);
    scene.extensionsRequired = model_.extensionsRequired;
}

Scene Loader::run() {
    Scene scene;
    scene.sourcePath = path_;
    checkExtensions();
    loadNodes(scene);
    if (scene.name.empty()) {
        scene.name = path_.stem().string();
        scene.fileSceneNamed = false;
    }
    loadMeshes(scene);
    loadMaterials(scene);
    loadTextures(scene);
    loadImages(scene);
    report("scene", 0, 1);
    loadLights(scene);
    loadCameras(scene);
    loadSkins(scene);
    loadAnimations(scene);
    keepFileData(scene);
    scene.updateWorldTransforms();
    report("scene", 1, 1);
    return scene;
}

// Splits tinygltf's newline-separated messages.
std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(line);
    return out;
}

// What tinygltf 2.7 does not read, from the file's JSON: an animation sampler's "extensions" (tinygltf reads them
// from the animation object instead of the sampler, fixed in the model) and the extras and
// extensions of sparse accessors' parts (returned by accessor index).
std::map<int, std::array<KeptGltf, 3>> readWhatTinygltfSkips(tinygltf::Model& model, const nlohmann::json& doc) {
    std::map<int, std::array<KeptGltf, 3>> sparseKept;
    const bool sparse = std::any_of(model.accessors.begin(), model.accessors.end(),
                                    [](const tinygltf::Accessor& a) { return a.sparse.isSparse; });
    if (model.animations.empty() && !sparse) return sparseKept;
    if (sparse && doc.is_object() && doc.contains("accessors") && doc["accessors"].is_array()) {
        const nlohmann::json& accessors = doc["accessors"];
        for (std::size_t i = 0; i < accessors.size() && i < model.accessors.size(); ++i) {
            if (!model.accessors[i].sparse.isSparse || !accessors[i].is_object()) continue;
            const auto found = accessors[i].find("sparse");
            if (found == accessors[i].end() || !found->is_object()) continue;
            const auto part = [&](const char* key) {
                const auto p = found->find(key);
                return p == found->end() ? KeptGltf{} : gltfkeep::keepFromJson(*p);
            };
            std::array<KeptGltf, 3> kept{gltfkeep::keepFromJson(*found), part("indices"), part("values")};
            if (!(kept == std::array<KeptGltf, 3>{})) sparseKept[static_cast<int>(i)] = std::move(kept);
        }
    }
    const nlohmann::json* animations = doc.is_object() && doc.contains("animations") ? &doc["animations"] : nullptr;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const nlohmann::json* samplers = animations && animations->is_array() && a < animations->size() &&
                                                 (*animations)[a].is_object() && (*animations)[a].contains("samplers")
                                             ? &(*animations)[a]["samplers"]
                                             : nullptr;
        for (std::size_t i = 0; i < model.animations[a].samplers.size(); ++i) {
            tinygltf::ExtensionMap& extensions = model.animations[a].samplers[i].extensions;
            extensions.clear();
            if (!samplers || !samplers->is_array() || i >= samplers->size() || !(*samplers)[i].is_object()) continue;
            const auto found = (*samplers)[i].find("extensions");
            if (found == (*samplers)[i].end() || !found->is_object()) continue;
            for (auto it = found->begin(); it != found->end(); ++it) extensions[it.key()] = gltfkeep::toValue(it.value());
        }
    }
    return sparseKept;
}

}  // namespace

Scene loadGltf(const std::filesystem::path& path, Log& log, const GltfLoadOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (options.progress) options.progress({"file", 0, 1});
    checkSceneFile(path, options.limits);
    const Container container = detectContainer(path);
    // Size, depth, version and URIs checked before tinygltf sees the file (io/GltfGuard.h).
    const GuardedScene guarded = guardGltfFile(path, container == Container::Binary, options.limits);
    GuardedFileSystem files(path, options.limits, guarded.externalImages, guarded.absoluteFiles);

    tinygltf::Model model;
    tinygltf::TinyGLTF parser;
    parser.SetFsCallbacks(files.callbacks());
    ImageCallbackContext imageContext;
    imageContext.model = &model;
    parser.SetImageLoader(&keepEncodedImage, &imageContext);
    std::string err, warn;
    bool ok = false;
    try {
        const std::string baseDir = path.parent_path().string();
        ok = container == Container::Binary
                 ? parser.LoadBinaryFromMemory(&model, &err, &warn, guarded.bytes.data(),
                                               static_cast<unsigned int>(guarded.bytes.size()), baseDir)
                 : parser.LoadASCIIFromString(&model, &err, &warn, guarded.json.data(),
                                              static_cast<unsigned int>(guarded.json.size()), baseDir);
    } catch (const std::exception& e) {
        throw SceneLoadError(path.string() + ": tinygltf failed: " + e.what());
    }
    const std::string file = path.filename().string();
    for (const std::string& line : lines(warn)) log.warning(file + ": " + line);
    for (const std::string& problem : imageContext.problems) log.warning(file + ": " + problem);
    for (const std::string& refusal : files.refusals()) log.warning(file + ": not read: " + refusal);
    if (!ok) {
        std::string message =
            path.string() + ": " +
            (container == Container::Binary ? "cannot load the GLB file" : "cannot load the glTF file");
        std::vector<std::string> errors = lines(err);
        for (const std::string& refusal : files.refusals()) errors.push_back("not read: " + refusal);
        for (std::size_t i = 0; i < errors.size(); ++i) message += (i == 0 ? ": " : "; ") + errors[i];
        throw SceneLoadError(message);
    }
    for (std::size_t i = 0; i < model.images.size(); ++i) model.images[i].image = imageContext.images.take(static_cast<int>(i));
    // The JSON once more, for what tinygltf does not read or report (a few ms for Sponza's 0.3 MB).
    const nlohmann::json doc = nlohmann::json::parse(guarded.json.begin(), guarded.json.end(), nullptr, false);
    const std::map<int, std::array<KeptGltf, 3>> sparseKept = readWhatTinygltfSkips(model, doc);
    checkMemoryBudget(path, model, imageContext.images, options.limits);

    if (options.progress) options.progress({"file", 1, 1});
    Scene scene = Loader(path, model, log, options, imageContext.images, sparseKept, doc).run();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // The one summary line of a load, for every front end: "loaded Sponza.gltf: 1 mesh, 262k
    // triangles, 69 textures, 297 MB in 3912 ms".
    log.info("loaded " + toString(summarize(scene)) + " in " + std::to_string(static_cast<long long>(ms + 0.5)) + " ms");
    return scene;
}

SceneSummary summarize(const Scene& scene) {
    SceneSummary s;
    s.name = !scene.sourcePath.empty() ? scene.sourcePath.filename().string() : scene.name;
    s.nodes = scene.nodes.size();
    s.meshes = scene.meshes.size();
    for (const Mesh& mesh : scene.meshes)
        for (const Primitive& p : mesh.primitives) {
            ++s.primitives;
            s.triangles += p.indices.size() / 3;
            s.vertices += p.vertices.size();
            s.vertexBytes += p.vertices.size() * sizeof(Vertex);
            s.indexBytes += p.indices.size() * sizeof(std::uint32_t);
        }
    s.materials = scene.materials.size();
    s.textures = scene.textures.size();
    s.images = scene.images.size();
    for (const Image& image : scene.images) s.pixelBytes += image.rgba.size();
    s.lights = scene.lights.size();
    s.cameras = scene.cameras.size();
    return s;
}

std::string toString(const SceneSummary& summary) {
    const auto count = [](std::size_t n, const char* one, const char* many) {
        const std::string number = n >= 10000 ? std::to_string((n + 500) / 1000) + "k" : std::to_string(n);
        return number + " " + (n == 1 ? one : many);
    };
    char megabytes[32];
    std::snprintf(megabytes, sizeof megabytes, "%.0f MB", static_cast<double>(summary.cpuBytes()) / 1e6);
    return summary.name + ": " + count(summary.meshes, "mesh", "meshes") + ", " +
           count(summary.triangles, "triangle", "triangles") + ", " +
           count(summary.textures, "texture", "textures") + ", " + megabytes;
}

}  // namespace lit
