// Writing back what the glTF import kept without drawing it (scene/GltfExportDetail.h; what Lit
// draws is scene/GltfExport.cpp, the buffer's layout scene/GltfFileLayout.cpp).
//
// Decisions worth knowing:
// - What the loader kept (scene/Scene.h: KeptAccessor and friends) is written back in its own
//   component types: extra vertex attributes and morph targets (one buffer view each, strides
//   padded to 4 bytes), primitives of other modes, skins (joints remapped like the nodes; a skin
//   with a joint that is no longer written is left out), node and mesh weights, texture
//   coordinate sets and orthographic cameras. Kept per-vertex data whose element count no longer
//   matches the primitive's vertices (an edit rebuilt them) is left out.
// - Kept accessors that were sparse are written sparse (KeptAccessor::Sparse), with a new layout
//   where an edit made the file's wrong (resparse).
// - Animation outputs are written in the file's component type (normalized integer rotations
//   and weights); key times shared by samplers are written once.
// - Names, extras and extensions of the file's accessors, buffer views and buffers go on the
//   accessor or view that holds the same data again (kept attributes, sparse data, embedded
//   images, animation data, drawn geometry while unedited); the one buffer gets those of all the
//   file's buffers.

#include "scene/GltfExportDetail.h"
#include "scene/GltfKeep.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace lit::gltfexport {

namespace {

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

int typeCode(const std::string& type) {
    static const std::map<std::string, int> codes = {{"SCALAR", TINYGLTF_TYPE_SCALAR}, {"VEC2", TINYGLTF_TYPE_VEC2},
                                                     {"VEC3", TINYGLTF_TYPE_VEC3},     {"VEC4", TINYGLTF_TYPE_VEC4},
                                                     {"MAT2", TINYGLTF_TYPE_MAT2},     {"MAT3", TINYGLTF_TYPE_MAT3},
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
// (the file's, or wider). It stays sparse so the parts' names, extras and extensions, which a
// dense accessor cannot hold, survive the edit. Where the base is kept, the file's base elements
// stay under its indices; under an index past the file's base, the element itself.
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
            const std::uint8_t* under =
                baseKnown && fileSlot[i] != kNotSparse ? file.baseBytes.data() + fileSlot[i] * elementSize : element;
            out.baseBytes.insert(out.baseBytes.end(), under, under + elementSize);
        }
    }
    if (out.indices.empty()) {  // glTF: sparse.count ≥ 1; element 0 over its own base (or zero over zeros)
        out.indices.push_back(0);
        if (file.hasBase)
            out.baseBytes.assign(kept.bytes.begin(), kept.bytes.begin() + static_cast<std::ptrdiff_t>(elementSize));
    }
    const std::uint32_t last = out.indices.back();
    const int wanted = last < 256u ? 1 : last < 65536u ? 2 : 4;
    const int size = std::max(wanted, sparseIndexBytes(file.indexComponentType));
    out.indexComponentType = size == 1   ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
                             : size == 2 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                         : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    return out;
}

}  // namespace

