// glTF meshes → Scene::meshes (scene/GltfImportMeshes.h).

#include "scene/GltfImportMeshes.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/GltfImportKept.h"
#include "scene/GltfKeep.h"
#include "scene/GltfValidate.h"
#include "scene/Tangents.h"

namespace lit::gltfimport {

namespace {

// How far from 1 a tangent's length may be and still count as unit (float32 rounding of its
// components is a few 1e-8; exporters write normalized float32 tangents).
constexpr float kUnitTangentTolerance = 1e-6f;

// The normal texture's place in Material's per-reference arrays (scene/Scene.h).
constexpr std::size_t kNormalSlot = 2;

// The material a primitive draws with (already imported: Importer::run loads the materials
// first), nullptr for the default one.
const Material* materialOf(const Scene& scene, int material) {
    if (material < 0 || static_cast<std::size_t>(material) >= scene.materials.size()) return nullptr;
    return &scene.materials[static_cast<std::size_t>(material)];
}

// The first of the material's texture references drawn with TEXCOORD_1, nullptr when none is.
const char* referenceReadingUvSet1(const Material* m) {
    if (!m) return nullptr;
    static constexpr std::array<const char*, 5> kSlotNames = {"baseColorTexture", "metallicRoughnessTexture",
                                                              "normalTexture", "emissiveTexture", "occlusionTexture"};
    const std::array<int, 5> textures = {m->baseColorTexture, m->metallicRoughnessTexture, m->normalTexture,
                                         m->emissiveTexture, m->occlusionTexture};
    for (std::size_t slot = 0; slot < textures.size(); ++slot)
        if (textures[slot] >= 0 && drawnTexCoord(*m, slot) == 1) return kSlotNames[slot];
    for (const ExtensionTextureSlot& slot : kExtensionTextureSlots)
        if (const ExtensionTexture& t = m->*slot.member; t.texture >= 0 && drawnTexCoord(t) == 1) return slot.key;
    return nullptr;
}

void importPrimitive(const GltfSource& source, const Material* material, const tinygltf::Primitive& in,
                     const std::string& meshName, std::size_t primitiveIndex, Primitive& out) {
    const std::string where = "mesh '" + meshName + "' primitive " + std::to_string(primitiveIndex);
    const auto attribute = [&](const char* name) {
        auto it = in.attributes.find(name);
        return it == in.attributes.end() ? -1 : it->second;
    };
    const int positionIndex = attribute("POSITION");
    if (positionIndex < 0) source.fail(where + " has no POSITION attribute");
    const AccessorData positions = readAccessor(source, positionIndex, TINYGLTF_TYPE_VEC3, "POSITION of " + where);
    const std::size_t vertexCount = positions.count;
    if (vertexCount > std::numeric_limits<std::uint32_t>::max())
        source.fail(where + " has " + std::to_string(vertexCount) + " vertices, more than 32-bit indices can address");

    out.vertices.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i)
        out.vertices[i].position = {positions.component(i, 0), positions.component(i, 1), positions.component(i, 2)};

    const auto checkCount = [&](const AccessorData& a, int index, const char* name) {
        if (a.count != vertexCount)
            source.fail("accessor " + std::to_string(index) + " (" + name + " of " + where + ") has " +
                        std::to_string(a.count) + " elements, but POSITION has " + std::to_string(vertexCount));
    };

    const int normalIndex = attribute("NORMAL");
    if (normalIndex >= 0) {
        const AccessorData normals = readAccessor(source, normalIndex, TINYGLTF_TYPE_VEC3, "NORMAL of " + where);
        checkCount(normals, normalIndex, "NORMAL");
        for (std::size_t i = 0; i < vertexCount; ++i)
            out.vertices[i].normal = {normals.component(i, 0), normals.component(i, 1), normals.component(i, 2)};
    }
    const int uvIndex = attribute("TEXCOORD_0");
    if (uvIndex >= 0) {
        const AccessorData uvs = readAccessor(source, uvIndex, TINYGLTF_TYPE_VEC2, "TEXCOORD_0 of " + where);
        checkCount(uvs, uvIndex, "TEXCOORD_0");
        for (std::size_t i = 0; i < vertexCount; ++i) out.vertices[i].uv = {uvs.component(i, 0), uvs.component(i, 1)};
    }
    const int uv1Index = attribute("TEXCOORD_1");
    if (uv1Index >= 0) {
        const AccessorData uvs = readAccessor(source, uv1Index, TINYGLTF_TYPE_VEC2, "TEXCOORD_1 of " + where);
        checkCount(uvs, uv1Index, "TEXCOORD_1");
        for (std::size_t i = 0; i < vertexCount; ++i) out.vertices[i].uv1 = {uvs.component(i, 0), uvs.component(i, 1)};
    } else {
        for (Vertex& v : out.vertices) v.uv1 = v.uv;
        if (const char* reference = referenceReadingUvSet1(material))
            source.warn(where + " has no TEXCOORD_1, which its material's " + reference +
                        " reads; drawn with TEXCOORD_0");
    }
    // A file's tangents are only meaningful with the file's normals (glTF 2.0 §3.7.2.1).
    const int tangentIndex = normalIndex >= 0 ? attribute("TANGENT") : -1;
    bool haveTangents = false;
    if (tangentIndex >= 0) {
        const AccessorData tangents = readAccessor(source, tangentIndex, TINYGLTF_TYPE_VEC4, "TANGENT of " + where);
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
        if (!haveTangents) source.warn(where + " has zero or non-finite TANGENTs; they are recomputed");
        if (haveTangents && !allUnit) {
            out.fileTangents.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i)
                for (int c = 0; c < 4; ++c) out.fileTangents[i][c] = tangents.component(i, c);
        }
    }

