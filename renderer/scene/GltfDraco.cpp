// KHR_draco_mesh_compression decoding (scene/GltfDraco.h). The extension's specification:
// https://github.com/KhronosGroup/glTF/tree/main/extensions/2.0/Khronos/KHR_draco_mesh_compression

#include "scene/GltfDraco.h"

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>

#include "scene/GltfKeep.h"
#include "scene/GltfLoader.h"
#include "scene/GltfValidate.h"

namespace lit::gltfimport {

namespace {

// A buffer view of `byteLength` bytes at the end of buffer `decoded`, 4-byte aligned (every
// component type's alignment); returns the view's index and a pointer to its bytes.
std::pair<int, unsigned char*> appendView(tinygltf::Model& model, int decoded, std::size_t byteLength) {
    std::vector<unsigned char>& bytes = model.buffers[static_cast<std::size_t>(decoded)].data;
    const std::size_t offset = (bytes.size() + 3) & ~std::size_t(3);
    bytes.resize(offset + byteLength, 0);
    tinygltf::BufferView view;
    view.buffer = decoded;
    view.byteOffset = offset;
    view.byteLength = byteLength;
    model.bufferViews.push_back(view);
    return {static_cast<int>(model.bufferViews.size() - 1), bytes.data() + offset};
}

// Component `c` of each of `count` values converted by draco to T, written tightly packed.
template <typename T>
bool writeAttribute(const draco::PointAttribute& attribute, std::size_t count, int components, unsigned char* out) {
    T value[16];
    for (std::size_t i = 0; i < count; ++i) {
        const draco::AttributeValueIndex index =
            attribute.mapped_index(draco::PointIndex(static_cast<std::uint32_t>(i)));
        if (index.value() >= attribute.size()) return false;
        if (!attribute.ConvertValue<T>(index, static_cast<std::int8_t>(components), value)) return false;
        std::memcpy(out + i * sizeof(T) * static_cast<std::size_t>(components), value,
                    sizeof(T) * static_cast<std::size_t>(components));
    }
    return true;
}

bool writeAttribute(int componentType, const draco::PointAttribute& attribute, std::size_t count, int components,
                    unsigned char* out) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return writeAttribute<float>(attribute, count, components, out);
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return writeAttribute<std::int8_t>(attribute, count, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return writeAttribute<std::uint8_t>(attribute, count, components, out);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return writeAttribute<std::int16_t>(attribute, count, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return writeAttribute<std::uint16_t>(attribute, count, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return writeAttribute<std::uint32_t>(attribute, count, components, out);
        default:
            return false;
    }
}

const tinygltf::Accessor& accessorAt(const std::string& what, const tinygltf::Model& model, int index,
                                     const std::string& role) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        throw SceneLoadError(what + ": the " + role + " accessor " + std::to_string(index) +
                             " does not exist (the file has " + std::to_string(model.accessors.size()) + ")");
    return model.accessors[static_cast<std::size_t>(index)];
}

}  // namespace

void decodeDracoPrimitive(const std::string& what, const nlohmann::json& extension,
                          const tinygltf::Primitive& primitive, tinygltf::Model& model, int decoded) {
    const std::string where = what + ": KHR_draco_mesh_compression";
    if (!extension.is_object() || !extension.contains("bufferView") || !extension["bufferView"].is_number_unsigned() ||
        !extension.contains("attributes") || !extension["attributes"].is_object())
        throw SceneLoadError(where + " needs a 'bufferView' index and an 'attributes' object");
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1)
        throw SceneLoadError(where + ": Lit decodes Draco triangle meshes only (the primitive's mode is " +
                             std::to_string(primitive.mode) + ")");
    if (primitive.indices < 0) throw SceneLoadError(where + ": the primitive has no indices accessor");

