#include "scene/Tangents.h"

#include <cmath>
#include <cstddef>

namespace lit {

namespace {

// Any unit vector perpendicular to `n` (n need not be unit length, but must not be zero).
glm::vec3 anyPerpendicular(const glm::vec3& n) {
    // Cross with the world axis least aligned with n, so the result never degenerates.
    const glm::vec3 a =
        std::abs(n.x) < 0.9f * glm::length(n) ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(n, a));
}

bool finiteVec(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A usable unit normal: the vertex normal, or +Y where the data holds a zero or non-finite normal.
glm::vec3 safeNormal(const glm::vec3& n) {
    const float len = glm::length(n);
    if (!std::isfinite(len) || len < 1e-12f) return {0.0f, 1.0f, 0.0f};
    return n / len;
}

}  // namespace

void computeTangents(Primitive& primitive, int uvSet) {
    std::vector<Vertex>& vertices = primitive.vertices;
    const std::vector<std::uint32_t>& indices = primitive.indices;
    // Per vertex: the accumulated directions of increasing u (tangent) and of increasing v.
    std::vector<glm::vec3> uDirection(vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> vDirection(vertices.size(), glm::vec3(0.0f));

    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
        if (i0 >= vertices.size() || i1 >= vertices.size() || i2 >= vertices.size()) continue;
        const Vertex& v0 = vertices[i0];
        const Vertex& v1 = vertices[i1];
        const Vertex& v2 = vertices[i2];
        const glm::vec3 e1 = v1.position - v0.position;
        const glm::vec3 e2 = v2.position - v0.position;
        const auto uvOf = [uvSet](const Vertex& v) { return uvSet == 1 ? v.uv1 : v.uv; };
        const glm::vec2 d1 = uvOf(v1) - uvOf(v0);
        const glm::vec2 d2 = uvOf(v2) - uvOf(v0);
        // Solve [e1 e2] = [dP/du dP/dv] · [d1 d2] (Lengyel, "Computing Tangent Space Basis
        // Vectors for an Arbitrary Mesh", 2001). det is twice the signed UV-space area.
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (!std::isfinite(det) || std::abs(det) < 1e-20f) continue;  // degenerate UVs: no information
        const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
        const float lu = glm::length(dPdu), lv = glm::length(dPdv);
        if (!(lu > 0.0f) || !(lv > 0.0f) || !std::isfinite(lu) || !std::isfinite(lv)) continue;
        // Weight by the triangle's area so slivers do not dominate a vertex's average; the
        // directions are normalised first so the UV scale of a triangle does not matter either.
        const float area = 0.5f * glm::length(glm::cross(e1, e2));
        if (!std::isfinite(area)) continue;
        const glm::vec3 su = dPdu / lu * area;
        const glm::vec3 sv = dPdv / lv * area;
        for (std::uint32_t i : {i0, i1, i2}) {
            uDirection[i] += su;
            vDirection[i] += sv;
        }
    }

    for (std::size_t i = 0; i < vertices.size(); ++i) {
        Vertex& vertex = vertices[i];
        const glm::vec3 n = safeNormal(vertex.normal);
        // Gram-Schmidt: remove the normal's component so the tangent lies in the surface.
        glm::vec3 t = uDirection[i] - n * glm::dot(n, uDirection[i]);
        const float len = glm::length(t);
        if (!finiteVec(t) || len < 1e-12f) {
            vertex.tangent = glm::vec4(anyPerpendicular(n), 1.0f);
            continue;
        }
        t /= len;
        // glTF: bitangent = cross(normal, tangent.xyz) * w, and it points towards decreasing v
        // (texture space +Y is "up" in the image, and v grows downwards).
        const float w = glm::dot(glm::cross(n, t), -vDirection[i]) < 0.0f ? -1.0f : 1.0f;
        vertex.tangent = glm::vec4(t, w);
    }
}

void computeNormals(Primitive& primitive) {
    // glTF 2.0 §3.7.2.1: without NORMAL, "client implementations MUST calculate flat normals".
    // A vertex shared by triangles of different orientation cannot hold a flat normal for each,
    // so the primitive is unwelded first: every index gets its own vertex. The face normal is
    // the normalised cross product (its length is twice the area, the weight once unwelded).
    std::vector<Vertex> unwelded;
    unwelded.reserve(primitive.indices.size());
    const std::size_t triangleIndexCount = primitive.indices.size() - primitive.indices.size() % 3;
    for (std::size_t t = 0; t < triangleIndexCount; t += 3) {
        Vertex corner[3];
        bool valid = true;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t index = primitive.indices[t + static_cast<std::size_t>(k)];
            if (index >= primitive.vertices.size()) {
                valid = false;
                break;
            }
            corner[k] = primitive.vertices[index];
        }
        if (!valid) continue;
        const glm::vec3 cross =
            glm::cross(corner[1].position - corner[0].position, corner[2].position - corner[0].position);
        const float len = glm::length(cross);
        // Zero-area triangles have no orientation; +Y keeps the data finite (they cover no pixels).
        const glm::vec3 normal = (std::isfinite(len) && len > 0.0f) ? cross / len : glm::vec3(0.0f, 1.0f, 0.0f);
        for (Vertex& v : corner) {
            v.normal = normal;
            unwelded.push_back(v);
        }
    }
    primitive.vertices = std::move(unwelded);
    primitive.indices.resize(primitive.vertices.size());
    for (std::size_t i = 0; i < primitive.indices.size(); ++i) primitive.indices[i] = static_cast<std::uint32_t>(i);
}

}  // namespace lit
