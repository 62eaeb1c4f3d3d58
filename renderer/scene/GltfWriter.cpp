// glTF 2.0 export: Scene → tinygltf::Model → files (io/GltfFile.h writes them atomically).
//
// Decisions worth knowing:
// - All geometry and embedded images go into one buffer: "<stem>.bin" beside a .gltf, the BIN
//   chunk of a .glb. A primitive's vertices are one interleaved buffer view (lit::Vertex as it
//   is in memory: POSITION, NORMAL, TEXCOORD_0, TANGENT every 48 bytes); indices are UNSIGNED_INT.
// - The nodes reachable from Scene::roots are written first, in index order, then
//   Scene::keptNodes (the file's nodes outside the shown scene), in theirs: a file whose shown
//   nodes came first keeps its node indices. Primitives without triangles are left out (the
//   loader skips them), and so are meshes left with none.
// - Names, extras and extensions of the file's accessors, buffer views and buffers go on the
//   accessor or view that holds the same data again (kept attributes, sparse data, embedded
//   images, animation data); the one buffer gets those of all the file's buffers.
// - asset.generator is "Lit": glTF means the tool that wrote the file, and importers use it to
//   work around that tool's quirks. The file's own generator goes to the asset's extras as
//   "litSourceGenerator" (a file Lit wrote keeps the one it already has there).
// - An image that came from a file which still exists is referenced by a URI relative to the new
//   file's folder (not copied, not re-encoded: JPEGs stay JPEGs); an image embedded in the source
//   is written with its own bytes and MIME type (Image::encoded: 16-bit PNGs and KTX2 stay as
//   they were); any other image (generated, or from a file that is gone) is encoded as PNG into
//   the buffer. The loader's white stand-in (Image::generated) is not written.
// - Every glTF scene of the source is written, in its order (Scene::otherScenes around the
//   shown one, which keeps its index as `scene`).
// - Kept accessors that were sparse are written sparse (KeptAccessor::Sparse).
// - What the loader kept without drawing it (scene/Scene.h: KeptAccessor and friends) is written
//   back in its own component types: extra vertex attributes and morph targets (one buffer view
//   each, strides padded to 4 bytes), primitives of other modes, skins (joints remapped like the
//   nodes; a skin with a joint that is no longer written is left out), node and mesh weights,
//   texture coordinate sets and orthographic cameras. Kept per-vertex data whose element count no
//   longer matches the primitive's vertices (an edit rebuilt them) is left out.
// - Light intensities are written in glTF's photometric units: Scene's W/sr and W/m² times
//   683 lm/W (scene/LightUnits.h), or the file's own number for a light that was not edited.
// - Light::castsShadow has no glTF equivalent; false is written to the light's extras as
//   {"litCastsShadow": false}, which the loader reads back.
// - A camera's zfar of 0 (fitted to the scene) is written as no zfar, which glTF reads as an
//   infinite far plane.

#include "scene/GltfWriter.h"

#include "animation/CameraPathIO.h"
#include "image/ImageIO.h"
#include "io/GltfFile.h"
#include "scene/GltfKeep.h"
#include "scene/LightUnits.h"
#include "scene/Scene.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

namespace lit {

namespace {

namespace fs = std::filesystem;

constexpr int kArrayBuffer = 34962;         // GL_ARRAY_BUFFER: vertex attributes
constexpr int kElementArrayBuffer = 34963;  // GL_ELEMENT_ARRAY_BUFFER: indices
constexpr const char* kLightsExtension = "KHR_lights_punctual";
constexpr const char* kEmissiveStrengthExtension = "KHR_materials_emissive_strength";
constexpr const char* kCastsShadowKey = "litCastsShadow";
constexpr const char* kGenerator = "Lit";
constexpr const char* kSourceGeneratorKey = "litSourceGenerator";

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string named(const std::string& kind, std::size_t index, const std::string& name) {
    return kind + " " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
}

// The file's exact number of a field while its float still equals it, else the float
// (scene/Scene.h: FileNumbers).
double fileOr(const FileNumbers& numbers, const std::string& key, float value) {
    const auto it = numbers.find(key);
    return it != numbers.end() && static_cast<float>(it->second) == value ? it->second : static_cast<double>(value);
}

template <int N>
std::vector<double> fileOr(const FileNumbers& numbers, const char* prefix, const glm::vec<N, float>& v) {
    std::vector<double> out(N);
    for (int i = 0; i < N; ++i) out[static_cast<std::size_t>(i)] = fileOr(numbers, prefix + std::to_string(i), v[i]);
    return out;
}

template <int N>
std::vector<double> doubles(const glm::vec<N, float>& v) {
    std::vector<double> out(N);
    for (int i = 0; i < N; ++i) out[static_cast<std::size_t>(i)] = v[i];
    return out;
}

class ModelBuilder {
public:
    // `replacedAnimation`: the name of a kept animation not to write (the caller writes its own).
    ModelBuilder(const Scene& scene, const fs::path& file, std::string replacedAnimation)
        : scene_(scene), file_(file), replacedAnimation_(std::move(replacedAnimation)) {}

    tinygltf::Model build();
    std::vector<std::pair<std::string, std::string>> takeJsonPatches() { return std::move(jsonPatches_); }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw SceneSaveError(file_.string() + ": " + problem); }
    void checkIndex(int index, std::size_t count, const std::string& what, const char* kind) const;
    void checkFinite(float value, const std::string& what) const;
    template <int N>
    void checkFinite(const glm::vec<N, float>& value, const std::string& what) const {
        for (int i = 0; i < N; ++i) checkFinite(value[i], what);
    }
    void checkScene() const;
    std::vector<int> reachableNodes() const;

    int addBufferView(const void* data, std::size_t bytes, int target, std::size_t stride);
    int addAccessor(int view, std::size_t byteOffset, int componentType, int type, std::size_t count);
    // A kept accessor (scene/Scene.h); vertex data (`target` kArrayBuffer) gets a stride that is
    // a multiple of 4 bytes, as glTF requires.
    int addKeptAccessor(const KeptAccessor& kept, int target);
    // Attribute name → accessor, for kept attributes whose count is `vertexCount` (others are
    // dropped: the geometry was rebuilt). False when one was dropped.
    bool addKeptAttributes(const KeptAttributes& kept, std::size_t vertexCount, std::map<std::string, int>& attributes);
    void addTargets(const std::vector<KeptAttributes>& targets, std::size_t vertexCount, tinygltf::Primitive& primitive);
    void addSkins();
    // The written index of a node reference (scene/Scene.h: keptNodeRef), -1 when not written.
    int writtenNode(int reference) const;
    // Names, extras and extensions of the file's objects Lit lays out itself (scene/Scene.h).
    void keepView(int view, const KeptObject& kept);
    void keepAccessor(int accessor, const KeptAccessorInfo& info);
    template <class Object>
    void keepNameAndExtras(Object& out, const char* array, int index, const std::string& name, const KeptGltf& kept);
    void keepBuffers();
    void checkKeptNodes() const;
    std::optional<std::string> relativeUri(const Image& image) const;
    void addImages();
    void addTextures();
    void addMaterials();
    void addMeshes();
    void addLights();
    void addCameras();
    void addNodes();
    void addAnimations();
    void useExtension(const std::string& name);
    // Writes what the loader kept back into an object, declaring the extensions it brings.
    void restore(const KeptGltf& kept, tinygltf::Value& extras, tinygltf::ExtensionMap& extensions);
    void restoreTextureInfo(const std::string& keptExtras, const std::string& keptExtensions, tinygltf::Value& extras,
                            tinygltf::ExtensionMap& extensions);