    // The compressed bytes, inside their buffer.
    const std::uint64_t viewIndex = extension["bufferView"].get<std::uint64_t>();
    if (viewIndex >= model.bufferViews.size())
        throw SceneLoadError(where + " names buffer view " + std::to_string(viewIndex) +
                             ", which does not exist (the file has " + std::to_string(model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size() || view.buffer == decoded)
        throw SceneLoadError(where + ": buffer view " + std::to_string(viewIndex) + " names buffer " +
                             std::to_string(view.buffer) + ", which does not exist");
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
        throw SceneLoadError(where + ": buffer view " + std::to_string(viewIndex) + " (offset " +
                             std::to_string(view.byteOffset) + ", " + std::to_string(view.byteLength) +
                             " bytes) lies outside its buffer (" + std::to_string(buffer.size()) + " bytes)");

    // libdraco reads only inside the DecoderBuffer and reports malformed data as a status.
    draco::DecoderBuffer input;
    input.Init(reinterpret_cast<const char*>(buffer.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&input);
    if (!result.ok())
        throw SceneLoadError(where + ": the Draco data in buffer view " + std::to_string(viewIndex) + " (" +
                             std::to_string(view.byteLength) +
                             " bytes) does not decode: " + result.status().error_msg_string());
    const std::unique_ptr<draco::Mesh> mesh = std::move(result).value();
    if (!mesh) throw SceneLoadError(where + ": the Draco data holds no mesh");
    const std::size_t points = mesh->num_points();

    // Indices: three per face, in the index accessor's type.
    {
        const tinygltf::Accessor& indices = accessorAt(where, model, primitive.indices, "indices");
        const std::size_t count = static_cast<std::size_t>(mesh->num_faces()) * 3;
        if (indices.count != count)
            throw SceneLoadError(where + " decodes " + std::to_string(mesh->num_faces()) + " triangles (" +
                                 std::to_string(count) + " indices) but the indices accessor " +
                                 std::to_string(primitive.indices) + " has " + std::to_string(indices.count));
        if (indices.type != TINYGLTF_TYPE_SCALAR)
            throw SceneLoadError(where + ": the indices accessor " + std::to_string(primitive.indices) +
                                 " is not SCALAR");
        const int size = indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                         : indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                         : indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                           : 0;
        if (size == 0)
            throw SceneLoadError(where + ": the indices accessor " + std::to_string(primitive.indices) +
                                 " has component type " + std::to_string(indices.componentType) +
                                 ", not an unsigned integer type");
        const std::uint64_t largest = size == 1 ? 0xFFu : size == 2 ? 0xFFFFu : 0xFFFFFFFFu;
        const auto [index, out] = appendView(model, decoded, count * static_cast<std::size_t>(size));
        for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
            const draco::Mesh::Face& face = mesh->face(f);
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t value = face[c].value();
                if (value >= points || value > largest)
                    throw SceneLoadError(where + ": decoded triangle " + std::to_string(f.value()) + " names point " +
                                         std::to_string(value) + " (the mesh has " + std::to_string(points) +
                                         " points; the index type holds up to " + std::to_string(largest) + ")");
                unsigned char* at = out + (static_cast<std::size_t>(f.value()) * 3 + static_cast<std::size_t>(c)) *
                                              static_cast<std::size_t>(size);
                if (size == 1) *at = static_cast<std::uint8_t>(value);
                if (size == 2) {
                    const auto v16 = static_cast<std::uint16_t>(value);
                    std::memcpy(at, &v16, 2);
                }
                if (size == 4) std::memcpy(at, &value, 4);
            }
        }
        tinygltf::Accessor& target = model.accessors[static_cast<std::size_t>(primitive.indices)];
        target.bufferView = index;
        target.byteOffset = 0;
    }

    // The attributes the extension names, each by its Draco unique id.
    const nlohmann::json& ids = extension["attributes"];
    for (auto it = ids.begin(); it != ids.end(); ++it) {
        const auto named = primitive.attributes.find(it.key());
        if (named == primitive.attributes.end())
            throw SceneLoadError(where + " lists the attribute " + it.key() + ", which the primitive does not have");
        if (!it.value().is_number_unsigned() ||
            it.value().get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max())
            throw SceneLoadError(where + ": the Draco id of " + it.key() + " is " + it.value().dump() +
                                 ", not an unsigned integer");
        const draco::PointAttribute* attribute =
            mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(it.value().get<std::uint64_t>()));
        if (!attribute)
            throw SceneLoadError(where + ": the Draco data has no attribute with id " + it.value().dump() + " (" +
                                 it.key() + ")");
        const tinygltf::Accessor& accessor = accessorAt(where, model, named->second, it.key());
        if (accessor.count != points)
            throw SceneLoadError(where + " decodes " + std::to_string(points) + " points but the " + it.key() +
                                 " accessor " + std::to_string(named->second) + " has " +
                                 std::to_string(accessor.count));
        const int componentSize = gltfkeep::componentBytes(accessor.componentType);
        const int components = componentsOf(accessor.type);
        if (componentSize == 0 || components == 0)
            throw SceneLoadError(where + ": the " + it.key() + " accessor " + std::to_string(named->second) +
                                 " is not a SCALAR or VECn of a glTF component type");
        const std::size_t elementSize = static_cast<std::size_t>(componentSize) * static_cast<std::size_t>(components);
        const auto [index, out] = appendView(model, decoded, points * elementSize);
        if (!writeAttribute(accessor.componentType, *attribute, points, components, out))
            throw SceneLoadError(where + ": the Draco attribute " + it.key() +
                                 " cannot be converted to the accessor's type");
        tinygltf::Accessor& target = model.accessors[static_cast<std::size_t>(named->second)];
        target.bufferView = index;
        target.byteOffset = 0;
    }
}

}  // namespace lit::gltfimport
