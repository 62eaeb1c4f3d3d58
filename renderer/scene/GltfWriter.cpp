// glTF 2.0 export: Scene → tinygltf::Model → files (io/GltfFile.h writes them atomically).
//
// Decisions worth knowing:
// - All geometry and embedded images go into one buffer: "<stem>.bin" beside a .gltf, the BIN
//   chunk of a .glb. A view whose bytes the source file had goes back to the file's offset
//   (keepFileLayout); edited and new data fill the gaps or follow. A primitive's vertices are laid out in the file's views (scene/Scene.h:
//   Primitive::fileViews): attributes the file kept in one view in one view again (one per view,
//   blocks one after the other, or interleaved at the file's offsets and stride), or else in one
//   interleaved view (lit::Vertex as it is in memory: POSITION, NORMAL, TEXCOORD_0, TANGENT every
//   48 bytes); indices in the file's component type while they fit, else UNSIGNED_INT.
// - Nodes are written in the file's order (Node::fileIndex), nodes Lit made after them: an
//   unedited file keeps its node indices. A node's `matrix` is written back while its transform
//   is unedited and no written animation moves it. Primitives without triangles are left out
//   (the loader skips them), and so are meshes left with none.
// - A primitive's accessors are written in the file's order, and an accessor the file shared
//   (KeptAccessorInfo::file) is written once while the values agree, so an unedited file keeps
//   its accessor indices too; min/max the file had are recomputed from the written values
//   (the file's exact numbers where their floats agree).
// - Names, extras and extensions of the file's accessors, buffer views and buffers go on the
//   accessor or view that holds the same data again (kept attributes, sparse data, embedded
//   images, animation data, drawn geometry while unedited); the one buffer gets those of all the
//   file's buffers.
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
// - Kept accessors that were sparse are written sparse (KeptAccessor::Sparse), with a new layout
//   where an edit made the file's wrong (resparse).
// - Animation outputs are written in the file's component type (normalized integer rotations
//   and weights); key times shared by samplers are written once.
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
#include <functional>
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

// A drawn vertex attribute of lit::Vertex as a primitive writes it.
struct PrimitiveAttribute {
    const char* name;
    std::size_t offset;  // in lit::Vertex
    std::size_t bytes;
    int type;
};

class ModelBuilder {
public:
    // `replacedAnimation`: the name of a kept animation not to write (the caller writes its own).
    ModelBuilder(const Scene& scene, const fs::path& file, std::string replacedAnimation)
        : scene_(scene), file_(file), replacedAnimation_(std::move(replacedAnimation)) {}

    tinygltf::Model build();
    std::vector<std::pair<std::string, std::string>> takeJsonPatches() { return std::move(jsonPatches_); }
    // The written indices of Scene::keptNodes (valid after build()).
    const std::vector<int>& keptNodeIndices() const { return keptNodeIndex_; }

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
    // The skins (in order) up to the first whose inverse bind matrices came after the file's
    // accessor `beforeFileAccessor`, so they are written in the file's accessor order.
    void addSkins(int beforeFileAccessor);
    void orderNodes();
    // The written index of a node reference (scene/Scene.h: keptNodeRef), -1 when not written.
    int writtenNode(int reference) const;
    // Names, extras and extensions of the file's objects Lit lays out itself (scene/Scene.h).
    void keepView(int view, const KeptObject& kept);
    void keepAccessor(int accessor, const KeptAccessorInfo& info);
    std::pair<std::vector<double>, std::vector<double>> minMaxOf(int accessor) const;
    void keepMinMax(int accessor, const KeptAccessorInfo& info);
    template <class Object>
    void keepNameAndExtras(Object& out, const char* array, int index, const std::string& name, const KeptGltf& kept);
    void keepBuffers();
    void checkKeptNodes() const;
    std::optional<std::string> relativeUri(const Image& image) const;
    void addImages();
    void addTextures();
    void addMaterials();
    void keepMaterialFields(const Material& material, const tinygltf::Material& out, std::size_t index);
    void addMeshes();
    tinygltf::Primitive addPrimitive(const Primitive& primitive);
    void addAttributeView(const std::vector<PrimitiveAttribute>& group, const std::vector<Vertex>& vertices,
                          const Primitive& primitive, tinygltf::Primitive& p);
    void setPositionBounds(int accessor, const Primitive& primitive);
    int sharedAccessor(int file, int componentType, int type, bool normalized, const unsigned char* bytes,
                       std::size_t count) const;
    void addLights();
    void addCameras();
    void addNodes();
    void addAnimations();
    int addAnimationOutput(const Animation::Sampler& sampler, int type);
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
    std::size_t nextSkin_ = 0;    // the next skin addSkins looks at
    std::vector<std::pair<const Node*, bool>> writtenNodes_;  // in written order; true: a kept node
    std::vector<int> imageIndex_;  // scene image → glTF image, -1 when not written (generated)
    // JSON the tinygltf serialiser cannot write (a sampler's name and extensions): JSON pointer →
    // value text, set into the document by writeGltfModel.
    std::vector<std::pair<std::string, std::string>> jsonPatches_;
    // Animation accessors written so far, by the file's accessor index (Animation::Sampler).
    std::map<int, std::pair<int, const std::vector<float>*>> writtenInputs_;
    std::map<int, std::pair<int, const Animation::Sampler*>> writtenOutputs_;
    std::map<int, int> writtenByFile_;  // the file's accessor → its written copy (sharedAccessor)
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
    keepMinMax(accessor, info);
    tinygltf::Accessor& out = model_.accessors[static_cast<std::size_t>(accessor)];
    keepNameAndExtras(out, "accessors", accessor, info.name, info.kept);
    keepView(out.bufferView, info.view);
}

// Component c of an element, as the number glTF's min/max give (not normalized).
double componentValue(const unsigned char* element, int componentType, int c) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return static_cast<std::int8_t>(element[c]);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return element[c];
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, element + 2 * c, 2);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, element + 2 * c, 2);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, element + 4 * c, 4);
            return v;
        }
        default: {
            float v;
            std::memcpy(&v, element + 4 * c, 4);
            return v;
        }
    }
}