    const Scene& scene_;
    const fs::path& file_;
    tinygltf::Model model_;
    std::string replacedAnimation_;
    std::vector<int> meshIndex_;  // scene mesh → glTF mesh, -1 when left out
    std::vector<int> nodeIndex_;  // scene node → glTF node, -1 when not written
    std::vector<int> keptNodeIndex_;  // Scene::keptNodes → glTF node
    std::vector<int> skinIndex_;  // scene skin → glTF skin, -1 when not written
    std::vector<int> imageIndex_;  // scene image → glTF image, -1 when not written (generated)
    // JSON the tinygltf serialiser cannot write (a sampler's name and extensions): JSON pointer →
    // value text, set into the document by writeGltfModel.
    std::vector<std::pair<std::string, std::string>> jsonPatches_;
    bool wroteKeptVertexData_ = false;  // kept attributes or morph targets (KHR_mesh_quantization)
};

void ModelBuilder::restore(const KeptGltf& kept, tinygltf::Value& extras, tinygltf::ExtensionMap& extensions) {
    gltfkeep::restore(kept, extras, extensions);
    for (const auto& [name, value] : extensions) useExtension(name);
}

void ModelBuilder::restoreTextureInfo(const std::string& keptExtras, const std::string& keptExtensions,
                                      tinygltf::Value& extras, tinygltf::ExtensionMap& extensions) {
    restore(KeptGltf{keptExtras, keptExtensions}, extras, extensions);
}

// Gives object `index` of the file's `array` ("accessors", "bufferViews") the name, extras and
// extensions it had: tinygltf 2.7 writes no extensions for these, so they go in as a JSON patch.
template <class Object>
void ModelBuilder::keepNameAndExtras(Object& out, const char* array, int index, const std::string& name,
                                     const KeptGltf& kept) {
    out.name = name;
    tinygltf::ExtensionMap extensions;
    restore(kept, out.extras, extensions);
    if (!kept.extensions.empty())
        jsonPatches_.emplace_back("/" + std::string(array) + "/" + std::to_string(index) + "/extensions", kept.extensions);
}

void ModelBuilder::keepView(int view, const KeptObject& kept) {
    if (view < 0 || kept.empty()) return;
    keepNameAndExtras(model_.bufferViews[static_cast<std::size_t>(view)], "bufferViews", view, kept.name, kept.kept);
}

void ModelBuilder::keepAccessor(int accessor, const KeptAccessorInfo& info) {
    if (accessor < 0) return;
    tinygltf::Accessor& out = model_.accessors[static_cast<std::size_t>(accessor)];
    keepNameAndExtras(out, "accessors", accessor, info.name, info.kept);
    keepView(out.bufferView, info.view);
}

// The one buffer gets the first buffer's name (the first that has one) and every buffer's extras
// keys and extensions, the first buffer's winning.
void ModelBuilder::keepBuffers() {
    if (model_.buffers.empty()) return;
    tinygltf::Buffer& out = model_.buffers[0];
    nlohmann::json extensions = nlohmann::json::object();
    for (const KeptObject& kept : scene_.buffers) {
        if (out.name.empty()) out.name = kept.name;
        tinygltf::ExtensionMap ignored;
        if (!(out.extras.Type() != tinygltf::NULL_TYPE && !out.extras.IsObject()))  // a non-object extras: the first's
            restore(KeptGltf{kept.kept.extras, ""}, out.extras, ignored);
        const nlohmann::json e = nlohmann::json::parse(kept.kept.extensions.empty() ? "{}" : kept.kept.extensions, nullptr, false);
        if (e.is_object())
            for (auto it = e.begin(); it != e.end(); ++it)
                if (!extensions.contains(it.key())) {
                    extensions[it.key()] = it.value();
                    useExtension(it.key());
                }
    }
    // tinygltf 2.7 writes no buffer extensions: set them in the JSON.
    if (!extensions.empty()) jsonPatches_.emplace_back("/buffers/0/extensions", extensions.dump());
}

int ModelBuilder::writtenNode(int reference) const {
    if (reference >= 0)
        return static_cast<std::size_t>(reference) < nodeIndex_.size() ? nodeIndex_[static_cast<std::size_t>(reference)] : -1;
    const int kept = keptNodeIndex(reference);
    return reference <= -2 && static_cast<std::size_t>(kept) < keptNodeIndex_.size()
               ? keptNodeIndex_[static_cast<std::size_t>(kept)]
               : -1;
}

// Kept nodes form trees of their own (the loader's): children in range, each node reached once
// from the kept nodes without a parent.
void ModelBuilder::checkKeptNodes() const {
    const std::size_t count = scene_.keptNodes.size();
    std::vector<int> parent(count, -1);
    for (std::size_t i = 0; i < count; ++i) {
        const Node& node = scene_.keptNodes[i];
        const std::string what = named("kept node", i, node.name);
        for (int child : node.children) {
            if (child < 0 || static_cast<std::size_t>(child) >= count)
                fail(what + " has child " + std::to_string(child) + ", which does not exist (there are " +
                     std::to_string(count) + " kept nodes)");
            if (parent[static_cast<std::size_t>(child)] >= 0 || static_cast<std::size_t>(child) == i)
                fail(named("kept node", static_cast<std::size_t>(child), scene_.keptNodes[static_cast<std::size_t>(child)].name) +
                     " has two parents or is its own child");
            parent[static_cast<std::size_t>(child)] = static_cast<int>(i);
        }
        checkIndex(node.mesh, scene_.meshes.size(), what, "mesh");
        checkIndex(node.light, scene_.lights.size(), what, "light");
        checkIndex(node.camera, scene_.cameras.size(), what, "camera");
        checkIndex(node.skin, scene_.skins.size(), what, "skin");
    }
    std::vector<std::uint8_t> reached(count, 0);
    std::vector<std::size_t> stack;
    for (std::size_t i = 0; i < count; ++i)
        if (parent[i] < 0) stack.push_back(i);
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        reached[i] = 1;
        for (int child : scene_.keptNodes[i].children) stack.push_back(static_cast<std::size_t>(child));
    }
    for (std::size_t i = 0; i < count; ++i)
        if (!reached[i]) fail(named("kept node", i, scene_.keptNodes[i].name) + " is part of a cycle");
}

