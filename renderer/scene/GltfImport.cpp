// glTF → Scene (scene/GltfImport.h).
//
// Decisions worth knowing:
// - The nodes of the chosen scene (the default scene, else scene 0, else every parentless node)
//   become Scene::nodes; the file's other nodes (other scenes' trees, nodes of no scene) become
//   Scene::keptNodes, kept for saving and not drawn. Both lists are in file order.
// - Orthographic cameras are drawn as perspective cameras with yfov 0.8 (warning) and saved back
//   as orthographic.
// - Meshes: scene/GltfImportMeshes.h. Images: scene/GltfImportImages.h. What Lit does not draw:
//   scene/GltfImportKept.h.

#include "scene/GltfImport.h"

#include "scene/GltfImportImages.h"
#include "scene/GltfImportKept.h"
#include "scene/GltfImportMeshes.h"
#include "scene/GltfKeep.h"
#include "scene/GltfMaterialLayers.h"
#include "scene/GltfTextureTransform.h"
#include "scene/GltfValidate.h"
#include "scene/LightUnits.h"

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace lit::gltfimport {

namespace {

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

class Importer {
public:
    explicit Importer(const GltfSource& source) : source_(source), model_(source.model) {}

    Scene run();

private:
    [[noreturn]] void fail(const std::string& problem) const { source_.fail(problem); }
    void warn(const std::string& problem) const { source_.warn(problem); }
    void report(const char* stage, std::size_t done, std::size_t total) const { source_.report(stage, done, total); }

    // Returns each file node's node reference (scene/Scene.h: keptNodeRef).
    std::vector<int> loadNodes(Scene& scene) const;
    void loadMaterials(Scene& scene) const;
    void loadTextures(Scene& scene) const;
    void loadLights(Scene& scene) const;
    void loadCameras(Scene& scene) const;
    // A textureInfo object inside a material extension (`where` names it in messages).
    ExtensionTexture extensionTexture(const tinygltf::Value& info, const std::string& where) const;
    // One warning where texture reference `reference` names a UV set beyond TEXCOORD_1 (its own
    // `texCoord`, or its transform's override): Lit draws it with TEXCOORD_0.
    void warnUndrawnUvSet(const std::string& reference, int texCoord, const TextureTransform& transform) const;

    const GltfSource& source_;
    const tinygltf::Model& model_;
};

ExtensionTexture Importer::extensionTexture(const tinygltf::Value& info, const std::string& where) const {
    ExtensionTexture out;
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt()) {
        warn(where + " is not a textureInfo with an integer index; not drawn (kept and saved)");
        return out;
    }
    out.texture = checkedTextureIndex(source_, info.Get("index").Get<int>(), where);
    if (info.Has("texCoord")) {
        const tinygltf::Value& set = info.Get("texCoord");
        if (set.IsInt() && set.Get<int>() >= 0)
            out.texCoord = set.Get<int>();
        else
            warn(where + " texCoord is not a non-negative integer; Lit uses TEXCOORD_0");
    }
    if (info.Has("scale")) {
        const tinygltf::Value& scale = info.Get("scale");
        if (scale.IsNumber() && std::isfinite(scale.GetNumberAsDouble()))
            out.scale = static_cast<float>(scale.GetNumberAsDouble());
        else
            warn(where + " scale is not a finite number; Lit uses 1");
    }
    if (info.Has("extensions") && info.Get("extensions").IsObject()) {
        const tinygltf::Value& extensions = info.Get("extensions");
        tinygltf::ExtensionMap map;
        for (const std::string& key : extensions.Keys()) map[key] = extensions.Get(key);
        out.transform =
            gltfkeep::readTextureTransform(map, [&](const std::string& problem) { warn(where + ": " + problem); });
    }
    if (out.texture >= 0) warnUndrawnUvSet(where, out.texCoord, out.transform);
    return out;
}

void Importer::warnUndrawnUvSet(const std::string& reference, int texCoord, const TextureTransform& transform) const {
    const bool overridden = transform.texCoord >= 0;
    const int set = overridden ? transform.texCoord : texCoord;
    if (set > 1)
        warn(reference + " uses TEXCOORD_" + std::to_string(set) +
             (overridden ? " (KHR_texture_transform texCoord)" : "") +
             "; Lit draws TEXCOORD_0 and TEXCOORD_1 and draws it with TEXCOORD_0 (the file's choice is saved back)");
}

// Notes a file's number that a float cannot hold exactly (scene/Scene.h: FileNumbers).
void noteNumber(FileNumbers& numbers, const std::string& key, double file) {
    if (std::isfinite(file) && static_cast<double>(static_cast<float>(file)) != file) numbers[key] = file;
}

// How far from 1 a rotation's length may be and still count as unit: float32 rounding of the
// components (Blender writes float32 values) is a few 1e-8; well inside the glTF validator's
// unit-length tolerance.
constexpr float kUnitQuaternionTolerance = 1e-6f;

std::vector<int> Importer::loadNodes(Scene& scene) const {
    const std::size_t n = model_.nodes.size();
    // Every node's parent, the tree checked (scene/GltfValidate.h).
    const std::vector<int> parent = checkNodeTree(source_);

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
            source_.log.info(source_.path.filename().string() + ": " + std::to_string(kept) +
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
                warn(what +
                     " is skinned; skinning is not supported and the mesh is drawn in its bind pose (the skin is "
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
            // The keys "t0", "r3", ... built by append: GCC 12 at -O3 warns (-Wrestrict, a false
            // positive) on "t" + std::to_string(k) here, which breaks the -Werror Release build.
            const auto component = [](char what, std::size_t k) { return std::string(1, what).append(std::to_string(k)); };
            for (std::size_t k = 0; k < in.translation.size(); ++k)
                noteNumber(node.fileNumbers, component('t', k), in.translation[k]);
            for (std::size_t k = 0; k < in.rotation.size(); ++k)
                noteNumber(node.fileNumbers, component('r', k), in.rotation[k]);
            for (std::size_t k = 0; k < in.scale.size(); ++k)
                noteNumber(node.fileNumbers, component('s', k), in.scale[k]);
        }
        node.kept = gltfkeep::keep(in.extras, in.extensions, {"KHR_lights_punctual"});
        (reachable[i] ? scene.nodes : scene.keptNodes).push_back(std::move(node));
    }
    for (int root : roots) scene.roots.push_back(remap[static_cast<std::size_t>(root)]);
    return reference;
}

void Importer::loadMaterials(Scene& scene) const {
    for (std::size_t m = 0; m < model_.materials.size(); ++m) {
        const tinygltf::Material& in = model_.materials[m];
        const std::string what = "material " + std::to_string(m) + (in.name.empty() ? "" : " ('" + in.name + "')");
        const auto texture = [&](int index, const char* slot) {
            return checkedTextureIndex(source_, index, what + " " + slot);
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
        out.baseColorTexture = texture(pbr.baseColorTexture.index, "baseColorTexture");
        out.metallic = static_cast<float>(unitFactors({pbr.metallicFactor}, "metallicFactor")[0]);
        out.roughness = static_cast<float>(unitFactors({pbr.roughnessFactor}, "roughnessFactor")[0]);
        out.metallicRoughnessTexture = texture(pbr.metallicRoughnessTexture.index, "metallicRoughnessTexture");
        out.normalTexture = texture(in.normalTexture.index, "normalTexture");
        out.normalScale = static_cast<float>(in.normalTexture.scale);
        if (in.emissiveFactor.size() == 3) {
            const std::vector<double> f = unitFactors(in.emissiveFactor, "emissiveFactor");
            out.emissiveFactor = glm::vec3(f[0], f[1], f[2]);
        }
        out.emissiveTexture = texture(in.emissiveTexture.index, "emissiveTexture");
        out.occlusionTexture = texture(in.occlusionTexture.index, "occlusionTexture");
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
        gltfkeep::readMaterialLayers(in.extensions, out, [&](const std::string& problem) { warn(what + " " + problem); });
        for (const ExtensionTextureSlot& slot : kExtensionTextureSlots)
            if (const auto it = in.extensions.find(slot.extension);
                it != in.extensions.end() && it->second.IsObject() && it->second.Has(slot.key))
                out.*slot.member =
                    extensionTexture(it->second.Get(slot.key), what + " " + slot.extension + " " + slot.key);
        out.kept = gltfkeep::keep(in.extras, in.extensions, {"KHR_materials_emissive_strength"});
        out.textureTexCoord = {pbr.baseColorTexture.texCoord, pbr.metallicRoughnessTexture.texCoord,
                               in.normalTexture.texCoord, in.emissiveTexture.texCoord, in.occlusionTexture.texCoord};
        // KHR_texture_transform is read into textureTransforms (and written from there); the
        // references' other extensions are kept as text.
        const std::array<const tinygltf::ExtensionMap*, 5> referenceExtensions = {
            &pbr.baseColorTexture.extensions, &pbr.metallicRoughnessTexture.extensions, &in.normalTexture.extensions,
            &in.emissiveTexture.extensions, &in.occlusionTexture.extensions};
        static constexpr std::array<const char*, 5> kSlotNames = {"baseColorTexture", "metallicRoughnessTexture",
                                                                  "normalTexture", "emissiveTexture",
                                                                  "occlusionTexture"};
        const std::array<int, 5> textures = {out.baseColorTexture, out.metallicRoughnessTexture, out.normalTexture,
                                             out.emissiveTexture, out.occlusionTexture};
        for (std::size_t slot = 0; slot < 5; ++slot) {
            const tinygltf::ExtensionMap& extensions = *referenceExtensions[slot];
            out.textureExtensions[slot] = gltfkeep::extensionsText(extensions, {gltfkeep::kTextureTransformExtension});
            const std::string reference = what + " " + kSlotNames[slot];
            TextureTransform& transform = out.textureTransforms[slot];
            transform = gltfkeep::readTextureTransform(
                extensions, [&](const std::string& problem) { warn(reference + ": " + problem); });
            if (textures[slot] >= 0) warnUndrawnUvSet(reference, out.textureTexCoord[slot], transform);
        }
        out.textureExtras = {
            gltfkeep::extrasText(pbr.baseColorTexture.extras),
            gltfkeep::extrasText(pbr.metallicRoughnessTexture.extras), gltfkeep::extrasText(in.normalTexture.extras),
            gltfkeep::extrasText(in.emissiveTexture.extras), gltfkeep::extrasText(in.occlusionTexture.extras)};
        out.pbrKept = gltfkeep::keep(pbr.extras, pbr.extensions);
        // What tinygltf does not report: which optional fields the file wrote (a save writes
        // them again, defaults included), and its exact numbers (scene/Scene.h: Material).
        if (const nlohmann::json& file = source_.fileObject("materials", m); file.is_object())
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

void Importer::loadTextures(Scene& scene) const {
    for (std::size_t t = 0; t < model_.textures.size(); ++t) {
        const tinygltf::Texture& in = model_.textures[t];
        Texture out;
        out.name = in.name;
        if (in.source >= 0) {
            if (static_cast<std::size_t>(in.source) >= model_.images.size())
                fail("texture " + std::to_string(t) + " refers to image " + std::to_string(in.source) +
                     ", which is out of range (the file has " + std::to_string(model_.images.size()) + " images)");
            out.image = source_.images.canonical(in.source);  // identical images are decoded once and shared
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
            const nlohmann::json& file = source_.fileObject("samplers", static_cast<std::size_t>(in.sampler));
            out.samplerFields = {!file.is_object() || file.contains("wrapS"),
                                 !file.is_object() || file.contains("wrapT"), s.minFilter >= 0, s.magFilter >= 0};
        } else {
            out.hasSampler = false;
        }
        // EXT_texture_webp: its image replaces `source`, which stays the file's fallback.
        const auto webp = in.extensions.find("EXT_texture_webp");
        const bool readWebp = LIT_HAS_WEBP != 0 && webp != in.extensions.end();
        if (readWebp) {
            const tinygltf::Value& source = webp->second.Get("source");
            const int image = source.IsInt() ? source.Get<int>() : -1;
            if (image < 0 || static_cast<std::size_t>(image) >= model_.images.size())
                fail("texture " + std::to_string(t) + " has an EXT_texture_webp source that is not an image of the file (" +
                     std::to_string(model_.images.size()) + " images)");
            out.fallbackImage = out.fileImage;
            out.image = source_.images.canonical(image);
            out.fileImage = image;
            out.webp = true;
        }
        out.kept = readWebp ? gltfkeep::keep(in.extras, in.extensions, {"EXT_texture_webp"})
                            : gltfkeep::keep(in.extras, in.extensions);
        scene.textures.push_back(out);
    }
}

void Importer::loadLights(Scene& scene) const {
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
            const double outer = std::isnan(in.spot.outerConeAngle)
                                     ? kQuarterTurn
                                     : std::clamp(in.spot.outerConeAngle, 1e-4, kQuarterTurn);
            const double inner =
                std::isnan(in.spot.innerConeAngle) ? 0.0 : std::clamp(in.spot.innerConeAngle, 0.0, outer * 0.999);
            if (outer != in.spot.outerConeAngle || inner != in.spot.innerConeAngle)
                warn(what + " has cone angles inner " + numberText(in.spot.innerConeAngle) + ", outer " +
                     numberText(in.spot.outerConeAngle) +
                     " rad (the spec wants 0 <= inner < outer <= pi/2); Lit uses inner " + numberText(inner) +
                     ", outer " + numberText(outer));
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
        // Lit's own flag (scene/GltfExport.cpp writes it); glTF has no shadow switch.
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

void Importer::loadCameras(Scene& scene) const {
    for (std::size_t c = 0; c < model_.cameras.size(); ++c) {
        const tinygltf::Camera& in = model_.cameras[c];
        Camera out;
        out.name = in.name;
        if (in.type == "perspective") {
            const std::string what = "camera " + std::to_string(c) + (in.name.empty() ? "" : " ('" + in.name + "')");
            const tinygltf::PerspectiveCamera& p = in.perspective;
            // The spec: yfov > 0, znear > 0, zfar > znear when present (0 here: absent, infinite).
            if (p.yfov > 0.0 && p.yfov < 3.14159)
                out.yfov = static_cast<float>(p.yfov);
            else
                warn(what + " has yfov " + numberText(p.yfov) + " rad; Lit uses " + numberText(out.yfov));
            out.aspectRatio = static_cast<float>(std::max(p.aspectRatio, 0.0));
            if (p.znear > 0.0)
                out.znear = static_cast<float>(p.znear);
            else
                warn(what + " has znear " + numberText(p.znear) + "; Lit uses " + numberText(out.znear));
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

Scene Importer::run() {
    Scene scene;
    scene.sourcePath = source_.path;
    const std::vector<int> nodeRefs = loadNodes(scene);
    if (scene.name.empty()) {
        scene.name = source_.path.stem().string();
        scene.fileSceneNamed = false;
    }
    loadMaterials(scene);  // before the meshes: their tangents and UV sets follow their materials
    importMeshes(source_, scene);
    loadTextures(scene);
    importImages(source_, scene);
    report("scene", 0, 1);
    loadLights(scene);
    loadCameras(scene);
    importSkins(source_, nodeRefs, scene);
    importAnimations(source_, nodeRefs, scene);
    keepFileData(source_, nodeRefs, scene);
    scene.updateWorldTransforms();
    report("scene", 1, 1);
    return scene;
}

}  // namespace

Scene importScene(const GltfSource& source) { return Importer(source).run(); }

}  // namespace lit::gltfimport