    // Indices: from the accessor, or 0..n−1 for non-indexed geometry.
    if (in.indices >= 0) {
        out.indices = readIndices(source, in.indices, vertexCount, where);
    } else {
        out.indices.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) out.indices[i] = static_cast<std::uint32_t>(i);
    }
    if (out.indices.size() % 3 != 0) {
        source.warn(where + " has " + std::to_string(out.indices.size()) +
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
        source.warn(where + " has " + std::to_string(nonFinite) + " vertex position" + (nonFinite == 1 ? "" : "s") +
                    " that are not finite (NaN or infinity); the " +
                    std::to_string((out.indices.size() - kept.size()) / 3) + " triangle(s) using them are dropped");
        out.indices = std::move(kept);
    }

    // The attributes and morph targets Lit does not draw with, kept for a save.
    out.keptAttributes =
        keptAttributes(source, in.attributes, {"POSITION", "NORMAL", "TEXCOORD_0", "TANGENT"}, where, vertexCount);
    out.morphTargets = keptTargets(source, in, where, vertexCount);
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
    // A normal map is painted in the frame of its own UVs (the base's, else the clear coat's;
    // both share the one tangent frame).
    if (!haveTangents) {
        int tangentSet = 0;
        if (material && material->normalTexture >= 0)
            tangentSet = drawnTexCoord(*material, kNormalSlot);
        else if (material && material->clearcoatNormalTexture.texture >= 0)
            tangentSet = drawnTexCoord(material->clearcoatNormalTexture);
        computeTangents(out, tangentSet);
    }
    out.fileHasTangents = haveTangents;
    out.kept = gltfkeep::keep(in.extras, in.extensions);
    // How the file stored the drawn data and what its accessors held besides the values, for a
    // save (scene/Scene.h: Primitive::fileAccessors).
    {
        // Every drawn attribute in a buffer view (not sparse): written in the file's views again.
        bool inViews = true;
        const auto keepInfo = [&](const char* name, int index) {
            if (index < 0) return;
            const tinygltf::Accessor& a = source.model.accessors[static_cast<std::size_t>(index)];
            inViews = inViews && a.bufferView >= 0 && !a.sparse.isSparse;
            out.fileAccessors[name] = keptAccessorInfo(source, index);
        };
        keepInfo("POSITION", positionIndex);
        keepInfo("NORMAL", normalIndex);
        keepInfo("TEXCOORD_0", uvIndex);
        keepInfo("TANGENT", haveTangents ? tangentIndex : -1);
        out.fileViews = inViews;
        if (in.indices >= 0) {
            out.fileIndexType = source.model.accessors[static_cast<std::size_t>(in.indices)].componentType;
            out.fileAccessors["indices"] = keptAccessorInfo(source, in.indices);
        } else {
            out.fileIndexType = 0;
        }
    }
    for (const Vertex& v : out.vertices)
        if (std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z))
            out.bounds.extend(v.position);  // the non-finite ones belong to no triangle (above)
}

}  // namespace

void importMeshes(const GltfSource& source, Scene& scene) {
    scene.meshes.reserve(source.model.meshes.size());
    source.report("meshes", 0, source.model.meshes.size());
    for (std::size_t m = 0; m < source.model.meshes.size(); ++m) {
        const tinygltf::Mesh& in = source.model.meshes[m];
        Mesh mesh;
        mesh.name = in.name.empty() ? "mesh " + std::to_string(m) : in.name;
        for (std::size_t p = 0; p < in.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = in.primitives[p];
            const std::string where = "mesh '" + mesh.name + "' primitive " + std::to_string(p);
            // tinygltf reports an absent mode as -1; glTF's default is TRIANGLES.
            if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES) {
                std::optional<KeptPrimitive> kept = keptPrimitive(source, prim, where);
                source.warn(where + " has mode " + std::to_string(prim.mode) + " (only TRIANGLES is drawn); " +
                            (kept ? "not drawn, kept for saving" : "skipped"));
                if (kept) mesh.otherPrimitives.push_back(std::move(*kept));
                continue;
            }
            if (prim.material >= 0 && static_cast<std::size_t>(prim.material) >= source.model.materials.size())
                source.fail(where + " refers to material " + std::to_string(prim.material) +
                            ", which is out of range (the file has " + std::to_string(source.model.materials.size()) +
                            " materials)");
            if (!prim.targets.empty())
                source.warn(where +
                            " has morph targets; Lit draws the base shape (the targets are kept and saved back)");
            Primitive out;
            out.material = prim.material;
            importPrimitive(source, materialOf(scene, prim.material), prim, mesh.name, p, out);
            if (out.indices.empty()) {
                source.warn(where + " has no triangles; skipped");
                continue;
            }
            mesh.primitives.push_back(std::move(out));
        }
        mesh.weights = in.weights;
        mesh.kept = gltfkeep::keep(in.extras, in.extensions);
        scene.meshes.push_back(std::move(mesh));
        source.report("meshes", m + 1, source.model.meshes.size());
    }
}

}  // namespace lit::gltfimport