void ModelBuilder::checkIndex(int index, std::size_t count, const std::string& what, const char* kind) const {
    if (index < -1 || index >= static_cast<int>(count))
        fail(what + " refers to " + kind + " " + std::to_string(index) + ", which does not exist (the scene has " +
             std::to_string(count) + ")");
}

void ModelBuilder::checkFinite(float value, const std::string& what) const {
    if (!std::isfinite(value)) fail(what + " is not a finite number");
}

// Everything the file will refer to must exist, and every number must be writable as JSON.
void ModelBuilder::checkScene() const {
    for (std::size_t i = 0; i < scene_.nodes.size(); ++i) {
        const Node& node = scene_.nodes[i];
        const std::string what = named("node", i, node.name);
        for (int child : node.children)
            if (child < 0 || child >= static_cast<int>(scene_.nodes.size()))
                fail(what + " has child " + std::to_string(child) + ", which does not exist (the scene has " +
                     std::to_string(scene_.nodes.size()) + " nodes)");
        checkIndex(node.mesh, scene_.meshes.size(), what, "mesh");
        checkIndex(node.light, scene_.lights.size(), what, "light");
        checkIndex(node.camera, scene_.cameras.size(), what, "camera");
        checkIndex(node.skin, scene_.skins.size(), what, "skin");
        checkFinite(node.translation, what + "'s translation");
        checkFinite(glm::vec4(node.rotation.x, node.rotation.y, node.rotation.z, node.rotation.w), what + "'s rotation");
        checkFinite(node.scale, what + "'s scale");
        if (glm::length(node.rotation) < 1e-6f) fail(what + "'s rotation is a zero quaternion");
    }
    checkKeptNodes();
    for (int root : scene_.roots)
        if (root < 0 || root >= static_cast<int>(scene_.nodes.size()))
            fail("root " + std::to_string(root) + " does not exist (the scene has " +
                 std::to_string(scene_.nodes.size()) + " nodes)");
    for (std::size_t m = 0; m < scene_.meshes.size(); ++m)
        for (std::size_t p = 0; p < scene_.meshes[m].primitives.size(); ++p) {
            const Primitive& primitive = scene_.meshes[m].primitives[p];
            const std::string what = "mesh '" + scene_.meshes[m].name + "' primitive " + std::to_string(p);
            checkIndex(primitive.material, scene_.materials.size(), what, "material");
            if (primitive.indices.size() % 3 != 0)
                fail(what + " has " + std::to_string(primitive.indices.size()) + " indices, not a multiple of 3");
            for (std::uint32_t index : primitive.indices)
                if (index >= primitive.vertices.size())
                    fail(what + " has the index " + std::to_string(index) + ", which is out of range (" +
                         std::to_string(primitive.vertices.size()) + " vertices)");
            for (const Vertex& v : primitive.vertices) {
                checkFinite(v.position, what + ": a vertex position");
                checkFinite(v.normal, what + ": a vertex normal");
                checkFinite(v.uv, what + ": a vertex texture coordinate");
                checkFinite(v.tangent, what + ": a vertex tangent");
            }
        }
    for (std::size_t m = 0; m < scene_.materials.size(); ++m) {
        const Material& material = scene_.materials[m];
        const std::string what = named("material", m, material.name);
        for (int texture : {material.baseColorTexture, material.metallicRoughnessTexture, material.normalTexture,
                            material.emissiveTexture, material.occlusionTexture})
            checkIndex(texture, scene_.textures.size(), what, "texture");
        checkFinite(material.baseColorFactor, what + "'s baseColorFactor");
        checkFinite(material.metallic, what + "'s metallic factor");
        checkFinite(material.roughness, what + "'s roughness factor");
        checkFinite(material.normalScale, what + "'s normalScale");
        checkFinite(material.emissiveFactor, what + "'s emissiveFactor");
        checkFinite(material.emissiveStrength, what + "'s emissiveStrength");
        checkFinite(material.occlusionStrength, what + "'s occlusionStrength");
        checkFinite(material.alphaCutoff, what + "'s alphaCutoff");
    }
    for (std::size_t t = 0; t < scene_.textures.size(); ++t)
        checkIndex(scene_.textures[t].image, scene_.images.size(), "texture " + std::to_string(t), "image");
    for (std::size_t l = 0; l < scene_.lights.size(); ++l) {
        const Light& light = scene_.lights[l];
        const std::string what = named("light", l, light.name);
        checkFinite(light.color, what + "'s colour");
        checkFinite(light.intensity, what + "'s intensity");
        checkFinite(light.range, what + "'s range");
        checkFinite(light.innerConeAngle, what + "'s innerConeAngle");
        checkFinite(light.outerConeAngle, what + "'s outerConeAngle");
    }
    for (std::size_t c = 0; c < scene_.cameras.size(); ++c) {
        const Camera& camera = scene_.cameras[c];
        const std::string what = named("camera", c, camera.name);
        checkFinite(camera.aspectRatio, what + "'s aspectRatio");
        checkFinite(camera.zfar, what + "'s zfar");
        if (!(camera.yfov > 0.0f && std::isfinite(camera.yfov)))
            fail(what + " has yfov " + std::to_string(camera.yfov) + "; glTF needs a positive field of view");
        if (!(camera.znear > 0.0f && std::isfinite(camera.znear)))
            fail(what + " has znear " + std::to_string(camera.znear) + "; glTF needs a positive near plane");
    }
}

// The nodes reachable from the roots, in index order. A node reached twice (a cycle, or two
// parents) cannot be written as a glTF tree.
std::vector<int> ModelBuilder::reachableNodes() const {
    std::vector<std::uint8_t> reached(scene_.nodes.size(), 0);
    std::vector<int> stack;
    for (int root : scene_.roots)
        if (std::find(stack.begin(), stack.end(), root) == stack.end()) stack.push_back(root);
    while (!stack.empty()) {
        const int index = stack.back();
        stack.pop_back();
        if (reached[static_cast<std::size_t>(index)])
            fail(named("node", static_cast<std::size_t>(index), scene_.nodes[static_cast<std::size_t>(index)].name) +
                 " is reached twice from the roots (a cycle, or a node with two parents)");
        reached[static_cast<std::size_t>(index)] = 1;
        for (int child : scene_.nodes[static_cast<std::size_t>(index)].children) stack.push_back(child);
    }
    std::vector<int> out;
    for (std::size_t i = 0; i < reached.size(); ++i)
        if (reached[i]) out.push_back(static_cast<int>(i));
    return out;
}

int ModelBuilder::addBufferView(const void* data, std::size_t bytes, int target, std::size_t stride) {
    if (model_.buffers.empty()) model_.buffers.emplace_back();
    std::vector<unsigned char>& bin = model_.buffers[0].data;
    bin.resize((bin.size() + 3) & ~std::size_t(3), 0);  // every view starts 4-byte aligned
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bin.size();
    view.byteLength = bytes;
    view.byteStride = stride;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    bin.insert(bin.end(), p, p + bytes);
    model_.bufferViews.push_back(std::move(view));
    return static_cast<int>(model_.bufferViews.size()) - 1;
}