// Min and max of a written accessor's elements (its buffer view, or zeros, with its sparse values
// put in), per component.
std::pair<std::vector<double>, std::vector<double>> ModelBuilder::minMaxOf(int index) const {
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (components <= 0 || a.count == 0) return {};
    const std::size_t elementSize = static_cast<std::size_t>(gltfkeep::componentBytes(a.componentType)) * static_cast<std::size_t>(components);
    const std::vector<unsigned char> zeros(elementSize, 0);
    const auto viewBytes = [&](int view) {
        const tinygltf::BufferView& v = model_.bufferViews[static_cast<std::size_t>(view)];
        return model_.buffers[static_cast<std::size_t>(v.buffer)].data.data() + v.byteOffset;
    };
    std::vector<const unsigned char*> elements(a.count, zeros.data());
    if (a.bufferView >= 0) {
        const tinygltf::BufferView& v = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
        const std::size_t stride = v.byteStride ? v.byteStride : elementSize;
        const unsigned char* first = viewBytes(a.bufferView) + a.byteOffset;
        for (std::size_t i = 0; i < a.count; ++i) elements[i] = first + i * stride;
    }
    if (a.sparse.isSparse) {
        const unsigned char* indices = viewBytes(a.sparse.indices.bufferView) + a.sparse.indices.byteOffset;
        const unsigned char* values = viewBytes(a.sparse.values.bufferView) + a.sparse.values.byteOffset;
        for (std::size_t s = 0; s < static_cast<std::size_t>(a.sparse.count); ++s) {
            const auto target = static_cast<std::size_t>(
                componentValue(indices, a.sparse.indices.componentType, static_cast<int>(s)));
            elements[target] = values + s * elementSize;
        }
    }
    std::vector<double> lo(static_cast<std::size_t>(components), std::numeric_limits<double>::max());
    std::vector<double> hi(static_cast<std::size_t>(components), std::numeric_limits<double>::lowest());
    for (const unsigned char* element : elements)
        for (int c = 0; c < components; ++c) {
            const double v = componentValue(element, a.componentType, c);
            lo[static_cast<std::size_t>(c)] = std::min(lo[static_cast<std::size_t>(c)], v);
            hi[static_cast<std::size_t>(c)] = std::max(hi[static_cast<std::size_t>(c)], v);
        }
    return {lo, hi};
}