// Gives object `index` of the file's `array` ("accessors", "bufferViews") the name, extras and
// extensions it had: tinygltf 2.7 writes no extensions for these, so they go in as a JSON patch.
template <class Object>
void ModelBuilder::keepNameAndExtras(Object& out, const char* array, int index, const std::string& name,
                                     const KeptGltf& kept) {
    out.name = name;
    tinygltf::ExtensionMap extensions;
    restore(kept, out.extras, extensions);
    if (!kept.extensions.empty())
        jsonPatches_.emplace_back("/" + std::string(array) + "/" + std::to_string(index) + "/extensions",
                                  kept.extensions);
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

// Min and max of a written accessor's elements (its buffer view, or zeros, with its sparse values
// put in), per component.
std::pair<std::vector<double>, std::vector<double>> ModelBuilder::minMaxOf(int index) const {
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (components <= 0 || a.count == 0) return {};
    const std::size_t elementSize =
        static_cast<std::size_t>(gltfkeep::componentBytes(a.componentType)) * static_cast<std::size_t>(components);
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
            const auto target =
                static_cast<std::size_t>(componentValue(indices, a.sparse.indices.componentType, static_cast<int>(s)));
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
        const nlohmann::json e =
            nlohmann::json::parse(kept.kept.extensions.empty() ? "{}" : kept.kept.extensions, nullptr, false);
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
                fail(named("kept node", static_cast<std::size_t>(child),
                           scene_.keptNodes[static_cast<std::size_t>(child)].name) +
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

int ModelBuilder::addKeptAccessor(const KeptAccessor& kept, int target) {
    const int type = typeCode(kept.type);
    if (type < 0 || kept.count == 0 || kept.bytes.size() % kept.count != 0)
        fail("kept accessor data of type '" + kept.type + "' is inconsistent (" + std::to_string(kept.bytes.size()) +
             " bytes for " + std::to_string(kept.count) + " elements)");
    const std::size_t elementSize = kept.bytes.size() / kept.count;
    if (!kept.sparse) {
        const int shared =
            sharedAccessor(kept.info.file, kept.componentType, type, kept.normalized, kept.bytes.data(), kept.count);
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
            std::memcpy(base.data() + sparse->indices[s] * elementSize, sparse->baseBytes.data() + s * elementSize,
                        elementSize);
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
            std::memcpy(indices.data() + s * static_cast<std::size_t>(indexSize), &index,
                        static_cast<std::size_t>(indexSize));  // little-endian
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
        const auto key = [](const KeptAccessor* k) {
            return k->info.file >= 0 ? k->info.file : std::numeric_limits<int>::max();
        };
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

// The optional fields the file wrote (Material::fileFields) go back even where they hold glTF's
// default, which tinygltf leaves out: as JSON patches of the values being written. Texture
// reference fields only while the material still has that texture.
void ModelBuilder::keepMaterialFields(const Material& material, const tinygltf::Material& out, std::size_t index) {
    const auto number = [](double v) { return nlohmann::json(v).dump(); };
    const auto numbers = [](const std::vector<double>& v) { return nlohmann::json(v).dump(); };
    const tinygltf::PbrMetallicRoughness& pbr = out.pbrMetallicRoughness;
    for (const std::string& field : material.fileFields) {
        std::optional<std::string> value;
        if (field == "alphaCutoff")
            value = number(out.alphaCutoff);
        else if (field == "alphaMode")
            value = nlohmann::json(out.alphaMode).dump();
        else if (field == "doubleSided")
            value = nlohmann::json(out.doubleSided).dump();
        else if (field == "emissiveFactor")
            value = numbers(out.emissiveFactor);
        else if (field == "pbrMetallicRoughness/baseColorFactor")
            value = numbers(pbr.baseColorFactor);
        else if (field == "pbrMetallicRoughness/metallicFactor")
            value = number(pbr.metallicFactor);
        else if (field == "pbrMetallicRoughness/roughnessFactor")
            value = number(pbr.roughnessFactor);
        else if (field == "pbrMetallicRoughness/baseColorTexture/texCoord" && pbr.baseColorTexture.index >= 0)
            value = std::to_string(pbr.baseColorTexture.texCoord);
        else if (field == "pbrMetallicRoughness/metallicRoughnessTexture/texCoord" &&
                 pbr.metallicRoughnessTexture.index >= 0)
            value = std::to_string(pbr.metallicRoughnessTexture.texCoord);
        else if (field == "normalTexture/texCoord" && out.normalTexture.index >= 0)
            value = std::to_string(out.normalTexture.texCoord);
        else if (field == "normalTexture/scale" && out.normalTexture.index >= 0)
            value = number(out.normalTexture.scale);
        else if (field == "emissiveTexture/texCoord" && out.emissiveTexture.index >= 0)
            value = std::to_string(out.emissiveTexture.texCoord);
        else if (field == "occlusionTexture/texCoord" && out.occlusionTexture.index >= 0)
            value = std::to_string(out.occlusionTexture.texCoord);
        else if (field == "occlusionTexture/strength" && out.occlusionTexture.index >= 0)
            value = number(out.occlusionTexture.strength);
        if (value) jsonPatches_.emplace_back("/materials/" + std::to_string(index) + "/" + field, *value);
    }
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
        const bool valid =
            std::all_of(animation.samplers.begin(), animation.samplers.end(), [](const Animation::Sampler& s) {
                return s.components >= 1 && s.components <= 4 && !s.input.empty() &&
                       s.output.size() % static_cast<std::size_t>(s.components) == 0;
            });
        if (!valid) continue;
        tinygltf::Animation out;
        out.name = animation.name;
        for (const Animation::Channel& channel : animation.channels) {
            const int node = writtenNode(channel.node);
            if (node < 0 || channel.sampler < 0 ||
                static_cast<std::size_t>(channel.sampler) >= animation.samplers.size())
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
                input = addAccessor(inputView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR,
                                    sampler.input.size());
                const auto [lo, hi] = std::minmax_element(sampler.input.begin(), sampler.input.end());
                model_.accessors[static_cast<std::size_t>(input)].minValues = {*lo};
                model_.accessors[static_cast<std::size_t>(input)].maxValues = {*hi};
                keepAccessor(input, sampler.inputInfo);
                if (sampler.fileInput >= 0) writtenInputs_[sampler.fileInput] = {input, &sampler.input};
            }
            int output = -1;
            if (const auto shared = writtenOutputs_.find(sampler.fileOutput);
                sampler.fileOutput >= 0 && shared != writtenOutputs_.end() &&
                shared->second.second->output == sampler.output &&
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
                jsonPatches_.emplace_back(at + std::to_string(out.samplers.size()) + "/extensions",
                                          sampler.kept.extensions);
            out.samplers.push_back(std::move(s));
        }
        restore(animation.kept, out.extras, out.extensions);
        model_.animations.push_back(std::move(out));
    }
}

}  // namespace lit::gltfexport