int ModelBuilder::addAccessor(int view, std::size_t byteOffset, int componentType, int type, std::size_t count) {
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.byteOffset = byteOffset;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    model_.accessors.push_back(std::move(accessor));
    return static_cast<int>(model_.accessors.size()) - 1;
}

int typeCode(const std::string& type) {
    static const std::map<std::string, int> codes = {
        {"SCALAR", TINYGLTF_TYPE_SCALAR}, {"VEC2", TINYGLTF_TYPE_VEC2}, {"VEC3", TINYGLTF_TYPE_VEC3},
        {"VEC4", TINYGLTF_TYPE_VEC4},     {"MAT2", TINYGLTF_TYPE_MAT2}, {"MAT3", TINYGLTF_TYPE_MAT3},
        {"MAT4", TINYGLTF_TYPE_MAT4}};
    const auto it = codes.find(type);
    return it == codes.end() ? -1 : it->second;
}

int ModelBuilder::addKeptAccessor(const KeptAccessor& kept, int target) {
    const int type = typeCode(kept.type);
    if (type < 0 || kept.count == 0 || kept.bytes.size() % kept.count != 0)
        fail("kept accessor data of type '" + kept.type + "' is inconsistent (" + std::to_string(kept.bytes.size()) +
             " bytes for " + std::to_string(kept.count) + " elements)");
    const std::size_t elementSize = kept.bytes.size() / kept.count;
    const KeptAccessor::Sparse* sparse = kept.sparse ? &*kept.sparse : nullptr;
    const int indexSize = sparse ? (sparse->indexComponentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                                    : sparse->indexComponentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                    : sparse->indexComponentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                                           : 0)
                                 : 0;
    if (sparse && (indexSize == 0 || sparse->indices.empty() ||
                   (sparse->hasBase && sparse->baseBytes.size() != sparse->indices.size() * elementSize) ||
                   std::any_of(sparse->indices.begin(), sparse->indices.end(), [&](std::uint32_t i) {
                       return i >= kept.count || (indexSize < 4 && i >= (1u << (8 * indexSize)));
                   })))
        sparse = nullptr;  // inconsistent (edited): written dense, which holds the same values
    // The dense part: all elements, or for a sparse accessor its base (the file's base elements
    // put back where the sparse values replaced them), or nothing when the base was zeros.
    std::vector<std::uint8_t> base;
    const std::vector<std::uint8_t>* dense = &kept.bytes;
    if (sparse && sparse->hasBase) {
        base = kept.bytes;
        for (std::size_t s = 0; s < sparse->indices.size(); ++s)
            std::memcpy(base.data() + sparse->indices[s] * elementSize, sparse->baseBytes.data() + s * elementSize, elementSize);
        dense = &base;
    }
    const std::size_t stride = target == kArrayBuffer ? (elementSize + 3) & ~std::size_t(3) : elementSize;
    int view = -1;
    if (sparse && !sparse->hasBase) {
        view = -1;  // no buffer view: zeros (glTF §3.6.2.3)
    } else if (stride == elementSize) {
        view = addBufferView(dense->data(), dense->size(), target, target == kArrayBuffer ? stride : 0);
    } else {  // e.g. a normalized UNSIGNED_BYTE VEC3 colour: 3 bytes every 4
        std::vector<std::uint8_t> padded(kept.count * stride, 0);
        for (std::size_t i = 0; i < kept.count; ++i)
            std::memcpy(padded.data() + i * stride, dense->data() + i * elementSize, elementSize);
        view = addBufferView(padded.data(), padded.size(), target, stride);
    }
    const int accessor = addAccessor(view, 0, kept.componentType, type, kept.count);
    model_.accessors[static_cast<std::size_t>(accessor)].normalized = kept.normalized;
    if (sparse) {
        // Indices in their own component type, values tightly packed; views without a target
        // (glTF: sparse data is not bound as a vertex or index buffer).
        std::vector<std::uint8_t> indices(sparse->indices.size() * static_cast<std::size_t>(indexSize));
        std::vector<std::uint8_t> values(sparse->indices.size() * elementSize);
        for (std::size_t s = 0; s < sparse->indices.size(); ++s) {
            const std::uint32_t index = sparse->indices[s];
            std::memcpy(indices.data() + s * static_cast<std::size_t>(indexSize), &index, static_cast<std::size_t>(indexSize));  // little-endian
            std::memcpy(values.data() + s * elementSize, kept.bytes.data() + index * elementSize, elementSize);
        }
        const int indexView = addBufferView(indices.data(), indices.size(), 0, 0);
        const int valueView = addBufferView(values.data(), values.size(), 0, 0);
        tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(accessor)];
        a.sparse.isSparse = true;
        a.sparse.count = static_cast<int>(sparse->indices.size());
        a.sparse.indices.bufferView = indexView;
        a.sparse.indices.byteOffset = 0;
        a.sparse.indices.componentType = sparse->indexComponentType;
        a.sparse.values.bufferView = valueView;
        a.sparse.values.byteOffset = 0;
        keepView(indexView, sparse->indicesView);
        keepView(valueView, sparse->valuesView);
    }
    keepAccessor(accessor, kept.info);
    return accessor;
}

void ModelBuilder::addTargets(const std::vector<KeptAttributes>& targets, std::size_t vertexCount,
                              tinygltf::Primitive& primitive) {
    // All or none: a mesh's weights count the targets. None when the geometry was rebuilt.
    for (const KeptAttributes& target : targets)
        for (const auto& [name, accessor] : target)
            if (accessor.count != vertexCount) return;
    for (const KeptAttributes& target : targets) {
        std::map<std::string, int> attributes;
        addKeptAttributes(target, vertexCount, attributes);
        primitive.targets.push_back(std::move(attributes));
    }
}

bool ModelBuilder::addKeptAttributes(const KeptAttributes& kept, std::size_t vertexCount,
                                     std::map<std::string, int>& attributes) {
    bool all = true;
    for (const auto& [name, accessor] : kept) {
        if (accessor.count != vertexCount) {
            all = false;
            continue;
        }
        const int index = addKeptAccessor(accessor, kArrayBuffer);
        // glTF requires min and max on POSITION accessors, morph targets' included.
        if (name == "POSITION" && accessor.type == "VEC3" && accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
            std::vector<double> lo(3, std::numeric_limits<double>::max()), hi(3, std::numeric_limits<double>::lowest());
            for (std::size_t i = 0; i < accessor.count; ++i)
                for (std::size_t c = 0; c < 3; ++c) {
                    float v;
                    std::memcpy(&v, accessor.bytes.data() + (i * 3 + c) * sizeof(float), sizeof(float));
                    lo[c] = std::min(lo[c], double(v));
                    hi[c] = std::max(hi[c], double(v));
                }
            model_.accessors[static_cast<std::size_t>(index)].minValues = lo;
            model_.accessors[static_cast<std::size_t>(index)].maxValues = hi;
        }
        attributes[name] = index;
        wroteKeptVertexData_ = true;
    }
    return all;
}

