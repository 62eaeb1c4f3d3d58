// Reading what the glTF import keeps without drawing (scene/GltfImportKept.h). The writer
// writes it back (scene/GltfExportKept.cpp).

#include "scene/GltfImportKept.h"

#include "animation/CameraPathIO.h"
#include "scene/GltfKeep.h"
#include "scene/GltfValidate.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <utility>

namespace lit::gltfimport {

KeptObject keptView(const GltfSource& source, int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= source.model.bufferViews.size()) return {};
    const tinygltf::BufferView& view = source.model.bufferViews[static_cast<std::size_t>(index)];
    return KeptObject{view.name, gltfkeep::keep(view.extras, view.extensions)};
}

KeptAccessorInfo keptAccessorInfo(const GltfSource& source, int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= source.model.accessors.size()) return {};
    const tinygltf::Accessor& a = source.model.accessors[static_cast<std::size_t>(index)];
    const std::size_t stride =
        a.bufferView >= 0 && static_cast<std::size_t>(a.bufferView) < source.model.bufferViews.size()
            ? source.model.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride
            : 0;
    return KeptAccessorInfo{a.name,
                            gltfkeep::keep(a.extras, a.extensions),
                            keptView(source, a.bufferView),
                            a.minValues,
                            a.maxValues,
                            index,
                            stride,
                            a.bufferView,
                            a.byteOffset};
}