// The file had min/max on this accessor: written again, recomputed from the written values, each
// number the file's own where it still holds (its float equals the recomputed one), so an
// unedited accessor keeps the file's exact JSON numbers.
void ModelBuilder::keepMinMax(int accessor, const KeptAccessorInfo& info) {
    if (info.min.empty() && info.max.empty()) return;
    auto [lo, hi] = minMaxOf(accessor);
    if (lo.empty()) return;
    const auto fileNumbers = [](std::vector<double>& computed, const std::vector<double>& file) {
        if (file.size() != computed.size()) return;
        for (std::size_t c = 0; c < computed.size(); ++c)
            if (static_cast<float>(file[c]) == static_cast<float>(computed[c])) computed[c] = file[c];
    };
    fileNumbers(lo, info.min);
    fileNumbers(hi, info.max);
    tinygltf::Accessor& out = model_.accessors[static_cast<std::size_t>(accessor)];
    out.minValues = std::move(lo);
    out.maxValues = std::move(hi);
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

// Bytes of a sparse index of this component type; 0 where glTF allows no sparse indices (signed, float).
int sparseIndexBytes(int componentType) {
    const bool unsignedType = componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                              componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                              componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    return unsignedType ? gltfkeep::componentBytes(componentType) : 0;
}

bool isZero(const std::uint8_t* element, std::size_t bytes) {
    return std::all_of(element, element + bytes, [](std::uint8_t b) { return b == 0; });
}

// Whether a kept sparse accessor's layout (KeptAccessor::Sparse) still describes its elements:
// indices strictly increasing, inside the elements and their component type, the base's elements
// known, and with a base of zeros, every element outside the indices zero.
bool sparseLayoutHolds(const KeptAccessor& kept, std::size_t elementSize) {
    const KeptAccessor::Sparse& sparse = *kept.sparse;
    const int indexSize = sparseIndexBytes(sparse.indexComponentType);
    if (indexSize == 0 || sparse.indices.empty() ||
        (sparse.hasBase && sparse.baseBytes.size() != sparse.indices.size() * elementSize))
        return false;
    for (std::size_t s = 0; s < sparse.indices.size(); ++s) {
        const std::uint32_t i = sparse.indices[s];
        if (i >= kept.count || (indexSize < 4 && i >= (1u << (8 * indexSize))) || (s > 0 && i <= sparse.indices[s - 1]))
            return false;
    }
    if (sparse.hasBase) return true;
    std::size_t s = 0;
    for (std::size_t i = 0; i < kept.count; ++i) {
        if (s < sparse.indices.size() && sparse.indices[s] == i) {
            ++s;
            continue;
        }
        if (!isZero(kept.bytes.data() + i * elementSize, elementSize)) return false;
    }
    return true;
}

// A sparse layout for elements an edit changed so the file's no longer holds them (an index past
// the elements, a non-zero element over a base of zeros): the file's indices still inside the
// elements, with a base of zeros also every non-zero element, in a component type that holds them
// (the file's, or wider). The parts' names, extras and extensions stay (before issue #13's seventh
// session such an accessor was written dense, without them). Where the base is kept, the file's
// base elements stay under its indices; under an index past the file's base, the element itself.
KeptAccessor::Sparse resparse(const KeptAccessor& kept, std::size_t elementSize) {
    const KeptAccessor::Sparse& file = *kept.sparse;
    KeptAccessor::Sparse out = file;
    out.indices.clear();
    out.baseBytes.clear();
    const bool baseKnown = file.hasBase && file.baseBytes.size() == file.indices.size() * elementSize;
    constexpr std::size_t kNotSparse = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> fileSlot(kept.count, kNotSparse);  // element → its place in file.indices
    for (std::size_t s = 0; s < file.indices.size(); ++s)
        if (file.indices[s] < kept.count && fileSlot[file.indices[s]] == kNotSparse) fileSlot[file.indices[s]] = s;
    for (std::size_t i = 0; i < kept.count; ++i) {
        const std::uint8_t* element = kept.bytes.data() + i * elementSize;
        if (fileSlot[i] == kNotSparse && (file.hasBase || isZero(element, elementSize))) continue;
        out.indices.push_back(static_cast<std::uint32_t>(i));
        if (file.hasBase) {
            const std::uint8_t* under = baseKnown && fileSlot[i] != kNotSparse ? file.baseBytes.data() + fileSlot[i] * elementSize : element;
            out.baseBytes.insert(out.baseBytes.end(), under, under + elementSize);
        }
    }
    if (out.indices.empty()) {  // glTF: sparse.count ≥ 1; element 0 over its own base (or zero over zeros)
        out.indices.push_back(0);
        if (file.hasBase) out.baseBytes.assign(kept.bytes.begin(), kept.bytes.begin() + static_cast<std::ptrdiff_t>(elementSize));
    }
    const std::uint32_t last = out.indices.back();
    const int wanted = last < 256u ? 1 : last < 65536u ? 2 : 4;
    const int size = std::max(wanted, sparseIndexBytes(file.indexComponentType));
    out.indexComponentType = size == 1   ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
                             : size == 2 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                         : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    return out;
}

int ModelBuilder::addKeptAccessor(const KeptAccessor& kept, int target) {
    const int type = typeCode(kept.type);
    if (type < 0 || kept.count == 0 || kept.bytes.size() % kept.count != 0)
        fail("kept accessor data of type '" + kept.type + "' is inconsistent (" + std::to_string(kept.bytes.size()) +
             " bytes for " + std::to_string(kept.count) + " elements)");
    const std::size_t elementSize = kept.bytes.size() / kept.count;
    if (!kept.sparse) {
        const int shared = sharedAccessor(kept.info.file, kept.componentType, type, kept.normalized, kept.bytes.data(), kept.count);
        if (shared >= 0) return shared;
    }
    const KeptAccessor::Sparse* sparse = kept.sparse ? &*kept.sparse : nullptr;
    std::optional<KeptAccessor::Sparse> resparsed;
    if (sparse && !sparseLayoutHolds(kept, elementSize)) {
        resparsed = resparse(kept, elementSize);
        sparse = &*resparsed;
    }
    const int indexSize = sparse ? sparseIndexBytes(sparse->indexComponentType) : 0;
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
        // byteStride only where the file's view had it (it is optional for a view of one accessor).
        view = addBufferView(dense->data(), dense->size(), target,
                             target == kArrayBuffer && kept.info.viewStride == stride ? stride : 0);
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
        // tinygltf 2.7 writes no extras or extensions of these parts: set them in the JSON.
        const std::string at = "/accessors/" + std::to_string(accessor) + "/sparse";
        const auto keepPart = [&](const std::string& where, const KeptGltf& kept) {
            if (!kept.extras.empty()) jsonPatches_.emplace_back(where + "/extras", kept.extras);
            if (kept.extensions.empty()) return;
            jsonPatches_.emplace_back(where + "/extensions", kept.extensions);
            const nlohmann::json e = nlohmann::json::parse(kept.extensions, nullptr, false);
            if (e.is_object())
                for (auto it = e.begin(); it != e.end(); ++it) useExtension(it.key());
        };
        keepPart(at, sparse->sparseKept);
        keepPart(at + "/indices", sparse->indicesKept);
        keepPart(at + "/values", sparse->valuesKept);
    }
    keepAccessor(accessor, kept.info);
    if (kept.info.file >= 0) writtenByFile_.emplace(kept.info.file, accessor);
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
    // In the file's accessor order (those without a file index last).
    std::vector<std::pair<const std::string*, const KeptAccessor*>> ordered;
    for (const auto& [name, accessor] : kept) ordered.emplace_back(&name, &accessor);
    std::stable_sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) {
        const auto key = [](const KeptAccessor* k) { return k->info.file >= 0 ? k->info.file : std::numeric_limits<int>::max(); };
        return key(a.second) < key(b.second);
    });
    for (const auto& [namePointer, accessorPointer] : ordered) {
        const std::string& name = *namePointer;
        const KeptAccessor& accessor = *accessorPointer;
        if (accessor.count != vertexCount) {
            all = false;
            continue;
        }
        const int index = addKeptAccessor(accessor, kArrayBuffer);
        // glTF requires min and max on POSITION accessors, morph targets' included.
        if (name == "POSITION" && model_.accessors[static_cast<std::size_t>(index)].minValues.empty()) {
            auto [lo, hi] = minMaxOf(index);
            model_.accessors[static_cast<std::size_t>(index)].minValues = std::move(lo);
            model_.accessors[static_cast<std::size_t>(index)].maxValues = std::move(hi);
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
            // tinygltf writes no mimeType beside a uri; the file's optional one goes back.
            if (!image.mimeType.empty())
                jsonPatches_.emplace_back("/images/" + std::to_string(model_.images.size()) + "/mimeType",
                                          nlohmann::json(image.mimeType).dump());
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
    // One glTF sampler per distinct setting (name, extras, extensions and the fields written
    // included).
    using SamplerKey = std::tuple<std::array<int, 4>, std::array<bool, 4>, std::string, std::string, std::string>;
    std::map<SamplerKey, int> samplers;
    // Lit's values for what a file left out (scene/Scene.h: Texture).
    const std::array<int, 4> defaults = {10497, 10497, 9987, 9729};
    for (const Texture& texture : scene_.textures) {
        const std::array<int, 4> values = {texture.wrapS, texture.wrapT, texture.minFilter, texture.magFilter};
        // A field is written where the file had it or where it no longer holds Lit's default.
        std::array<bool, 4> written{};
        for (std::size_t f = 0; f < 4; ++f)
            written[f] = (texture.hasSampler && texture.samplerFields[f]) || values[f] != defaults[f];
        const bool anySampler = texture.hasSampler || std::find(written.begin(), written.end(), true) != written.end();
        int samplerIndex = -1;
        if (anySampler) {
            const SamplerKey key = {values, written, texture.samplerName, texture.samplerKept.extras, texture.samplerKept.extensions};
            auto [it, added] = samplers.emplace(key, static_cast<int>(model_.samplers.size()));
            if (added) {
                tinygltf::Sampler sampler;
                sampler.wrapS = texture.wrapS;
                sampler.wrapT = texture.wrapT;
                sampler.minFilter = written[2] ? texture.minFilter : -1;  // -1: not written by tinygltf
                sampler.magFilter = written[3] ? texture.magFilter : -1;
                tinygltf::ExtensionMap extensions;
                restore(texture.samplerKept, sampler.extras, extensions);
                // tinygltf 2.7 writes neither a sampler's name nor its extensions: set them in the
                // JSON; it always writes wrapS and wrapT: removed where the file had none.
                const std::string at = "/samplers/" + std::to_string(model_.samplers.size());
                if (!texture.samplerName.empty())
                    jsonPatches_.emplace_back(at + "/name", nlohmann::json(texture.samplerName).dump());
                if (!texture.samplerKept.extensions.empty())
                    jsonPatches_.emplace_back(at + "/extensions", texture.samplerKept.extensions);
                if (!written[0]) jsonPatches_.emplace_back(at + "/wrapS", "");
                if (!written[1]) jsonPatches_.emplace_back(at + "/wrapT", "");
                model_.samplers.push_back(sampler);
            }
            samplerIndex = it->second;
        }
        tinygltf::Texture out;
        out.name = texture.name;
        // The file's own image where the loader shared an identical earlier one (Texture::fileImage).
        int image = texture.image;
        if (texture.fileImage >= 0 && static_cast<std::size_t>(texture.fileImage) < scene_.images.size() &&
            texture.image >= 0 && scene_.images[static_cast<std::size_t>(texture.fileImage)].sameAs == texture.image)
            image = texture.fileImage;
        out.source = image >= 0 && static_cast<std::size_t>(image) < imageIndex_.size() ? imageIndex_[static_cast<std::size_t>(image)] : -1;
        out.sampler = samplerIndex;
        restore(texture.kept, out.extras, out.extensions);
        model_.textures.push_back(std::move(out));
    }
}

void ModelBuilder::addMaterials() {
    for (const Material& material : scene_.materials) {
        const FileNumbers& n = material.fileNumbers;
        tinygltf::Material out;
        out.name = material.name;
        tinygltf::PbrMetallicRoughness& pbr = out.pbrMetallicRoughness;
        pbr.baseColorFactor = fileOr(n, "baseColorFactor", material.baseColorFactor);
        pbr.baseColorTexture.index = material.baseColorTexture;
        pbr.baseColorTexture.texCoord = material.textureTexCoord[0];
        pbr.metallicFactor = fileOr(n, "metallicFactor", material.metallic);
        pbr.roughnessFactor = fileOr(n, "roughnessFactor", material.roughness);
        pbr.metallicRoughnessTexture.index = material.metallicRoughnessTexture;
        pbr.metallicRoughnessTexture.texCoord = material.textureTexCoord[1];
        out.normalTexture.texCoord = material.textureTexCoord[2];
        out.emissiveTexture.texCoord = material.textureTexCoord[3];
        out.occlusionTexture.texCoord = material.textureTexCoord[4];
        out.normalTexture.index = material.normalTexture;
        out.normalTexture.scale = fileOr(n, "normalScale", material.normalScale);
        out.occlusionTexture.index = material.occlusionTexture;
        out.occlusionTexture.strength = fileOr(n, "occlusionStrength", material.occlusionStrength);
        out.emissiveTexture.index = material.emissiveTexture;
        out.emissiveFactor = fileOr(n, "emissiveFactor", material.emissiveFactor);
        if (material.emissiveStrength != 1.0f || n.count("emissiveStrength")) {
            tinygltf::Value::Object extension;
            extension["emissiveStrength"] = tinygltf::Value(fileOr(n, "emissiveStrength", material.emissiveStrength));
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
        out.alphaCutoff = fileOr(n, "alphaCutoff", material.alphaCutoff);
        out.doubleSided = material.doubleSided;
        keepMaterialFields(material, out, model_.materials.size());
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

// The optional fields the file wrote (Material::fileFields) go back even where they hold glTF's
// default, which tinygltf leaves out: as JSON patches of the values being written. Texture
// reference fields only while the material still has that texture.
void ModelBuilder::keepMaterialFields(const Material& material, const tinygltf::Material& out, std::size_t index) {
    const auto number = [](double v) { return nlohmann::json(v).dump(); };
    const auto numbers = [](const std::vector<double>& v) { return nlohmann::json(v).dump(); };
    const tinygltf::PbrMetallicRoughness& pbr = out.pbrMetallicRoughness;
    for (const std::string& field : material.fileFields) {
        std::optional<std::string> value;
        if (field == "alphaCutoff") value = number(out.alphaCutoff);
        else if (field == "alphaMode") value = nlohmann::json(out.alphaMode).dump();
        else if (field == "doubleSided") value = nlohmann::json(out.doubleSided).dump();
        else if (field == "emissiveFactor") value = numbers(out.emissiveFactor);
        else if (field == "pbrMetallicRoughness/baseColorFactor") value = numbers(pbr.baseColorFactor);
        else if (field == "pbrMetallicRoughness/metallicFactor") value = number(pbr.metallicFactor);
        else if (field == "pbrMetallicRoughness/roughnessFactor") value = number(pbr.roughnessFactor);
        else if (field == "pbrMetallicRoughness/baseColorTexture/texCoord" && pbr.baseColorTexture.index >= 0)
            value = std::to_string(pbr.baseColorTexture.texCoord);
        else if (field == "pbrMetallicRoughness/metallicRoughnessTexture/texCoord" && pbr.metallicRoughnessTexture.index >= 0)
            value = std::to_string(pbr.metallicRoughnessTexture.texCoord);
        else if (field == "normalTexture/texCoord" && out.normalTexture.index >= 0)
            value = std::to_string(out.normalTexture.texCoord);
        else if (field == "normalTexture/scale" && out.normalTexture.index >= 0) value = number(out.normalTexture.scale);
        else if (field == "emissiveTexture/texCoord" && out.emissiveTexture.index >= 0)
            value = std::to_string(out.emissiveTexture.texCoord);
        else if (field == "occlusionTexture/texCoord" && out.occlusionTexture.index >= 0)
            value = std::to_string(out.occlusionTexture.texCoord);
        else if (field == "occlusionTexture/strength" && out.occlusionTexture.index >= 0)
            value = number(out.occlusionTexture.strength);
        if (value) jsonPatches_.emplace_back("/materials/" + std::to_string(index) + "/" + field, *value);
    }
}

// A drawn primitive: POSITION, NORMAL, TEXCOORD_0, TANGENT (only when the file had them: the
// loader generates them otherwise) and indices, laid out as the file had them (one view per
// attribute, or Lit's interleaved one; the file's index type while the indices fit, none for a
// file without indices while they are still 0, 1, 2, ...), then the kept attributes and targets.
tinygltf::Primitive ModelBuilder::addPrimitive(const Primitive& primitive) {
    const std::size_t count = primitive.vertices.size();
    const bool tangents = primitive.fileHasTangents;
    using Attribute = PrimitiveAttribute;
    std::vector<Attribute> attributes = {{"POSITION", offsetof(Vertex, position), 12, TINYGLTF_TYPE_VEC3},
                                         {"NORMAL", offsetof(Vertex, normal), 12, TINYGLTF_TYPE_VEC3},
                                         {"TEXCOORD_0", offsetof(Vertex, uv), 8, TINYGLTF_TYPE_VEC2}};
    if (tangents) attributes.push_back({"TANGENT", offsetof(Vertex, tangent), 16, TINYGLTF_TYPE_VEC4});
    // A file's primitive without TEXCOORD_0 is written without while its coordinates are still
    // the zeros the loader gave it.
    if (primitive.fileAccessors.count("POSITION") && !primitive.fileAccessors.count("TEXCOORD_0") &&
        std::all_of(primitive.vertices.begin(), primitive.vertices.end(), [](const Vertex& v) { return v.uv == glm::vec2(0.0f); }))
        attributes.erase(attributes.begin() + 2);
    const auto fileInfo = [&](const char* name) -> const KeptAccessorInfo* {
        const auto found = primitive.fileAccessors.find(name);
        return found == primitive.fileAccessors.end() ? nullptr : &found->second;
    };
    // A new accessor of drawn data: the file's min/max (recomputed), name, extras and extensions,
    // edited or not (the data is still that attribute); remembered under its file index, so that
    // primitives that shared it share it again while their values agree (sharedAccessor).
    const auto keepFile = [&](int accessor, const char* name) {
        const KeptAccessorInfo* info = fileInfo(name);
        if (!info) return;
        keepAccessor(accessor, *info);
        if (info->file >= 0) writtenByFile_.emplace(info->file, accessor);
    };
    // The file's own TANGENTs where it wrote some that are not unit length, while every vertex
    // still has their normalized direction and sign (the loader's reading of them).
    const std::vector<Vertex>* vertices = &primitive.vertices;
    std::vector<Vertex> withFileTangents;
    if (tangents && primitive.fileTangents.size() == count) {
        bool unedited = true;
        for (std::size_t v = 0; unedited && v < count; ++v) {
            const glm::vec4& file = primitive.fileTangents[v];
            const glm::vec3 xyz(file);
            const float length = glm::length(xyz);
            const glm::vec3 direction = std::abs(length - 1.0f) <= 1e-6f ? xyz : xyz / length;  // as the loader
            unedited = glm::vec3(primitive.vertices[v].tangent) == direction &&
                       primitive.vertices[v].tangent.w == (file.w < 0.0f ? -1.0f : 1.0f);
        }
        if (unedited) {
            withFileTangents = primitive.vertices;
            for (std::size_t v = 0; v < count; ++v) withFileTangents[v].tangent = primitive.fileTangents[v];
            vertices = &withFileTangents;
        }
    }
    const auto fileIndex = [&](const char* name) {
        const KeptAccessorInfo* info = fileInfo(name);
        return info && info->file >= 0 ? info->file : std::numeric_limits<int>::max();
    };
    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = primitive.material;

    // The accessors are written in the file's order (drawn attributes, kept ones, morph targets,
    // indices; what has no file index after the rest), so an unedited file keeps its accessor
    // indices where Lit writes what the file had.
    std::vector<std::pair<int, std::function<void()>>> writes;
    if (primitive.fileViews) {
        // The file's views: attributes it kept in one view go in one view again (one per view as
        // Blender writes them, one block after the other, or interleaved); one without a view in
        // the file gets its own.
        std::vector<std::vector<Attribute>> groups;
        std::map<int, std::size_t> groupOfView;
        for (const Attribute& a : attributes) {
            const KeptAccessorInfo* info = fileInfo(a.name);
            if (!info || info->fileView < 0) {
                groups.push_back({a});
                continue;
            }
            const auto [it, added] = groupOfView.emplace(info->fileView, groups.size());
            if (added) groups.emplace_back();
            groups[it->second].push_back(a);
        }
        for (std::vector<Attribute>& group : groups) {
            std::stable_sort(group.begin(), group.end(),
                             [&](const Attribute& a, const Attribute& b) { return fileIndex(a.name) < fileIndex(b.name); });
            writes.emplace_back(fileIndex(group.front().name), [&, group] { addAttributeView(group, *vertices, primitive, p); });
        }
    } else {
        int first = std::numeric_limits<int>::max();
        for (const Attribute& a : attributes) first = std::min(first, fileIndex(a.name));
        writes.emplace_back(first, [&] {
            // One interleaved view: lit::Vertex as it is in memory, 32 bytes a vertex without tangents.
            constexpr std::size_t kPackedStride = offsetof(Vertex, tangent);
            int view = -1;
            if (tangents) {
                view = addBufferView(vertices->data(), count * sizeof(Vertex), kArrayBuffer, sizeof(Vertex));
            } else {
                std::vector<unsigned char> packed(count * kPackedStride);
                for (std::size_t v = 0; v < count; ++v)
                    std::memcpy(packed.data() + v * kPackedStride, &(*vertices)[v], kPackedStride);
                view = addBufferView(packed.data(), packed.size(), kArrayBuffer, kPackedStride);
            }
            std::vector<Attribute> inFileOrder = attributes;
            std::stable_sort(inFileOrder.begin(), inFileOrder.end(),
                             [&](const Attribute& a, const Attribute& b) { return fileIndex(a.name) < fileIndex(b.name); });
            for (const Attribute& a : inFileOrder)
                p.attributes[a.name] = addAccessor(view, a.offset, TINYGLTF_COMPONENT_TYPE_FLOAT, a.type, count);
            setPositionBounds(p.attributes["POSITION"], primitive);
            for (const Attribute& a : attributes) keepFile(p.attributes[a.name], a.name);
        });
    }
    for (const auto& [name, accessor] : primitive.keptAttributes)
        writes.emplace_back(accessor.info.file >= 0 ? accessor.info.file : std::numeric_limits<int>::max(), [&, name = name] {
            KeptAttributes one;
            one.emplace(name, primitive.keptAttributes.at(name));
            addKeptAttributes(one, count, p.attributes);
        });
    if (!primitive.morphTargets.empty()) {
        int first = std::numeric_limits<int>::max();
        for (const KeptAttributes& target : primitive.morphTargets)
            for (const auto& [name, accessor] : target)
                if (accessor.info.file >= 0) first = std::min(first, accessor.info.file);
        writes.emplace_back(first, [&] { addTargets(primitive.morphTargets, count, p); });
    }
    bool sequential = primitive.fileIndexType == 0 && primitive.indices.size() == count;
    for (std::size_t i = 0; sequential && i < primitive.indices.size(); ++i) sequential = primitive.indices[i] == i;
    if (!sequential)
        writes.emplace_back(fileIndex("indices"), [&] {
            // The file's index type while every index fits in it (glTF: a type's largest value is
            // reserved for primitive restart), else UNSIGNED_INT.
            const std::uint32_t largest = *std::max_element(primitive.indices.begin(), primitive.indices.end());
            int type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
            if (primitive.fileIndexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && largest < 0xFFFFu) type = primitive.fileIndexType;
            if (primitive.fileIndexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && largest < 0xFFu) type = primitive.fileIndexType;
            std::vector<unsigned char> bytes;
            if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                const std::vector<std::uint16_t> narrow(primitive.indices.begin(), primitive.indices.end());
                bytes.assign(reinterpret_cast<const unsigned char*>(narrow.data()),
                             reinterpret_cast<const unsigned char*>(narrow.data() + narrow.size()));
            } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                bytes.assign(primitive.indices.begin(), primitive.indices.end());
            } else {
                bytes.assign(reinterpret_cast<const unsigned char*>(primitive.indices.data()),
                             reinterpret_cast<const unsigned char*>(primitive.indices.data() + primitive.indices.size()));
            }
            const KeptAccessorInfo* info = fileInfo("indices");
            const int shared = sharedAccessor(info ? info->file : -1, type, TINYGLTF_TYPE_SCALAR, false, bytes.data(),
                                              primitive.indices.size());
            if (shared >= 0) {
                p.indices = shared;
                return;
            }
            const int view = addBufferView(bytes.data(), bytes.size(), kElementArrayBuffer, 0);
            p.indices = addAccessor(view, 0, type, TINYGLTF_TYPE_SCALAR, primitive.indices.size());
            keepFile(p.indices, "indices");
        });
    std::stable_sort(writes.begin(), writes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [order, write] : writes) write();
    restore(primitive.kept, p.extras, p.extensions);
    return p;
}

// One buffer view of drawn attributes as the file had them in one view (Primitive::fileViews):
// interleaved at the file's offsets and stride where they fitted in one element, else one block
// after the other in the file's order (elements the file's stride apart where it had one); every
// accessor shared again where the file shared them all and the values still agree.
void ModelBuilder::addAttributeView(const std::vector<PrimitiveAttribute>& group, const std::vector<Vertex>& vertices,
                                    const Primitive& primitive, tinygltf::Primitive& p) {
    const std::size_t count = vertices.size();
    const auto fileInfo = [&](const char* name) -> const KeptAccessorInfo* {
        const auto found = primitive.fileAccessors.find(name);
        return found == primitive.fileAccessors.end() ? nullptr : &found->second;
    };
    const std::size_t n = group.size();
    std::vector<std::vector<unsigned char>> packed(n);
    std::vector<int> shared(n, -1);
    bool allShared = true;
    for (std::size_t k = 0; k < n; ++k) {
        const PrimitiveAttribute& a = group[k];
        packed[k].resize(count * a.bytes);
        for (std::size_t v = 0; v < count; ++v)
            std::memcpy(packed[k].data() + v * a.bytes, reinterpret_cast<const unsigned char*>(&vertices[v]) + a.offset, a.bytes);
        const KeptAccessorInfo* info = fileInfo(a.name);
        shared[k] = sharedAccessor(info ? info->file : -1, TINYGLTF_COMPONENT_TYPE_FLOAT, a.type, false, packed[k].data(), count);
        allShared = allShared && shared[k] >= 0;
    }
    if (allShared) {
        for (std::size_t k = 0; k < n; ++k) p.attributes[group[k].name] = shared[k];
        return;
    }
    const KeptAccessorInfo* first = fileInfo(group[0].name);
    const std::size_t fileStride = first ? first->viewStride : 0;
    std::size_t largest = 0;
    for (const PrimitiveAttribute& a : group) largest = std::max(largest, a.bytes);
    // Offsets in the file's view relative to the group's first byte.
    std::vector<std::size_t> fileOffset(n, 0);
    for (std::size_t k = 0; k < n; ++k)
        if (const KeptAccessorInfo* info = fileInfo(group[k].name)) fileOffset[k] = info->byteOffset;
    const std::size_t base = *std::min_element(fileOffset.begin(), fileOffset.end());
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return fileOffset[a] < fileOffset[b]; });
    bool interleaved = n > 1 && fileStride > 0;
    for (std::size_t i = 0; interleaved && i < n; ++i) {
        const std::size_t k = order[i];
        const std::size_t end = fileOffset[k] - base + group[k].bytes;
        interleaved = end <= fileStride && (i + 1 == n || base + end <= fileOffset[order[i + 1]]);
    }
    std::vector<std::size_t> offset(n, 0);
    std::size_t stride = 0, length = 0;
    if (interleaved) {
        stride = fileStride;
        for (std::size_t k = 0; k < n; ++k) offset[k] = fileOffset[k] - base;
        length = count * stride;
    } else {
        stride = fileStride >= largest ? fileStride : 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t k = order[i];
            length = (length + 3) & ~std::size_t(3);
            offset[k] = length;
            length += count * (stride ? stride : group[k].bytes);
        }
    }
    std::vector<unsigned char> bytes(length, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t step = stride ? stride : group[k].bytes;
        for (std::size_t v = 0; v < count; ++v)
            std::memcpy(bytes.data() + offset[k] + v * step, packed[k].data() + v * group[k].bytes, group[k].bytes);
    }
    // byteStride where the file had one (optional for a view of one tightly packed accessor).
    const int view = addBufferView(bytes.data(), bytes.size(), kArrayBuffer, fileStride > 0 ? stride : 0);
    for (std::size_t k = 0; k < n; ++k) {
        const PrimitiveAttribute& a = group[k];
        const int accessor = addAccessor(view, offset[k], TINYGLTF_COMPONENT_TYPE_FLOAT, a.type, count);
        p.attributes[a.name] = accessor;
        if (a.offset == offsetof(Vertex, position)) setPositionBounds(accessor, primitive);
        if (const KeptAccessorInfo* info = fileInfo(a.name)) {
            keepAccessor(accessor, *info);
            if (info->file >= 0) writtenByFile_.emplace(info->file, accessor);
        }
    }
}