// The image's file as seen from the new file's folder, when the image came from a file that
// still exists.
std::optional<std::string> ModelBuilder::relativeUri(const Image& image) const {
    if (image.uri.empty() || isDataUri(image.uri) || scene_.sourcePath.empty()) return std::nullopt;
    std::error_code ec;
    const fs::path source = fs::absolute(scene_.sourcePath.parent_path() / percentDecode(image.uri), ec);
    if (ec || !fs::is_regular_file(source, ec)) return std::nullopt;
    const fs::path from = fs::weakly_canonical(fs::absolute(file_, ec).parent_path(), ec);
    if (ec) return std::nullopt;
    const fs::path to = fs::weakly_canonical(source, ec);
    if (ec) return std::nullopt;
    const fs::path relative = to.lexically_relative(from);
    if (relative.empty()) return std::nullopt;
    return percentEncodePath(relative.generic_string());
}

void ModelBuilder::addImages() {
    imageIndex_.assign(scene_.images.size(), -1);
    for (std::size_t i = 0; i < scene_.images.size(); ++i) {
        const Image& image = scene_.images[i];
        if (image.generated) continue;
        tinygltf::Image out;
        out.name = image.name;
        if (const std::optional<std::string> uri = relativeUri(image)) {
            out.uri = *uri;
        } else if (!image.encoded.empty()) {  // the file's own bytes: not re-encoded (16-bit PNG, KTX2, JPEG)
            out.bufferView = addBufferView(image.encoded.data(), image.encoded.size(), 0, 0);
            out.mimeType = image.mimeType.empty() ? "application/octet-stream" : image.mimeType;
        } else {
            std::vector<std::uint8_t> png;
            try {
                png = encodePng(image.width, image.height, image.rgba, /*flipVertically=*/false);  // rows are top-down
            } catch (const std::exception& e) {
                fail(named("image", i, image.name) + " cannot be embedded: " + e.what());
            }
            out.bufferView = addBufferView(png.data(), png.size(), 0, 0);
            out.mimeType = "image/png";
        }
        keepView(out.bufferView, image.view);
        restore(image.kept, out.extras, out.extensions);
        imageIndex_[i] = static_cast<int>(model_.images.size());
        model_.images.push_back(std::move(out));
    }
}

void ModelBuilder::addTextures() {
    // One glTF sampler per distinct setting (name, extras and extensions included).
    using SamplerKey = std::tuple<std::array<int, 4>, std::string, std::string, std::string>;
    std::map<SamplerKey, int> samplers;
    for (const Texture& texture : scene_.textures) {
        const SamplerKey key = {{texture.wrapS, texture.wrapT, texture.minFilter, texture.magFilter},
                                texture.samplerName, texture.samplerKept.extras, texture.samplerKept.extensions};
        auto [it, added] = samplers.emplace(key, static_cast<int>(model_.samplers.size()));
        if (added) {
            tinygltf::Sampler sampler;
            sampler.wrapS = texture.wrapS;
            sampler.wrapT = texture.wrapT;
            sampler.minFilter = texture.minFilter;
            sampler.magFilter = texture.magFilter;
            tinygltf::ExtensionMap extensions;
            restore(texture.samplerKept, sampler.extras, extensions);
            // tinygltf 2.7 writes neither a sampler's name nor its extensions: set them in the JSON.
            const std::string at = "/samplers/" + std::to_string(model_.samplers.size());
            if (!texture.samplerName.empty())
                jsonPatches_.emplace_back(at + "/name", nlohmann::json(texture.samplerName).dump());
            if (!texture.samplerKept.extensions.empty())
                jsonPatches_.emplace_back(at + "/extensions", texture.samplerKept.extensions);
            model_.samplers.push_back(sampler);
        }
        tinygltf::Texture out;
        out.name = texture.name;
        out.source = texture.image >= 0 && static_cast<std::size_t>(texture.image) < imageIndex_.size()
                         ? imageIndex_[static_cast<std::size_t>(texture.image)]
                         : -1;
        out.sampler = it->second;
        restore(texture.kept, out.extras, out.extensions);
        model_.textures.push_back(std::move(out));
    }
}

void ModelBuilder::addMaterials() {
    for (const Material& material : scene_.materials) {
        tinygltf::Material out;
        out.name = material.name;
        tinygltf::PbrMetallicRoughness& pbr = out.pbrMetallicRoughness;
        pbr.baseColorFactor = doubles(material.baseColorFactor);
        pbr.baseColorTexture.index = material.baseColorTexture;
        pbr.baseColorTexture.texCoord = material.textureTexCoord[0];
        pbr.metallicFactor = material.metallic;
        pbr.roughnessFactor = material.roughness;
        pbr.metallicRoughnessTexture.index = material.metallicRoughnessTexture;
        pbr.metallicRoughnessTexture.texCoord = material.textureTexCoord[1];
        out.normalTexture.texCoord = material.textureTexCoord[2];
        out.emissiveTexture.texCoord = material.textureTexCoord[3];
        out.occlusionTexture.texCoord = material.textureTexCoord[4];
        out.normalTexture.index = material.normalTexture;
        out.normalTexture.scale = material.normalScale;
        out.occlusionTexture.index = material.occlusionTexture;
        out.occlusionTexture.strength = material.occlusionStrength;
        out.emissiveTexture.index = material.emissiveTexture;
        out.emissiveFactor = doubles(material.emissiveFactor);
        if (material.emissiveStrength != 1.0f) {
            tinygltf::Value::Object extension;
            extension["emissiveStrength"] = tinygltf::Value(static_cast<double>(material.emissiveStrength));
            out.extensions[kEmissiveStrengthExtension] = tinygltf::Value(std::move(extension));
            useExtension(kEmissiveStrengthExtension);
        }
        switch (material.alphaMode) {
            case AlphaMode::Opaque:
                out.alphaMode = "OPAQUE";
                break;
            case AlphaMode::Mask:
                out.alphaMode = "MASK";
                break;
            case AlphaMode::Blend:
                out.alphaMode = "BLEND";
                break;
        }
        out.alphaCutoff = material.alphaCutoff;
        out.doubleSided = material.doubleSided;
        restore(material.kept, out.extras, out.extensions);
        const auto& extras = material.textureExtras;
        const auto& extensions = material.textureExtensions;
        restoreTextureInfo(extras[0], extensions[0], pbr.baseColorTexture.extras, pbr.baseColorTexture.extensions);
        restoreTextureInfo(extras[1], extensions[1], pbr.metallicRoughnessTexture.extras, pbr.metallicRoughnessTexture.extensions);
        restoreTextureInfo(extras[2], extensions[2], out.normalTexture.extras, out.normalTexture.extensions);
        restoreTextureInfo(extras[3], extensions[3], out.emissiveTexture.extras, out.emissiveTexture.extensions);
        restoreTextureInfo(extras[4], extensions[4], out.occlusionTexture.extras, out.occlusionTexture.extensions);
        restore(material.pbrKept, pbr.extras, pbr.extensions);
        model_.materials.push_back(std::move(out));
    }
}

