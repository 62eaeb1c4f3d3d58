// Scene meshes → glTF meshes, accessors and buffer views (scene/GltfExportDetail.h): a drawn
// primitive's vertices in the file's views (scene/Scene.h: Primitive::fileViews): attributes the
// file kept in one view in one view again (one per view, blocks one after the other, or
// interleaved at the file's offsets and stride), or else in one interleaved view (the head of
// lit::Vertex as it is in memory: POSITION, NORMAL, TEXCOORD_0, TANGENT every 48 bytes); indices
// in the file's component type while they fit, else UNSIGNED_INT. Accessors in the file's order,
// one the file shared written once while the values agree, so an unedited file keeps its accessor
// indices.

#include "scene/GltfExportDetail.h"
#include "scene/GltfKeep.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace lit::gltfexport {

namespace {

template <int N>
std::vector<double> doubles(const glm::vec<N, float>& v) {
    std::vector<double> out(N);
    for (int i = 0; i < N; ++i) out[static_cast<std::size_t>(i)] = v[i];
    return out;
}

}  // namespace

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
        std::all_of(primitive.vertices.begin(), primitive.vertices.end(),
                    [](const Vertex& v) { return v.uv == glm::vec2(0.0f); }))
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
            std::stable_sort(group.begin(), group.end(), [&](const Attribute& a, const Attribute& b) {
                return fileIndex(a.name) < fileIndex(b.name);
            });
            writes.emplace_back(fileIndex(group.front().name),
                                [&, group] { addAttributeView(group, *vertices, primitive, p); });
        }
    } else {
        int first = std::numeric_limits<int>::max();
        for (const Attribute& a : attributes) first = std::min(first, fileIndex(a.name));
        writes.emplace_back(first, [&] {
            // One interleaved view: the head of lit::Vertex as it is in memory, 48 bytes a vertex
            // with tangents, 32 without (uv1 is not in it: TEXCOORD_1 is a kept attribute).
            const std::size_t packedStride = offsetof(Vertex, tangent) + (tangents ? sizeof(glm::vec4) : 0);
            std::vector<unsigned char> packed(count * packedStride);
            for (std::size_t v = 0; v < count; ++v)
                std::memcpy(packed.data() + v * packedStride, &(*vertices)[v], packedStride);
            const int view = addBufferView(packed.data(), packed.size(), kArrayBuffer, packedStride);
            std::vector<Attribute> inFileOrder = attributes;
            std::stable_sort(inFileOrder.begin(), inFileOrder.end(), [&](const Attribute& a, const Attribute& b) {
                return fileIndex(a.name) < fileIndex(b.name);
            });
            for (const Attribute& a : inFileOrder)
                p.attributes[a.name] = addAccessor(view, a.offset, TINYGLTF_COMPONENT_TYPE_FLOAT, a.type, count);
            setPositionBounds(p.attributes["POSITION"], primitive);
            for (const Attribute& a : attributes) keepFile(p.attributes[a.name], a.name);
        });
    }
    for (const auto& [name, accessor] : primitive.keptAttributes)
        writes.emplace_back(accessor.info.file >= 0 ? accessor.info.file : std::numeric_limits<int>::max(),
                            [&, name = name] {
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
            if (primitive.fileIndexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && largest < 0xFFFFu)
                type = primitive.fileIndexType;
            if (primitive.fileIndexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && largest < 0xFFu)
                type = primitive.fileIndexType;
            std::vector<unsigned char> bytes;
            if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                const std::vector<std::uint16_t> narrow(primitive.indices.begin(), primitive.indices.end());
                bytes.assign(reinterpret_cast<const unsigned char*>(narrow.data()),
                             reinterpret_cast<const unsigned char*>(narrow.data() + narrow.size()));
            } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                bytes.assign(primitive.indices.begin(), primitive.indices.end());
            } else {
                bytes.assign(
                    reinterpret_cast<const unsigned char*>(primitive.indices.data()),
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
            std::memcpy(packed[k].data() + v * a.bytes, reinterpret_cast<const unsigned char*>(&vertices[v]) + a.offset,
                        a.bytes);
        const KeptAccessorInfo* info = fileInfo(a.name);
        shared[k] = sharedAccessor(info ? info->file : -1, TINYGLTF_COMPONENT_TYPE_FLOAT, a.type, false,
                                   packed[k].data(), count);
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
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return fileOffset[a] < fileOffset[b]; });
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
        static_cast<std::size_t>(gltfkeep::componentBytes(componentType)) *
        static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type)));
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::size_t stride = view.byteStride ? view.byteStride : elementSize;
    const unsigned char* first =
        model_.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset + a.byteOffset;
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
            if (kept.indices && kept.indices->count > 0)
                p.indices = addKeptAccessor(*kept.indices, kElementArrayBuffer);
            restore(kept.kept, p.extras, p.extensions);
            out.primitives.push_back(std::move(p));
        }
        if (out.primitives.empty()) continue;  // glTF requires at least one primitive per mesh
        // Default morph weights, while every primitive still has that many targets (glTF rule).
        if (!mesh.weights.empty() &&
            std::all_of(out.primitives.begin(), out.primitives.end(),
                        [&](const tinygltf::Primitive& p) { return p.targets.size() == mesh.weights.size(); }))
            out.weights = mesh.weights;
        restore(mesh.kept, out.extras, out.extensions);
        meshIndex_[m] = static_cast<int>(model_.meshes.size());
        model_.meshes.push_back(std::move(out));
    }
}

}  // namespace lit::gltfexport