// glTF requires POSITION's min and max.
void ModelBuilder::setPositionBounds(int accessor, const Primitive& primitive) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const Vertex& v : primitive.vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    model_.accessors[static_cast<std::size_t>(accessor)].minValues = doubles(lo);
    model_.accessors[static_cast<std::size_t>(accessor)].maxValues = doubles(hi);
}

// The accessor already written for the file's accessor `file`, when it has this type and these
// elements (tightly packed); -1 otherwise.
int ModelBuilder::sharedAccessor(int file, int componentType, int type, bool normalized, const unsigned char* bytes,
                                 std::size_t count) const {
    if (file < 0) return -1;
    const auto found = writtenByFile_.find(file);
    if (found == writtenByFile_.end()) return -1;
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(found->second)];
    if (a.componentType != componentType || a.type != type || a.count != count || a.normalized != normalized ||
        a.sparse.isSparse || a.bufferView < 0)
        return -1;
    const std::size_t elementSize =
        static_cast<std::size_t>(gltfkeep::componentBytes(componentType)) * static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type)));
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::size_t stride = view.byteStride ? view.byteStride : elementSize;
    const unsigned char* first = model_.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset + a.byteOffset;
    for (std::size_t i = 0; i < count; ++i)
        if (std::memcmp(first + i * stride, bytes + i * elementSize, elementSize) != 0) return -1;
    return found->second;
}