void ModelBuilder::addMeshes() {
    static_assert(offsetof(Vertex, position) == 0 && offsetof(Vertex, normal) == 12 && offsetof(Vertex, uv) == 24 &&
                      offsetof(Vertex, tangent) == 32,
                  "the interleaved vertex view below mirrors lit::Vertex");
    meshIndex_.assign(scene_.meshes.size(), -1);
    for (std::size_t m = 0; m < scene_.meshes.size(); ++m) {
        const Mesh& mesh = scene_.meshes[m];
        tinygltf::Mesh out;
        out.name = mesh.name;
        for (const Primitive& primitive : mesh.primitives) {
            if (primitive.indices.empty()) continue;
            const std::size_t count = primitive.vertices.size();
            // Tangents only when the file had them (the loader generates them otherwise): without
            // them the vertices are written 32 bytes apart (POSITION, NORMAL, TEXCOORD_0).
            const bool tangents = primitive.fileHasTangents;
            constexpr std::size_t kPackedStride = offsetof(Vertex, tangent);
            int vertices = -1;
            if (tangents) {
                vertices = addBufferView(primitive.vertices.data(), count * sizeof(Vertex), kArrayBuffer, sizeof(Vertex));
            } else {
                std::vector<unsigned char> packed(count * kPackedStride);
                for (std::size_t v = 0; v < count; ++v)
                    std::memcpy(packed.data() + v * kPackedStride, &primitive.vertices[v], kPackedStride);
                vertices = addBufferView(packed.data(), packed.size(), kArrayBuffer, kPackedStride);
            }
            tinygltf::Primitive p;
            p.mode = TINYGLTF_MODE_TRIANGLES;
            p.material = primitive.material;
            const int position = addAccessor(vertices, offsetof(Vertex, position), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                             TINYGLTF_TYPE_VEC3, count);
            glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
            for (const Vertex& v : primitive.vertices) {
                lo = glm::min(lo, v.position);
                hi = glm::max(hi, v.position);
            }
            model_.accessors[static_cast<std::size_t>(position)].minValues = doubles(lo);
            model_.accessors[static_cast<std::size_t>(position)].maxValues = doubles(hi);
            p.attributes["POSITION"] = position;
            p.attributes["NORMAL"] = addAccessor(vertices, offsetof(Vertex, normal), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                 TINYGLTF_TYPE_VEC3, count);
            p.attributes["TEXCOORD_0"] =
                addAccessor(vertices, offsetof(Vertex, uv), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, count);
            if (tangents)
                p.attributes["TANGENT"] = addAccessor(vertices, offsetof(Vertex, tangent), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                      TINYGLTF_TYPE_VEC4, count);
            addKeptAttributes(primitive.keptAttributes, count, p.attributes);
            addTargets(primitive.morphTargets, count, p);
            restore(primitive.kept, p.extras, p.extensions);
            const int indices = addBufferView(primitive.indices.data(), primitive.indices.size() * sizeof(std::uint32_t),
                                              kElementArrayBuffer, 0);
            p.indices = addAccessor(indices, 0, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                    primitive.indices.size());
            out.primitives.push_back(std::move(p));
        }
        for (const KeptPrimitive& kept : mesh.otherPrimitives) {
            const auto position = kept.attributes.find("POSITION");
            if (position == kept.attributes.end()) continue;  // the loader keeps none without
            tinygltf::Primitive p;
            p.mode = kept.mode;
            p.material = kept.material < static_cast<int>(scene_.materials.size()) ? kept.material : -1;
            addKeptAttributes(kept.attributes, position->second.count, p.attributes);
            addTargets(kept.morphTargets, position->second.count, p);
            if (kept.indices && kept.indices->count > 0) p.indices = addKeptAccessor(*kept.indices, kElementArrayBuffer);
            restore(kept.kept, p.extras, p.extensions);
            out.primitives.push_back(std::move(p));
        }
        if (out.primitives.empty()) continue;  // glTF requires at least one primitive per mesh
        // Default morph weights, while every primitive still has that many targets (glTF rule).
        if (!mesh.weights.empty() && std::all_of(out.primitives.begin(), out.primitives.end(), [&](const tinygltf::Primitive& p) {
                return p.targets.size() == mesh.weights.size();
            }))
            out.weights = mesh.weights;
        restore(mesh.kept, out.extras, out.extensions);
        meshIndex_[m] = static_cast<int>(model_.meshes.size());
        model_.meshes.push_back(std::move(out));
    }
}

void ModelBuilder::addLights() {
    for (const Light& light : scene_.lights) {
        tinygltf::Light out;
        out.name = light.name;
        out.color = fileOr(light.fileNumbers, "color", light.color);
        // Back to the file's photometric units (cd, lx); an unedited light keeps its exact number.
        out.intensity = light.intensity == light.fileIntensityAsLoaded ? light.fileIntensity
                                                                       : photometricFromRadiometric(light.intensity);
        out.range = fileOr(light.fileNumbers, "range", std::max(light.range, 0.0f));  // written only when > 0 (0 = infinite)
        switch (light.type) {
            case LightType::Directional:
                out.type = "directional";
                break;
            case LightType::Point:
                out.type = "point";
                break;
            case LightType::Spot:
                out.type = "spot";
                out.spot.innerConeAngle = fileOr(light.fileNumbers, "innerConeAngle", light.innerConeAngle);
                out.spot.outerConeAngle = fileOr(light.fileNumbers, "outerConeAngle", light.outerConeAngle);
                break;
        }
        if (!light.castsShadow) {
            tinygltf::Value::Object extras;
            extras[kCastsShadowKey] = tinygltf::Value(false);
            out.extras = tinygltf::Value(std::move(extras));
        }
        restore(light.kept, out.extras, out.extensions);
        model_.lights.push_back(std::move(out));
    }
    if (!model_.lights.empty()) useExtension(kLightsExtension);
}

void ModelBuilder::addCameras() {
    for (const Camera& camera : scene_.cameras) {
        tinygltf::Camera out;
        out.name = camera.name;
        if (camera.orthographic && camera.xmag != 0.0f && camera.ymag != 0.0f && camera.zfar > camera.znear) {
            out.type = "orthographic";  // as the file had it (Lit draws it in perspective)
            const FileNumbers& n = camera.fileNumbers;
            out.orthographic.xmag = fileOr(n, "xmag", camera.xmag);
            out.orthographic.ymag = fileOr(n, "ymag", camera.ymag);
            out.orthographic.znear = fileOr(n, "znear", camera.znear);
            out.orthographic.zfar = fileOr(n, "zfar", camera.zfar);
        } else {
            out.type = "perspective";
            const FileNumbers& n = camera.fileNumbers;
            out.perspective.yfov = fileOr(n, "yfov", camera.yfov);
            out.perspective.znear = fileOr(n, "znear", camera.znear);
            out.perspective.zfar = fileOr(n, "zfar", std::max(camera.zfar, 0.0f));  // 0: left out by writeGltfModel
            out.perspective.aspectRatio = fileOr(n, "aspectRatio", std::max(camera.aspectRatio, 0.0f));  // 0: left out
        }
        restore(camera.kept, out.extras, out.extensions);
        model_.cameras.push_back(std::move(out));
    }
}

