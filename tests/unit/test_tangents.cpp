// Tangent frames and computed normals (renderer/scene/Tangents.cpp).

#include <gtest/gtest.h>

#include <cmath>

#include "scene/Tangents.h"

namespace lit {
namespace {

Vertex vertex(glm::vec3 position, glm::vec2 uv, glm::vec3 normal = {0.0f, 0.0f, 1.0f}) {
    Vertex v;
    v.position = position;
    v.uv = uv;
    v.normal = normal;
    v.tangent = glm::vec4(0.0f);  // so a tangent that is never written shows up as zero
    return v;
}

// A unit quad in the XY plane facing +Z, with the texture upright as glTF lays it out: the UV
// origin is the image's top-left corner, so v grows downwards (towards −Y).
Primitive uprightQuad() {
    Primitive p;
    p.vertices = {vertex({-1, 1, 0}, {0, 0}), vertex({1, 1, 0}, {1, 0}), vertex({1, -1, 0}, {1, 1}),
                  vertex({-1, -1, 0}, {0, 1})};
    p.indices = {0, 3, 2, 0, 2, 1};  // counter-clockwise seen from +Z
    return p;
}

void expectUnitAndOrthogonal(const Vertex& v) {
    const glm::vec3 t(v.tangent);
    EXPECT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(t, glm::normalize(v.normal)), 0.0f, 1e-5f);
    EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f) << "w = " << v.tangent.w;
}

TEST(Tangents, UprightQuadHasTangentAlongUAndPositiveHandedness) {
    Primitive p = uprightQuad();
    computeTangents(p);
    for (const Vertex& v : p.vertices) {
        expectUnitAndOrthogonal(v);
        // u grows along +X, so the tangent is +X.
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);
        EXPECT_NEAR(v.tangent.y, 0.0f, 1e-5f);
        EXPECT_NEAR(v.tangent.z, 0.0f, 1e-5f);
        // glTF: bitangent = cross(N, T)·w must point up the image (decreasing v) = +Y here.
        EXPECT_EQ(v.tangent.w, 1.0f);
        const glm::vec3 bitangent = glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w;
        EXPECT_NEAR(bitangent.y, 1.0f, 1e-5f);
    }
}

TEST(Tangents, MirroredUvsFlipHandedness) {
    // Flipping v (texture mirrored vertically) keeps the tangent and negates w.
    Primitive p = uprightQuad();
    for (Vertex& v : p.vertices) v.uv.y = 1.0f - v.uv.y;
    computeTangents(p);
    for (const Vertex& v : p.vertices) {
        expectUnitAndOrthogonal(v);
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);
        EXPECT_EQ(v.tangent.w, -1.0f);
    }
}

TEST(Tangents, RotatedUvsGiveRotatedTangent) {
    // u grows along −Y: tangent is −Y.
    Primitive p = uprightQuad();
    for (Vertex& v : p.vertices) v.uv = {1.0f - (v.position.y + 1.0f) * 0.5f, (v.position.x + 1.0f) * 0.5f};
    computeTangents(p);
    for (const Vertex& v : p.vertices) {
        expectUnitAndOrthogonal(v);
        EXPECT_NEAR(v.tangent.y, -1.0f, 1e-5f);
    }
}

// A normal texture that reads TEXCOORD_1 is painted in that set's frame: the tangents follow uv1.
TEST(Tangents, SecondUvSetGivesItsOwnFrame) {
    Primitive p = uprightQuad();
    for (Vertex& v : p.vertices) v.uv1 = {1.0f - (v.position.y + 1.0f) * 0.5f, (v.position.x + 1.0f) * 0.5f};
    Primitive first = p;
    computeTangents(first);
    computeTangents(p, 1);
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        expectUnitAndOrthogonal(p.vertices[i]);
        EXPECT_NEAR(p.vertices[i].tangent.y, -1.0f, 1e-5f);     // u1 grows along −Y
        EXPECT_NEAR(first.vertices[i].tangent.x, 1.0f, 1e-5f);  // u along +X
    }
}

TEST(Tangents, TangentIsOrthogonalisedAgainstATiltedNormal) {
    Primitive p = uprightQuad();
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.5f, 0.2f, 1.0f));
    for (Vertex& v : p.vertices) v.normal = tilted;
    computeTangents(p);
    for (const Vertex& v : p.vertices) {
        expectUnitAndOrthogonal(v);
        EXPECT_GT(v.tangent.x, 0.8f);  // still mostly along u
    }
}

TEST(Tangents, DegenerateUvsGiveAFiniteUnitPerpendicularTangent) {
    Primitive p = uprightQuad();
    for (Vertex& v : p.vertices) v.uv = {0.5f, 0.5f};  // all UVs equal: no UV gradient at all
    computeTangents(p);
    for (const Vertex& v : p.vertices) expectUnitAndOrthogonal(v);

    // A normal along +X is the case where a naive "cross with X" fallback would fail.
    Primitive q = uprightQuad();
    for (Vertex& v : q.vertices) {
        v.uv = {0.0f, 0.0f};
        v.normal = {1.0f, 0.0f, 0.0f};
    }
    computeTangents(q);
    for (const Vertex& v : q.vertices) expectUnitAndOrthogonal(v);
}

TEST(Tangents, ZeroNormalDoesNotProduceNaN) {
    Primitive p = uprightQuad();
    p.vertices[0].normal = glm::vec3(0.0f);
    computeTangents(p);
    for (const Vertex& v : p.vertices) {
        EXPECT_TRUE(std::isfinite(v.tangent.x) && std::isfinite(v.tangent.y) && std::isfinite(v.tangent.z));
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
    }
}

TEST(Normals, FlatNormalsFollowWindingAndUnweldSharedVertices) {
    // Two triangles sharing an edge, folded 90° along it: one faces +Z, the other +Y. Smooth
    // normals would average them at the shared vertices; flat normals must not.
    Primitive p;
    p.vertices = {vertex({0, 0, 0}, {0, 0}), vertex({1, 0, 0}, {1, 0}), vertex({0, 1, 0}, {0, 1}),
                  vertex({0, 0, -1}, {1, 1})};
    p.indices = {0, 1, 2, 0, 1, 3};
    computeNormals(p);
    ASSERT_EQ(p.vertices.size(), 6u);
    ASSERT_EQ(p.indices.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(p.indices[i], i);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(glm::distance(p.vertices[static_cast<std::size_t>(k)].normal, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::distance(p.vertices[static_cast<std::size_t>(3 + k)].normal, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    }
    // Attributes travel with the unwelded vertices.
    EXPECT_EQ(p.vertices[4].position, glm::vec3(1, 0, 0));
    EXPECT_EQ(p.vertices[5].uv, glm::vec2(1, 1));
}

TEST(Normals, DegenerateTriangleGetsAFiniteNormal) {
    Primitive p;
    p.vertices = {vertex({0, 0, 0}, {0, 0}), vertex({1, 1, 1}, {1, 0}), vertex({2, 2, 2}, {0, 1})};
    p.indices = {0, 1, 2};
    computeNormals(p);
    ASSERT_EQ(p.vertices.size(), 3u);
    for (const Vertex& v : p.vertices) EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace lit
