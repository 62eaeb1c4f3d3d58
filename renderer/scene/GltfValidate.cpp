// Checks of a glTF file's data (scene/GltfValidate.h). Each message names the object, the index
// and the numbers that disagree, so a user can find the problem in the file.

#include "scene/GltfValidate.h"

#include "scene/GltfKeep.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string_view>

namespace lit::gltfimport {

std::string describeNode(const tinygltf::Model& model, std::size_t index) {
    const std::string& name = model.nodes[index].name;
    return "node " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
}

float AccessorData::component(std::size_t i, int c) const {
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
            return 0.0f;  // rejected by readAccessor()
    }
}

std::uint32_t AccessorData::index(std::size_t i) const {
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
            return 0;  // rejected by readAccessor()
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

AccessorData readAccessor(const GltfSource& source, int index, int expectedType, const std::string& role) {
    const std::string what = "accessor " + std::to_string(index) + " (" + role + ")";
    if (index < 0 || static_cast<std::size_t>(index) >= source.model.accessors.size())
        source.fail("accessor index " + std::to_string(index) + " (" + role + ") is out of range: the file has " +
                    std::to_string(source.model.accessors.size()) + " accessors");
    const tinygltf::Accessor& a = source.model.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) source.fail(what + " is a sparse accessor, which Lit does not support");
    if (a.type != expectedType)
        source.fail(what + " has type " + typeName(a.type) + ", expected " + typeName(expectedType));
    const int size = gltfkeep::componentBytes(a.componentType);
    if (size == 0) source.fail(what + " has unsupported component type " + std::to_string(a.componentType));
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT && expectedType != TINYGLTF_TYPE_SCALAR)
        source.fail(what + " has component type UNSIGNED_INT, which glTF allows only for indices");

    AccessorData data;
    data.count = a.count;
    data.componentType = a.componentType;
    data.components = componentsOf(a.type);
    data.normalized = a.normalized;
    if (a.count == 0) return data;
    if (a.bufferView < 0) source.fail(what + " has no buffer view (all-zero accessors are not supported)");
    if (static_cast<std::size_t>(a.bufferView) >= source.model.bufferViews.size())
        source.fail(what + " refers to buffer view " + std::to_string(a.bufferView) +
                    ", which does not exist (the file has " + std::to_string(source.model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = source.model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::string viewName = "buffer view " + std::to_string(a.bufferView);
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= source.model.buffers.size())
        source.fail(viewName + " (used by " + what + ") refers to buffer " + std::to_string(view.buffer) +
                    ", which does not exist (the file has " + std::to_string(source.model.buffers.size()) + ")");
    const tinygltf::Buffer& buffer = source.model.buffers[static_cast<std::size_t>(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
        source.fail(viewName + " (used by " + what + ") extends past the end of buffer " + std::to_string(view.buffer) +
                    " (offset " + std::to_string(view.byteOffset) + " + length " + std::to_string(view.byteLength) +
                    " > " + std::to_string(buffer.data.size()) + " bytes)");

    const std::size_t elementSize = static_cast<std::size_t>(size) * static_cast<std::size_t>(data.components);
    data.stride = view.byteStride ? view.byteStride : elementSize;
    if (data.stride < elementSize)
        source.fail(viewName + " (used by " + what + ") has byteStride " + std::to_string(view.byteStride) +
                    ", smaller than one element (" + std::to_string(elementSize) + " bytes)");
    // The last byte read is byteOffset + (count − 1)·stride + elementSize; compare without overflow.
    const std::size_t available = view.byteLength;
    const bool fits = a.byteOffset <= available && elementSize <= available - a.byteOffset &&
                      (a.count - 1) <= (available - a.byteOffset - elementSize) / data.stride;
    if (!fits)
        source.fail(what + " reads past the end of " + viewName + " (offset " + std::to_string(a.byteOffset) + ", " +
                    std::to_string(a.count) + " elements of " + std::to_string(elementSize) + " bytes every " +
                    std::to_string(data.stride) + " bytes; the view has " + std::to_string(available) + " bytes)");
    data.first = buffer.data.data() + view.byteOffset + a.byteOffset;
    return data;
}

std::pair<const unsigned char*, std::size_t> viewElements(const GltfSource& source, const std::string& what,
                                                          int viewIndex, std::size_t byteOffset,
                                                          std::size_t elementSize, std::size_t count, bool strided) {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= source.model.bufferViews.size())
        source.fail(what + " refers to buffer view " + std::to_string(viewIndex) +
                    ", which does not exist (the file has " + std::to_string(source.model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = source.model.bufferViews[static_cast<std::size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= source.model.buffers.size())
        source.fail(what + ": buffer view " + std::to_string(viewIndex) + " refers to buffer " +
                    std::to_string(view.buffer) + ", which does not exist");
    const tinygltf::Buffer& buffer = source.model.buffers[static_cast<std::size_t>(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
        source.fail(what + ": buffer view " + std::to_string(viewIndex) + " extends past the end of its buffer");
    const std::size_t stride = strided && view.byteStride ? view.byteStride : elementSize;
    if (stride < elementSize)
        source.fail(what + ": buffer view " + std::to_string(viewIndex) + " has a byteStride smaller than one element");
    const std::size_t available = view.byteLength;
    const bool fits = count == 0 || (byteOffset <= available && elementSize <= available - byteOffset &&
                                     (count - 1) <= (available - byteOffset - elementSize) / stride);
    if (!fits) source.fail(what + " reads past the end of buffer view " + std::to_string(viewIndex));
    return {buffer.data.data() + view.byteOffset + byteOffset, stride};
}

std::vector<std::uint32_t> readIndices(const GltfSource& source, int accessor, std::size_t vertexCount,
                                       const std::string& where) {
    // The type first: a float index accessor would otherwise be reported as reading past its view.
    const int indexType = static_cast<std::size_t>(accessor) < source.model.accessors.size()
                              ? source.model.accessors[static_cast<std::size_t>(accessor)].componentType
                              : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        source.fail("accessor " + std::to_string(accessor) + " (indices of " + where +
                    ") must have an unsigned integer component type (5121, 5123 or 5125), not " +
                    std::to_string(indexType));
    const AccessorData indices = readAccessor(source, accessor, TINYGLTF_TYPE_SCALAR, "indices of " + where);
    std::vector<std::uint32_t> out(indices.count);
    for (std::size_t i = 0; i < indices.count; ++i) {
        const std::uint32_t value = indices.index(i);
        if (value >= vertexCount)
            source.fail(where + ": index " + std::to_string(i) + " has the value " + std::to_string(value) +
                        ", which is out of range (the primitive has " + std::to_string(vertexCount) + " vertices)");
        out[i] = value;
    }
    return out;
}

std::vector<int> checkNodeTree(const GltfSource& source) {
    const std::size_t n = source.model.nodes.size();
    // Parents, with every index checked, and the tree property (one parent per node) enforced.
    std::vector<int> parent(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        for (int child : source.model.nodes[i].children) {
            if (child < 0 || static_cast<std::size_t>(child) >= n)
                source.fail(describeNode(source.model, i) + " has child index " + std::to_string(child) +
                            ", which is out of range (the file has " + std::to_string(n) + " nodes)");
            const auto c = static_cast<std::size_t>(child);
            if (c == i) source.fail("node cycle: " + describeNode(source.model, i) + " is its own child");
            if (parent[c] >= 0)
                source.fail(describeNode(source.model, c) + " is a child of both node " + std::to_string(parent[c]) +
                            " and node " + std::to_string(i) + " (a node may have only one parent)");
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
                std::string cycle = describeNode(source.model, i);
                for (std::size_t j = static_cast<std::size_t>(parent[i]); j != i;
                     j = static_cast<std::size_t>(parent[j]))
                    cycle = describeNode(source.model, j) + " → " + cycle;
                source.fail("node cycle: " + describeNode(source.model, i) + " is its own ancestor (" + cycle + ")");
            }
            state[i] = 1;
            walk.push_back(i);
            if (parent[i] < 0) break;
            i = static_cast<std::size_t>(parent[i]);
        }
        for (std::size_t j : walk) state[j] = 2;
    }
    return parent;
}

void checkExtensions(const GltfSource& source) {
    // Extensions whose data the loader reads. KHR_mesh_quantization only widens the accessor
    // types allowed for attributes, which the generic accessor reader handles.
    static const std::array<std::string_view, 3> supported = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                              "KHR_mesh_quantization"};
    const auto isSupported = [&](const std::string& e) {
        return std::find(supported.begin(), supported.end(), e) != supported.end();
    };
    for (const std::string& e : source.model.extensionsRequired)
        if (!isSupported(e)) source.fail("requires the glTF extension " + e + ", which Lit does not support");
    for (const std::string& e : source.model.extensionsUsed)
        if (!isSupported(e))
            source.warn("ignores the glTF extension " + e +
                        " (not supported; its data is kept and saved back as it was)");
}

int checkedTextureIndex(const GltfSource& source, int index, const std::string& what) {
    if (index < -1 || index >= static_cast<int>(source.model.textures.size()))
        source.fail(what + " refers to texture " + std::to_string(index) + ", which is out of range (the file has " +
                    std::to_string(source.model.textures.size()) + " textures)");
    return index;
}

}  // namespace lit::gltfimport