void ModelBuilder::addNodes() {
    const std::vector<int> written = reachableNodes();
    nodeIndex_.assign(scene_.nodes.size(), -1);
    for (std::size_t i = 0; i < written.size(); ++i) nodeIndex_[static_cast<std::size_t>(written[i])] = static_cast<int>(i);
    keptNodeIndex_.resize(scene_.keptNodes.size());
    for (std::size_t k = 0; k < scene_.keptNodes.size(); ++k) keptNodeIndex_[k] = static_cast<int>(written.size() + k);
    addSkins();
    const auto addNode = [&](const Node& node, const std::vector<int>& childIndex) {
        tinygltf::Node out;
        out.name = node.name;
        for (int child : node.children) out.children.push_back(childIndex[static_cast<std::size_t>(child)]);
        // Only what differs from the glTF defaults, as other exporters do.
        if (node.translation != glm::vec3(0.0f)) out.translation = fileOr(node.fileNumbers, "t", node.translation);
        if (node.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
            // A rotation already unit within float rounding is written as it is (the file's
            // numbers after a load), others normalized.
            const float length = glm::length(node.rotation);
            const glm::quat q = std::abs(length - 1.0f) <= 1e-6f ? node.rotation : node.rotation / length;
            out.rotation = fileOr(node.fileNumbers, "r", glm::vec4(q.x, q.y, q.z, q.w));  // glTF order
        }
        if (node.scale != glm::vec3(1.0f)) out.scale = fileOr(node.fileNumbers, "s", node.scale);
        out.mesh = node.mesh >= 0 ? meshIndex_[static_cast<std::size_t>(node.mesh)] : -1;
        out.camera = node.camera;
        out.skin = node.skin >= 0 ? skinIndex_[static_cast<std::size_t>(node.skin)] : -1;
        out.weights = node.weights;
        if (node.light >= 0) {
            tinygltf::Value::Object extension;
            extension["light"] = tinygltf::Value(node.light);
            out.extensions[kLightsExtension] = tinygltf::Value(std::move(extension));
        }
        restore(node.kept, out.extras, out.extensions);
        model_.nodes.push_back(std::move(out));
    };
    for (int index : written) addNode(scene_.nodes[static_cast<std::size_t>(index)], nodeIndex_);
    for (const Node& node : scene_.keptNodes) addNode(node, keptNodeIndex_);
    const auto sceneOf = [&](const std::string& name, const std::vector<int>& roots, const KeptGltf& kept) {
        tinygltf::Scene out;
        out.name = name;
        for (int reference : roots) {
            const int mapped = writtenNode(reference);
            if (mapped < 0) continue;
            // A node another scene shares may have been deleted or re-parented under a node.
            const Node& node = reference >= 0 ? scene_.nodes[static_cast<std::size_t>(reference)]
                                              : scene_.keptNodes[static_cast<std::size_t>(keptNodeIndex(reference))];
            if (node.parent >= 0) continue;
            if (std::find(out.nodes.begin(), out.nodes.end(), mapped) == out.nodes.end()) out.nodes.push_back(mapped);
        }
        restore(kept, out.extras, out.extensions);
        return out;
    };
    // The file's scenes in their order, the shown one where it was.
    const std::size_t shown = std::min(static_cast<std::size_t>(std::max(scene_.sceneIndex, 0)), scene_.otherScenes.size());
    for (std::size_t i = 0; i < scene_.otherScenes.size(); ++i) {
        if (i == shown) model_.scenes.push_back(sceneOf(scene_.name, scene_.roots, scene_.kept));
        const Scene::OtherScene& other = scene_.otherScenes[i];
        model_.scenes.push_back(sceneOf(other.name, other.roots, other.kept));
    }
    if (shown == scene_.otherScenes.size()) model_.scenes.push_back(sceneOf(scene_.name, scene_.roots, scene_.kept));
    model_.defaultScene = static_cast<int>(shown);
}

// The skins whose joints are all written (a deleted joint leaves its skin out, and the skinned
// nodes are written without one).
void ModelBuilder::addSkins() {
    skinIndex_.assign(scene_.skins.size(), -1);
    const auto written = [&](int reference) { return writtenNode(reference); };
    for (std::size_t s = 0; s < scene_.skins.size(); ++s) {
        const Skin& skin = scene_.skins[s];
        if (skin.joints.empty() ||
            std::any_of(skin.joints.begin(), skin.joints.end(), [&](int joint) { return written(joint) < 0; }) ||
            (!skin.inverseBindMatrices.empty() && skin.inverseBindMatrices.size() != 16 * skin.joints.size()))
            continue;
        tinygltf::Skin out;
        out.name = skin.name;
        for (int joint : skin.joints) out.joints.push_back(written(joint));
        out.skeleton = written(skin.skeleton);
        if (!skin.inverseBindMatrices.empty()) {
            KeptAccessor matrices;
            matrices.type = "MAT4";
            matrices.count = skin.joints.size();
            matrices.bytes.resize(skin.inverseBindMatrices.size() * sizeof(float));
            std::memcpy(matrices.bytes.data(), skin.inverseBindMatrices.data(), matrices.bytes.size());
            matrices.info = skin.inverseBindMatricesInfo;
            out.inverseBindMatrices = addKeptAccessor(matrices, 0);
        }
        restore(skin.kept, out.extras, out.extensions);
        skinIndex_[s] = static_cast<int>(model_.skins.size());
        model_.skins.push_back(std::move(out));
    }
}