void ModelBuilder::addMeshes() {
    static_assert(offsetof(Vertex, position) == 0 && offsetof(Vertex, normal) == 12 && offsetof(Vertex, uv) == 24 &&
                      offsetof(Vertex, tangent) == 32,
                  "the interleaved vertex view below mirrors lit::Vertex");
    meshIndex_.assign(scene_.meshes.size(), -1);
    for (std::size_t m = 0; m < scene_.meshes.size(); ++m) {
        const Mesh& mesh = scene_.meshes[m];
        // Skins whose matrices the file had before this mesh's data.
        int first = std::numeric_limits<int>::max();
        for (const Primitive& primitive : mesh.primitives)
            for (const auto& [name, info] : primitive.fileAccessors)
                if (info.file >= 0) first = std::min(first, info.file);
        addSkins(first);
        tinygltf::Mesh out;
        out.name = mesh.name;
        for (const Primitive& primitive : mesh.primitives) {
            if (!primitive.indices.empty()) out.primitives.push_back(addPrimitive(primitive));
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

// A node's translation, rotation and scale, only what differs from the glTF defaults (as other
// exporters write them), with the file's exact numbers while they still hold.
void addTrs(const Node& node, tinygltf::Node& out) {
    if (node.translation != glm::vec3(0.0f)) out.translation = fileOr(node.fileNumbers, "t", node.translation);
    if (node.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        // A rotation already unit within float rounding is written as it is (the file's
        // numbers after a load), others normalized.
        const float length = glm::length(node.rotation);
        const glm::quat q = std::abs(length - 1.0f) <= 1e-6f ? node.rotation : node.rotation / length;
        out.rotation = fileOr(node.fileNumbers, "r", glm::vec4(q.x, q.y, q.z, q.w));  // glTF order
    }
    if (node.scale != glm::vec3(1.0f)) out.scale = fileOr(node.fileNumbers, "s", node.scale);
}

void ModelBuilder::orderNodes() {
    // The written nodes (the shown ones reachable from the roots, then the kept ones) in the
    // file's order (Node::fileIndex), those Lit made after them in their own order: an unedited
    // file keeps its node indices, an edited one its nodes' order. A file index seen twice (a
    // copied node) counts once.
    struct Written {
        const Node* node;
        bool kept;
        int index;  // in Scene::nodes or Scene::keptNodes
        long long order;
    };
    std::vector<Written> written;
    for (int index : reachableNodes()) written.push_back({&scene_.nodes[static_cast<std::size_t>(index)], false, index, 0});
    for (std::size_t k = 0; k < scene_.keptNodes.size(); ++k) written.push_back({&scene_.keptNodes[k], true, static_cast<int>(k), 0});
    {
        std::vector<std::uint8_t> seen;
        constexpr long long kMade = 1LL << 40;  // after every file index
        for (std::size_t i = 0; i < written.size(); ++i) {
            const int file = written[i].node->fileIndex;
            const bool first = file >= 0 && (static_cast<std::size_t>(file) >= seen.size() || !seen[static_cast<std::size_t>(file)]);
            if (first) {
                if (static_cast<std::size_t>(file) >= seen.size()) seen.resize(static_cast<std::size_t>(file) + 1, 0);
                seen[static_cast<std::size_t>(file)] = 1;
            }
            written[i].order = first ? file : kMade + static_cast<long long>(i);
        }
        std::stable_sort(written.begin(), written.end(), [](const Written& a, const Written& b) { return a.order < b.order; });
    }
    nodeIndex_.assign(scene_.nodes.size(), -1);
    keptNodeIndex_.assign(scene_.keptNodes.size(), -1);
    for (std::size_t i = 0; i < written.size(); ++i)
        (written[i].kept ? keptNodeIndex_ : nodeIndex_)[static_cast<std::size_t>(written[i].index)] = static_cast<int>(i);
    for (const Written& w : written) writtenNodes_.emplace_back(w.node, w.kept);
    skinIndex_.assign(scene_.skins.size(), -1);
}

void ModelBuilder::addNodes() {
    addSkins(std::numeric_limits<int>::max());
    // Nodes a written animation moves: glTF forbids a matrix on them (§5.25).
    std::vector<const Node*> animated;
    for (const Animation& animation : scene_.animations) {
        if (!replacedAnimation_.empty() && animation.name == replacedAnimation_) continue;
        for (const Animation::Channel& channel : animation.channels) {
            if (channel.path == "weights") continue;
            if (channel.node >= 0 && static_cast<std::size_t>(channel.node) < scene_.nodes.size())
                animated.push_back(&scene_.nodes[static_cast<std::size_t>(channel.node)]);
            else if (channel.node <= -2 && static_cast<std::size_t>(keptNodeIndex(channel.node)) < scene_.keptNodes.size())
                animated.push_back(&scene_.keptNodes[static_cast<std::size_t>(keptNodeIndex(channel.node))]);
        }
    }
    const auto addNode = [&](const Node& node, const std::vector<int>& childIndex) {
        tinygltf::Node out;
        out.name = node.name;
        for (int child : node.children) out.children.push_back(childIndex[static_cast<std::size_t>(child)]);
        // The file's matrix while the transform is the one it gave (an edit writes TRS).
        const bool fileMatrix = node.fileMatrix.size() == 16 && node.translation == node.matrixTranslation &&
                                node.rotation == node.matrixRotation && node.scale == node.matrixScale &&
                                std::find(animated.begin(), animated.end(), &node) == animated.end();
        if (fileMatrix) {
            out.matrix = node.fileMatrix;
        } else {
            addTrs(node, out);
        }

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
    for (const auto& [node, kept] : writtenNodes_) addNode(*node, kept ? keptNodeIndex_ : nodeIndex_);
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
    // The file's scenes in their order, the shown one where it was (without a name while it still
    // has the one the loader gave an unnamed scene).
    const std::string shownName =
        !scene_.fileSceneNamed && scene_.name == scene_.sourcePath.stem().string() ? std::string() : scene_.name;
    const std::size_t shown = std::min(static_cast<std::size_t>(std::max(scene_.sceneIndex, 0)), scene_.otherScenes.size());
    for (std::size_t i = 0; i < scene_.otherScenes.size(); ++i) {
        if (i == shown) model_.scenes.push_back(sceneOf(shownName, scene_.roots, scene_.kept));
        const Scene::OtherScene& other = scene_.otherScenes[i];
        model_.scenes.push_back(sceneOf(other.name, other.roots, other.kept));
    }
    if (shown == scene_.otherScenes.size()) model_.scenes.push_back(sceneOf(shownName, scene_.roots, scene_.kept));
    model_.defaultScene = static_cast<int>(shown);
}

// The skins whose joints are all written (a deleted joint leaves its skin out, and the skinned
// nodes are written without one).
void ModelBuilder::addSkins(int beforeFileAccessor) {
    const auto written = [&](int reference) { return writtenNode(reference); };
    for (; nextSkin_ < scene_.skins.size(); ++nextSkin_) {
        const std::size_t s = nextSkin_;
        const Skin& skin = scene_.skins[s];
        if (skin.inverseBindMatricesInfo.file >= beforeFileAccessor) break;
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

// An animation sampler's output values: floats, or the file's normalized integer type
// (rotations and morph weights may be BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT, glTF §5.7.1):
// the loader read c as c / 127 (BYTE), c / 255, c / 32767 or c / 65535, which round(v · that)
// turns back into c.
int ModelBuilder::addAnimationOutput(const Animation::Sampler& sampler, int type) {
    const std::size_t count = sampler.output.size() / static_cast<std::size_t>(sampler.components);
    const auto quantized = [&](auto zero, double scale, double lo) {
        using T = decltype(zero);
        std::vector<T> values(sampler.output.size());
        for (std::size_t i = 0; i < values.size(); ++i)
            values[i] = static_cast<T>(std::clamp(std::round(double(sampler.output[i]) * scale), lo, scale));
        const int view = addBufferView(values.data(), values.size() * sizeof(T), 0, 0);
        const int accessor = addAccessor(view, 0, sampler.outputComponentType, type, count);
        model_.accessors[static_cast<std::size_t>(accessor)].normalized = true;
        return accessor;
    };
    if (sampler.outputNormalized) {
        switch (sampler.outputComponentType) {
            case TINYGLTF_COMPONENT_TYPE_BYTE:
                return quantized(std::int8_t{}, 127.0, -127.0);
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                return quantized(std::uint8_t{}, 255.0, 0.0);
            case TINYGLTF_COMPONENT_TYPE_SHORT:
                return quantized(std::int16_t{}, 32767.0, -32767.0);
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
                return quantized(std::uint16_t{}, 65535.0, 0.0);
            default:
                break;
        }
    }
    const int view = addBufferView(sampler.output.data(), sampler.output.size() * sizeof(float), 0, 0);
    return addAccessor(view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, type, count);
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
            // An accessor the file's samplers shared is written once while the values agree.
            int input = -1;
            if (const auto shared = writtenInputs_.find(sampler.fileInput);
                sampler.fileInput >= 0 && shared != writtenInputs_.end() && *shared->second.second == sampler.input) {
                input = shared->second.first;
            } else {
                const int inputView = addBufferView(sampler.input.data(), sampler.input.size() * sizeof(float), 0, 0);
                input = addAccessor(inputView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, sampler.input.size());
                const auto [lo, hi] = std::minmax_element(sampler.input.begin(), sampler.input.end());
                model_.accessors[static_cast<std::size_t>(input)].minValues = {*lo};
                model_.accessors[static_cast<std::size_t>(input)].maxValues = {*hi};
                keepAccessor(input, sampler.inputInfo);
                if (sampler.fileInput >= 0) writtenInputs_[sampler.fileInput] = {input, &sampler.input};
            }
            int output = -1;
            if (const auto shared = writtenOutputs_.find(sampler.fileOutput);
                sampler.fileOutput >= 0 && shared != writtenOutputs_.end() && shared->second.second->output == sampler.output &&
                shared->second.second->components == sampler.components &&
                shared->second.second->outputComponentType == sampler.outputComponentType &&
                shared->second.second->outputNormalized == sampler.outputNormalized) {
                output = shared->second.first;
            } else {
                output = addAnimationOutput(sampler, typeOf[sampler.components]);
                keepAccessor(output, sampler.outputInfo);
                if (sampler.fileOutput >= 0) writtenOutputs_[sampler.fileOutput] = {output, &sampler};
            }
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
    orderNodes();
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

// Puts written buffer views whose bytes a view of the source file had (same length and hash,
// Scene::fileBufferViews) at that view's place: the file's buffers one after the other, each
// starting 4-byte aligned, so a file with one buffer keeps its offsets, and an unedited file's
// .bin comes back byte for byte (bytes the file had outside every view are written as zeros).
// A place is taken only where every accessor using the view stays aligned to its component size
// (glTF §3.6.2.4) and it agrees with the views already placed where they overlap (views the
// file let share bytes share them again). The other views (edited or new data) go into the gaps
// that are large enough, 4-byte aligned, else after the end. Runs on the merged buffer 0.
void keepFileLayout(tinygltf::Model& model, const Scene& scene) {
    if (model.buffers.size() != 1 || scene.fileBufferViews.empty()) return;
    for (const tinygltf::BufferView& view : model.bufferViews)  // mergeBuffers made them so; else leave the layout
        if (view.buffer != 0 || view.byteOffset > model.buffers[0].data.size() ||
            view.byteLength > model.buffers[0].data.size() - view.byteOffset)
            return;
    const auto align4 = [](std::size_t n) { return (n + 3) & ~std::size_t(3); };
    std::vector<std::size_t> base(scene.fileBufferSizes.size(), 0);
    for (std::size_t b = 0, end = 0; b < base.size(); ++b) {
        base[b] = align4(end);
        end = base[b] + scene.fileBufferSizes[b];
    }
    std::map<std::pair<std::size_t, std::uint64_t>, std::vector<std::size_t>> byContent;  // (length, hash) → file views
    for (std::size_t f = 0; f < scene.fileBufferViews.size(); ++f) {
        const Scene::FileBufferView& v = scene.fileBufferViews[f];
        if (v.buffer >= 0 && static_cast<std::size_t>(v.buffer) < base.size() && v.byteLength > 0)
            byContent[{v.byteLength, v.hash}].push_back(f);
    }
    // What each written view's place must be a multiple of, per accessor: (byteOffset, component size).
    std::vector<std::vector<std::pair<std::size_t, int>>> needs(model.bufferViews.size());
    const auto need = [&](int view, std::size_t offset, int componentType) {
        if (view >= 0 && static_cast<std::size_t>(view) < needs.size())
            needs[static_cast<std::size_t>(view)].emplace_back(offset, std::max(gltfkeep::componentBytes(componentType), 1));
    };
    for (const tinygltf::Accessor& a : model.accessors) {
        need(a.bufferView, a.byteOffset, a.componentType);
        if (a.sparse.isSparse) {
            need(a.sparse.indices.bufferView, a.sparse.indices.byteOffset, a.sparse.indices.componentType);
            need(a.sparse.values.bufferView, a.sparse.values.byteOffset, a.componentType);
        }
    }
    const std::vector<unsigned char>& written = model.buffers[0].data;
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> place(model.bufferViews.size(), kNone);
    std::vector<char> taken(scene.fileBufferViews.size(), 0);
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        const tinygltf::BufferView& view = model.bufferViews[v];
        if (view.byteLength == 0) continue;
        const auto it = byContent.find({view.byteLength, gltfkeep::hashBytes(written.data() + view.byteOffset, view.byteLength)});
        if (it == byContent.end()) continue;
        const auto fits = [&](std::size_t at) {
            return std::all_of(needs[v].begin(), needs[v].end(), [&](const auto& n) { return (at + n.first) % static_cast<std::size_t>(n.second) == 0; });
        };
        // The first file view of these bytes not taken yet (files write equal data more than once), else a taken one.
        for (int pass = 0; pass < 2 && place[v] == kNone; ++pass)
            for (std::size_t f : it->second) {
                const Scene::FileBufferView& file = scene.fileBufferViews[f];
                const std::size_t at = base[static_cast<std::size_t>(file.buffer)] + file.byteOffset;
                if ((pass == 0 && taken[f]) || !fits(at)) continue;
                place[v] = at;
                taken[f] = 1;
                break;
            }
    }
    std::vector<std::size_t> order;
    for (std::size_t v = 0; v < place.size(); ++v)
        if (place[v] != kNone) order.push_back(v);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return place[a] < place[b]; });
    std::vector<unsigned char> out;
    std::vector<std::pair<std::size_t, std::size_t>> gaps;  // [begin, end) between placed views
    std::size_t end = 0;  // of the placed views so far; [place, end) is inside the view that reached `end`
    for (std::size_t v : order) {
        const tinygltf::BufferView& view = model.bufferViews[v];
        const unsigned char* bytes = written.data() + view.byteOffset;
        const std::size_t at = place[v];
        const std::size_t overlap = at < end ? std::min(end, at + view.byteLength) - at : 0;
        if (overlap > 0 && std::memcmp(out.data() + at, bytes, overlap) != 0) {
            place[v] = kNone;  // shares bytes with a placed view that now differ: written elsewhere
            continue;
        }
        if (at > end) gaps.emplace_back(end, at);
        if (at + view.byteLength > out.size()) out.resize(at + view.byteLength, 0);
        std::memcpy(out.data() + at + overlap, bytes + overlap, view.byteLength - overlap);
        end = std::max(end, at + view.byteLength);
    }
    for (std::size_t v = 0; v < place.size(); ++v) {
        tinygltf::BufferView& view = model.bufferViews[v];
        if (place[v] != kNone) continue;
        std::size_t at = kNone;
        for (auto& gap : gaps)
            if (align4(gap.first) + view.byteLength <= gap.second) {
                at = align4(gap.first);
                gap.first = at + view.byteLength;
                break;
            }
        if (at == kNone) {
            at = align4(out.size());
            out.resize(at, 0);
        }
        if (at + view.byteLength > out.size()) out.resize(at + view.byteLength, 0);
        std::memcpy(out.data() + at, written.data() + view.byteOffset, view.byteLength);
        place[v] = at;
    }
    for (std::size_t v = 0; v < place.size(); ++v) model.bufferViews[v].byteOffset = place[v];
    model.buffers[0].data = std::move(out);
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
            // The path animates a camera of the shown scene: the kept nodes are hidden from
            // writeCameraPathAnimation's search for a camera node, so without a shown camera it
            // adds one rather than animate a node Lit does not show.
            const std::vector<int>& keptNodes = builder.keptNodeIndices();
            std::vector<int> keptCameras;
            for (int i : keptNodes) keptCameras.push_back(std::exchange(model.nodes[static_cast<std::size_t>(i)].camera, -1));
            writeCameraPathAnimation(model, *options.cameraPath, options.cameraPathName);
            for (std::size_t i = 0; i < keptCameras.size(); ++i)
                model.nodes[static_cast<std::size_t>(keptNodes[i])].camera = keptCameras[i];
        } catch (const CameraPathError& e) {
            throw SceneSaveError(file.string() + ": cannot write the camera path: " + e.what());
        }
    }
    mergeBuffers(model);
    keepFileLayout(model, scene);
    if (!binary && !model.buffers.empty()) model.buffers[0].uri = percentEncodePath(file.stem().string() + ".bin");

    try {
        writeGltfModel(std::move(model), file, binary, options.alsoWrite, jsonPatches);
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        throw SceneSaveError(what.starts_with(file.string() + ": ") ? what : file.string() + ": " + what);
    }
}

}  // namespace lit