KeptAccessor keptAccessor(const GltfSource& source, int index, const std::string& role,
                          std::optional<std::size_t> expectedCount) {
    const std::string what = "accessor " + std::to_string(index) + " (" + role + ")";
    if (index < 0 || static_cast<std::size_t>(index) >= source.model.accessors.size())
        source.fail("accessor index " + std::to_string(index) + " (" + role + ") is out of range: the file has " +
                    std::to_string(source.model.accessors.size()) + " accessors");
    const tinygltf::Accessor& a = source.model.accessors[static_cast<std::size_t>(index)];
    const int size = gltfkeep::componentBytes(a.componentType);
    if (size == 0) source.fail(what + " has unsupported component type " + std::to_string(a.componentType));
    const int components = elementComponents(a.type);
    if (components == 0) source.fail(what + " has an unknown type");
    // Matrices of 1- or 2-byte components have padded columns; glTF uses none for attributes.
    if ((a.type == TINYGLTF_TYPE_MAT2 || a.type == TINYGLTF_TYPE_MAT3) && size < 4)
        source.fail(what + " is a " + typeName(a.type) + " of " + std::to_string(size) +
                    "-byte components, which Lit does not keep");
    if (expectedCount && a.count != *expectedCount)
        source.fail(what + " has " + std::to_string(a.count) + " elements, expected " + std::to_string(*expectedCount));
    if (!expectedCount && a.bufferView < 0) source.fail(what + " has no buffer view");

    // A validated pointer to `count` elements of `elementSize` bytes, `stride` apart, in a view.
    const auto viewData = [&](int viewIndex, std::size_t byteOffset, std::size_t elementSize, std::size_t count,
                              bool strided) {
        return viewElements(source, what, viewIndex, byteOffset, elementSize, count, strided);
    };

    const std::size_t elementSize = static_cast<std::size_t>(size) * static_cast<std::size_t>(components);
    KeptAccessor out;
    out.type = typeName(a.type);
    out.componentType = a.componentType;
    out.normalized = a.normalized;
    out.count = a.count;
    out.info = keptAccessorInfo(source, index);
    std::pair<const unsigned char*, std::size_t> base{nullptr, 0};
    if (a.bufferView >= 0 && a.count > 0) base = viewData(a.bufferView, a.byteOffset, elementSize, a.count, true);
    out.bytes.assign(a.count * elementSize, 0);  // no buffer view: zeros (glTF §3.6.2.3)
    if (base.first) {
        const auto [first, stride] = base;
        for (std::size_t i = 0; i < a.count; ++i)
            std::memcpy(out.bytes.data() + i * elementSize, first + i * stride, elementSize);
    }
    if (a.sparse.isSparse && a.sparse.count > 0) {
        const auto count = static_cast<std::size_t>(a.sparse.count);
        if (count > a.count)
            source.fail(what + " has more sparse elements (" + std::to_string(count) + ") than elements");
        const int indexSize = gltfkeep::componentBytes(a.sparse.indices.componentType);
        if (a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            source.fail(what + "'s sparse indices must be unsigned integers");
        const auto indices =
            viewData(a.sparse.indices.bufferView, static_cast<std::size_t>(std::max(a.sparse.indices.byteOffset, 0)),
                     static_cast<std::size_t>(indexSize), count, false);
        const auto values =
            viewData(a.sparse.values.bufferView, static_cast<std::size_t>(std::max(a.sparse.values.byteOffset, 0)),
                     elementSize, count, false);
        KeptAccessor::Sparse sparse;
        sparse.indexComponentType = a.sparse.indices.componentType;
        sparse.indicesView = keptView(source, a.sparse.indices.bufferView);
        sparse.valuesView = keptView(source, a.sparse.values.bufferView);
        if (const auto found = source.sparseKept.find(index); found != source.sparseKept.end())
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
                source.fail(what + " has the sparse index " + std::to_string(target) + ", out of range (" +
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

KeptAttributes keptAttributes(const GltfSource& source, const std::map<std::string, int>& attributes,
                              std::initializer_list<std::string_view> skip, const std::string& where,
                              std::size_t vertexCount) {
    KeptAttributes out;
    for (const auto& [name, index] : attributes) {
        if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
        try {
            out[name] = keptAccessor(source, index, name + " of " + where, vertexCount);
        } catch (const SceneLoadError& e) {
            source.warn(std::string(e.what()) + "; the attribute is not kept");
        }
    }
    return out;
}

std::vector<KeptAttributes> keptTargets(const GltfSource& source, const tinygltf::Primitive& in,
                                        const std::string& where, std::size_t vertexCount) {
    std::vector<KeptAttributes> out;
    for (std::size_t t = 0; t < in.targets.size(); ++t)
        out.push_back(keptAttributes(source, in.targets[t], {}, "morph target " + std::to_string(t) + " of " + where,
                                     vertexCount));
    return out;
}

// A primitive of a mode Lit does not draw, as the file had it; none when its data is unusable.
std::optional<KeptPrimitive> keptPrimitive(const GltfSource& source, const tinygltf::Primitive& in,
                                           const std::string& where) {
    const auto position = in.attributes.find("POSITION");
    if (position == in.attributes.end() || position->second < 0 ||
        static_cast<std::size_t>(position->second) >= source.model.accessors.size())
        return std::nullopt;
    const tinygltf::Accessor& positions = source.model.accessors[static_cast<std::size_t>(position->second)];
    if (positions.bufferView < 0) return std::nullopt;  // its count is not bounded by the file's data
    KeptPrimitive out;
    out.mode = in.mode;
    out.material = in.material;
    try {
        // All attributes must be readable here: a line primitive missing one is worse than none.
        for (const auto& [name, index] : in.attributes)
            out.attributes[name] = keptAccessor(source, index, name + " of " + where, positions.count);
        if (in.indices >= 0) out.indices = keptAccessor(source, in.indices, "indices of " + where, std::nullopt);
        for (std::size_t t = 0; t < in.targets.size(); ++t) {
            KeptAttributes target;
            for (const auto& [name, index] : in.targets[t])
                target[name] = keptAccessor(
                    source, index, name + " of morph target " + std::to_string(t) + " of " + where, positions.count);
            out.morphTargets.push_back(std::move(target));
        }
    } catch (const SceneLoadError& e) {
        source.warn(e.what());
        return std::nullopt;
    }
    out.kept = gltfkeep::keep(in.extras, in.extensions);
    return out;
}

// Skins, kept for saving: joints as Scene node indices, inverse bind matrices as floats. A skin
// whose joints are not all imported keeps a joint of -1, and a save leaves it out.
void importSkins(const GltfSource& source, const std::vector<int>& nodeRefs, Scene& scene) {
    for (std::size_t s = 0; s < source.model.skins.size(); ++s) {
        const tinygltf::Skin& in = source.model.skins[s];
        const std::string what = "skin " + std::to_string(s) + (in.name.empty() ? "" : " ('" + in.name + "')");
        Skin out;
        out.name = in.name;
        const auto node = [&](int index) {
            return index >= 0 && static_cast<std::size_t>(index) < nodeRefs.size()
                       ? nodeRefs[static_cast<std::size_t>(index)]
                       : -1;
        };
        for (int joint : in.joints) out.joints.push_back(node(joint));
        if (std::find(out.joints.begin(), out.joints.end(), -1) != out.joints.end())
            source.warn(what + " has joints that do not exist; it is not saved back");
        out.skeleton = node(in.skeleton);
        if (in.inverseBindMatrices >= 0) {
            try {
                const KeptAccessor matrices =
                    keptAccessor(source, in.inverseBindMatrices, "inverseBindMatrices of " + what, in.joints.size());
                if (matrices.type != "MAT4" || matrices.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                    source.fail(what + "'s inverseBindMatrices are not MAT4 floats");
                out.inverseBindMatrices.resize(matrices.bytes.size() / sizeof(float));
                out.inverseBindMatricesInfo = matrices.info;
                std::memcpy(out.inverseBindMatrices.data(), matrices.bytes.data(), matrices.bytes.size());
            } catch (const SceneLoadError& e) {
                source.warn(std::string(e.what()) + "; the skin is not saved back");
                out.joints.assign(out.joints.size(), -1);
            }
        }
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        scene.skins.push_back(std::move(out));
    }
}

// Every animation, as floats, for the writer to save back (Lit plays camera paths only). One
// that cannot be read is reported and left out; the load goes on.
void importAnimations(const GltfSource& source, const std::vector<int>& nodeRefs, Scene& scene) {
    for (std::size_t a = 0; a < source.model.animations.size(); ++a) {
        const tinygltf::Animation& in = source.model.animations[a];
        const std::string what = "animation " + std::to_string(a) + (in.name.empty() ? "" : " ('" + in.name + "')");
        Animation out;
        out.name = in.name;
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        try {
            for (std::size_t i = 0; i < in.samplers.size(); ++i) {
                const tinygltf::AnimationSampler& s = in.samplers[i];
                const std::string where = what + " sampler " + std::to_string(i);
                if (s.output < 0 || static_cast<std::size_t>(s.output) >= source.model.accessors.size())
                    source.fail(where + " has no valid output accessor");
                const int outputType = source.model.accessors[static_cast<std::size_t>(s.output)].type;
                const AccessorData input = readAccessor(source, s.input, TINYGLTF_TYPE_SCALAR, "input of " + where);
                const AccessorData output = readAccessor(source, s.output, outputType, "output of " + where);
                Animation::Sampler sampler;
                sampler.interpolation = s.interpolation.empty() ? "LINEAR" : s.interpolation;
                sampler.components = output.components;
                sampler.kept = gltfkeep::keep(s.extras, s.extensions);
                sampler.inputInfo = keptAccessorInfo(source, s.input);
                sampler.outputInfo = keptAccessorInfo(source, s.output);
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
                    source.fail(what + " has a channel with sampler " + std::to_string(c.sampler) +
                                ", which does not exist");
                if (c.target_node < 0 || static_cast<std::size_t>(c.target_node) >= nodeRefs.size()) continue;
                const int node = nodeRefs[static_cast<std::size_t>(c.target_node)];
                if (node == -1) continue;
                out.channels.push_back({c.sampler, node, c.target_path, gltfkeep::keep(c.extras, c.extensions)});
            }
        } catch (const SceneLoadError& e) {
            source.warn(std::string(e.what()) + "; the animation is not kept");
            continue;
        }
        scene.animations.push_back(std::move(out));
    }
    scene.cameraAnimationNames = cameraAnimationNames(source.model);
}

// The file-level data Lit does not use, for a lossless save.
void keepFileData(const GltfSource& source, const std::vector<int>& nodeRefs, Scene& scene) {
    const int sceneIndex =
        source.model.defaultScene >= 0 ? source.model.defaultScene : (source.model.scenes.empty() ? -1 : 0);
    if (sceneIndex >= 0) {
        const tinygltf::Scene& s = source.model.scenes[static_cast<std::size_t>(sceneIndex)];
        scene.kept = gltfkeep::keep(s.extras, s.extensions);
    }
    scene.fileKept = gltfkeep::keep(source.model.extras, source.model.extensions, {"KHR_lights_punctual"});
    scene.copyright = source.model.asset.copyright;
    scene.generator = source.model.asset.generator;
    for (const tinygltf::Buffer& buffer : source.model.buffers) {
        scene.buffers.push_back(KeptObject{buffer.name, gltfkeep::keep(buffer.extras, buffer.extensions)});
        scene.fileBufferSizes.push_back(buffer.data.size());
    }
    // A compressed file's layout (compressed streams, fallback buffers) means nothing to the
    // uncompressed save: its views are not kept, and a save lays the buffer out afresh.
    scene.decodedCompression = source.compression;
    if (!source.compression.empty()) scene.fileBufferSizes.clear();
    for (const tinygltf::BufferView& view : source.model.bufferViews) {
        if (!source.compression.empty()) break;
        Scene::FileBufferView place{view.buffer, view.byteOffset, view.byteLength, 0};
        const std::vector<unsigned char>* data =
            view.buffer >= 0 && static_cast<std::size_t>(view.buffer) < source.model.buffers.size()
                ? &source.model.buffers[static_cast<std::size_t>(view.buffer)].data
                : nullptr;
        if (data && view.byteOffset <= data->size() && view.byteLength <= data->size() - view.byteOffset)
            place.hash = gltfkeep::hashBytes(data->data() + view.byteOffset, view.byteLength);
        else
            place.buffer = -1;  // never matched (the loader reports views it reads past their buffer)
        scene.fileBufferViews.push_back(place);
    }
    scene.assetKept = gltfkeep::keep(source.model.asset.extras, source.model.asset.extensions);
    // The other scenes.
    scene.sceneIndex = std::max(sceneIndex, 0);
    for (std::size_t i = 0; i < source.model.scenes.size(); ++i) {
        if (static_cast<int>(i) == sceneIndex) continue;
        const tinygltf::Scene& s = source.model.scenes[i];
        Scene::OtherScene other{s.name, {}, gltfkeep::keep(s.extras, s.extensions)};
        // Its roots: nodes the shown scene shares, or kept nodes (scene/Scene.h: keptNodeRef).
        for (int root : s.nodes) {
            const int mapped = root >= 0 && static_cast<std::size_t>(root) < nodeRefs.size()
                                   ? nodeRefs[static_cast<std::size_t>(root)]
                                   : -1;
            if (mapped == -1)
                source.warn("scene " + std::to_string(i) + (s.name.empty() ? "" : " ('" + s.name + "')") +
                            " lists node " + std::to_string(root) + ", which does not exist; a save leaves it out");
            else if (std::find(other.roots.begin(), other.roots.end(), mapped) == other.roots.end())
                other.roots.push_back(mapped);
        }
        scene.otherScenes.push_back(std::move(other));
    }
    static const std::array<std::string_view, 8> own = {
        "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_texture_transform", "EXT_texture_webp",
        "KHR_materials_ior",   "KHR_materials_specular",          "KHR_materials_clearcoat", "KHR_materials_sheen"};
    for (const std::string& e : source.model.extensionsUsed)
        if (std::find(own.begin(), own.end(), e) == own.end()) scene.unknownExtensionsUsed.push_back(e);
    scene.extensionsRequired = source.model.extensionsRequired;
}

}  // namespace lit::gltfimport