// The file's animations as the loader kept them (channels of nodes that are not written are
// dropped, and animations left with none). Float accessors; inputs carry min/max as glTF requires.
void ModelBuilder::addAnimations() {
    for (const Animation& animation : scene_.animations) {
        if (!replacedAnimation_.empty() && animation.name == replacedAnimation_) continue;
        const bool valid = std::all_of(animation.samplers.begin(), animation.samplers.end(), [](const Animation::Sampler& s) {
            return s.components >= 1 && s.components <= 4 && !s.input.empty() &&
                   s.output.size() % static_cast<std::size_t>(s.components) == 0;
        });
        if (!valid) continue;
        tinygltf::Animation out;
        out.name = animation.name;
        for (const Animation::Channel& channel : animation.channels) {
            const int node = writtenNode(channel.node);
            if (node < 0 || channel.sampler < 0 || static_cast<std::size_t>(channel.sampler) >= animation.samplers.size())
                continue;
            tinygltf::AnimationChannel c;
            c.sampler = channel.sampler;
            c.target_node = node;
            c.target_path = channel.path;
            restore(channel.kept, c.extras, c.extensions);
            out.channels.push_back(std::move(c));
        }
        if (out.channels.empty()) continue;
        const std::string at = "/animations/" + std::to_string(model_.animations.size()) + "/samplers/";
        for (const Animation::Sampler& sampler : animation.samplers) {
            const int typeOf[] = {0, TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4};
            const int inputView = addBufferView(sampler.input.data(), sampler.input.size() * sizeof(float), 0, 0);
            const int input = addAccessor(inputView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR,
                                          sampler.input.size());
            const auto [lo, hi] = std::minmax_element(sampler.input.begin(), sampler.input.end());
            model_.accessors[static_cast<std::size_t>(input)].minValues = {*lo};
            model_.accessors[static_cast<std::size_t>(input)].maxValues = {*hi};
            const int outputView = addBufferView(sampler.output.data(), sampler.output.size() * sizeof(float), 0, 0);
            const int output = addAccessor(outputView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, typeOf[sampler.components],
                                           sampler.output.size() / static_cast<std::size_t>(sampler.components));
            keepAccessor(input, sampler.inputInfo);
            keepAccessor(output, sampler.outputInfo);
            tinygltf::AnimationSampler s;
            s.input = input;
            s.output = output;
            s.interpolation = sampler.interpolation;
            tinygltf::ExtensionMap extensions;
            restore(sampler.kept, s.extras, extensions);
            // tinygltf 2.7 writes no animation sampler extensions: set them in the JSON.
            if (!sampler.kept.extensions.empty())
                jsonPatches_.emplace_back(at + std::to_string(out.samplers.size()) + "/extensions", sampler.kept.extensions);
            out.samplers.push_back(std::move(s));
        }
        restore(animation.kept, out.extras, out.extensions);
        model_.animations.push_back(std::move(out));
    }
}

void ModelBuilder::useExtension(const std::string& name) {
    if (std::find(model_.extensionsUsed.begin(), model_.extensionsUsed.end(), name) == model_.extensionsUsed.end())
        model_.extensionsUsed.push_back(name);
}

tinygltf::Model ModelBuilder::build() {
    checkScene();
    model_.asset.version = "2.0";
    model_.asset.generator = kGenerator;
    addImages();
    addTextures();
    addMaterials();
    addMeshes();
    addLights();
    addCameras();
    addNodes();
    addAnimations();
    keepBuffers();
    model_.asset.copyright = scene_.copyright;
    {
        tinygltf::Value extras;
        if (!scene_.generator.empty() && scene_.generator != kGenerator) {
            tinygltf::Value::Object source;
            source[kSourceGeneratorKey] = tinygltf::Value(scene_.generator);
            extras = tinygltf::Value(std::move(source));
        }
        restore(scene_.assetKept, extras, model_.asset.extensions);
        // tinygltf writes asset extras only when they are an object (glTF's extras usually are).
        model_.asset.extras = std::move(extras);
    }
    restore(scene_.fileKept, model_.extras, model_.extensions);
    // Kept vertex data may be quantized (KHR_mesh_quantization's types); the extension is then
    // required, as its specification says.
    const bool quantized = std::find(scene_.unknownExtensionsUsed.begin(), scene_.unknownExtensionsUsed.end(),
                                     "KHR_mesh_quantization") != scene_.unknownExtensionsUsed.end();
    if (quantized && wroteKeptVertexData_) {
        useExtension("KHR_mesh_quantization");
        model_.extensionsRequired.push_back("KHR_mesh_quantization");
    }
    // What the file required stays required while the saved file uses it (Blender requires
    // KHR_lights_punctual of a file with lights).
    for (const std::string& e : scene_.extensionsRequired)
        if (std::find(model_.extensionsUsed.begin(), model_.extensionsUsed.end(), e) != model_.extensionsUsed.end() &&
            std::find(model_.extensionsRequired.begin(), model_.extensionsRequired.end(), e) == model_.extensionsRequired.end())
            model_.extensionsRequired.push_back(e);
    // Extensions the source declared that no kept data uses any more are not declared again
    // (the validator reports unused ones); those still used were declared by restore().
    return std::move(model_);
}

// Moves every buffer's bytes into buffer 0 (the camera path animation brings a buffer of its
// own), so the scene is one .bin or one BIN chunk.
void mergeBuffers(tinygltf::Model& model) {
    if (model.buffers.size() < 2) return;
    std::vector<unsigned char>& first = model.buffers[0].data;
    std::vector<std::size_t> offset(model.buffers.size(), 0);
    for (std::size_t i = 1; i < model.buffers.size(); ++i) {
        first.resize((first.size() + 3) & ~std::size_t(3), 0);
        offset[i] = first.size();
        first.insert(first.end(), model.buffers[i].data.begin(), model.buffers[i].data.end());
    }
    for (tinygltf::BufferView& view : model.bufferViews) {
        if (view.buffer <= 0) continue;
        view.byteOffset += offset[static_cast<std::size_t>(view.buffer)];
        view.buffer = 0;
    }
    model.buffers.resize(1);
}

}  // namespace

void saveGltf(const Scene& scene, const fs::path& file, const GltfSaveOptions& options) {
    const std::string extension = lowercase(file.extension().string());
    if (extension != ".gltf" && extension != ".glb")
        throw SceneSaveError(file.string() + ": cannot save as '" + file.extension().string() +
                             "'; the file name must end in .gltf or .glb");
    const bool binary = extension == ".glb";

    const bool ownPath = options.cameraPath && !options.cameraPath->empty();
    ModelBuilder builder(scene, file, ownPath ? options.cameraPathName : std::string());
    tinygltf::Model model = builder.build();
    const std::vector<std::pair<std::string, std::string>> jsonPatches = builder.takeJsonPatches();
    if (options.cameraPath && !options.cameraPath->empty()) {
        try {
            // The path animates a camera of the shown scene: the kept nodes (written after the
            // shown ones) are hidden from writeCameraPathAnimation's search for a camera node, so
            // without a shown camera it adds one rather than animate a node Lit does not show.
            const std::size_t shownNodes = model.nodes.size() - scene.keptNodes.size();
            std::vector<int> keptCameras;
            for (std::size_t i = shownNodes; i < model.nodes.size(); ++i)
                keptCameras.push_back(std::exchange(model.nodes[i].camera, -1));
            writeCameraPathAnimation(model, *options.cameraPath, options.cameraPathName);
            for (std::size_t i = 0; i < keptCameras.size(); ++i) model.nodes[shownNodes + i].camera = keptCameras[i];
        } catch (const CameraPathError& e) {
            throw SceneSaveError(file.string() + ": cannot write the camera path: " + e.what());
        }
    }
    mergeBuffers(model);
    if (!binary && !model.buffers.empty()) model.buffers[0].uri = percentEncodePath(file.stem().string() + ".bin");

    try {
        writeGltfModel(std::move(model), file, binary, options.alsoWrite, jsonPatches);
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        throw SceneSaveError(what.starts_with(file.string() + ": ") ? what : file.string() + ": " + what);
    }
}

}  // namespace lit
