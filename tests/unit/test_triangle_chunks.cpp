// Splitting large primitives into chunks for culling (renderer/scene/TriangleChunks.h): every
// triangle lands in exactly one chunk with its winding, each chunk's box holds its triangles,
// chunks are spatially compact, and small primitives are left as they are.

#include "scene/TriangleChunks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <stdexcept>
#include <vector>

namespace lit {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::vector<Triangle> trianglesOf(const std::vector<std::uint32_t>& indices) {
    std::vector<Triangle> out;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) out.push_back({indices[i], indices[i + 1], indices[i + 2]});
    return out;
}

// A flat n×n grid of quads in the XZ plane (2 n² triangles), its triangles in shuffled order so
// that index order says nothing about position.
struct Grid {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
};
Grid shuffledGrid(int n, unsigned seed) {
    Grid g;
    for (int z = 0; z <= n; ++z)
        for (int x = 0; x <= n; ++x) {
            Vertex v;
            v.position = glm::vec3(static_cast<float>(x), 0.0f, static_cast<float>(z));
            g.vertices.push_back(v);
        }
    std::vector<Triangle> triangles;
    const auto at = [n](int x, int z) { return static_cast<std::uint32_t>(z * (n + 1) + x); };
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            triangles.push_back({at(x, z), at(x + 1, z), at(x + 1, z + 1)});
            triangles.push_back({at(x, z), at(x + 1, z + 1), at(x, z + 1)});
        }
    std::mt19937 rng(seed);
    std::shuffle(triangles.begin(), triangles.end(), rng);
    for (const Triangle& t : triangles) g.indices.insert(g.indices.end(), t.begin(), t.end());
    return g;
}

bool contains(const Aabb& box, const glm::vec3& p) {
    return glm::all(glm::greaterThanEqual(p, box.min)) && glm::all(glm::lessThanEqual(p, box.max));
}

// Chunks are contiguous, in order, cover the whole index buffer, hold at most `max` triangles,
// and the reordered buffer holds the same triangles (same corner order) as before.
void expectPartition(const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& before,
                     const std::vector<std::uint32_t>& after, const std::vector<TriangleChunk>& chunks,
                     std::uint32_t max) {
    ASSERT_EQ(before.size(), after.size());
    std::uint32_t next = 0;
    for (const TriangleChunk& c : chunks) {
        EXPECT_EQ(c.firstIndex, next) << "chunks must be contiguous and in index order";
        EXPECT_GT(c.indexCount, 0u);
        EXPECT_EQ(c.indexCount % 3, 0u);
        EXPECT_LE(c.indexCount / 3, max);
        for (std::uint32_t i = c.firstIndex; i < c.firstIndex + c.indexCount; ++i)
            ASSERT_TRUE(contains(c.bounds, vertices[after[i]].position)) << "index " << i << " outside its chunk's box";
        next = c.firstIndex + c.indexCount;
    }
    EXPECT_EQ(next, after.size()) << "chunks must cover every triangle";
    std::vector<Triangle> a = trianglesOf(before), b = trianglesOf(after);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_TRUE(a == b) << "every triangle exactly once, corners in their original order (winding)";
}

TEST(TriangleChunks, LargeGridSplitsIntoCompactChunksCoveringEveryTriangleOnce) {
    Grid g = shuffledGrid(64, 7);  // 8192 triangles
    const std::vector<std::uint32_t> before = g.indices;
    const std::vector<TriangleChunk> chunks = splitIntoChunks(g.vertices, g.indices, 500);
    expectPartition(g.vertices, before, g.indices, chunks, 500);
    // Median splits halve the count: 8192 → 16 chunks of 512 would exceed 500, so 32 of 256.
    EXPECT_EQ(chunks.size(), 32u);
    // Compact: the chunks tile the 64×64 plane with little overlap (a split by index order of the
    // shuffled triangles would give 32 boxes each covering nearly the whole plane).
    float area = 0.0f;
    for (const TriangleChunk& c : chunks) {
        area += c.bounds.size().x * c.bounds.size().z;
        EXPECT_EQ(c.bounds.size().y, 0.0f);
    }
    EXPECT_LE(area, 1.25f * 64.0f * 64.0f) << "chunk boxes overlap: the split is not spatial";
}

TEST(TriangleChunks, ChunkBoxesAreTightAroundTheirTriangles) {
    // Random triangles of random size in a 10 m cube: each box is exactly its triangles' box.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coord(-5.0f, 5.0f);
    std::vector<Vertex> vertices(3000);
    for (Vertex& v : vertices) v.position = glm::vec3(coord(rng), coord(rng), coord(rng));
    std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(vertices.size() - 1));
    std::vector<std::uint32_t> indices(3 * 5001);
    for (std::uint32_t& i : indices) i = pick(rng);
    const std::vector<std::uint32_t> before = indices;
    const std::vector<TriangleChunk> chunks = splitIntoChunks(vertices, indices, 1000);
    expectPartition(vertices, before, indices, chunks, 1000);
    EXPECT_GE(chunks.size(), 6u);
    for (const TriangleChunk& c : chunks) {
        Aabb tight;
        for (std::uint32_t i = c.firstIndex; i < c.firstIndex + c.indexCount; ++i) tight.extend(vertices[indices[i]].position);
        EXPECT_EQ(c.bounds.min, tight.min);
        EXPECT_EQ(c.bounds.max, tight.max);
    }
}

TEST(TriangleChunks, SmallPrimitivesAndSplittingOffKeepTheirOrder) {
    Grid g = shuffledGrid(8, 3);  // 128 triangles
    const std::vector<std::uint32_t> before = g.indices;
    for (const std::uint32_t max : {128u, 1000u, 0u}) {
        const std::vector<TriangleChunk> chunks = splitIntoChunks(g.vertices, g.indices, max);
        ASSERT_EQ(chunks.size(), 1u) << "max " << max;
        EXPECT_EQ(chunks[0].firstIndex, 0u);
        EXPECT_EQ(chunks[0].indexCount, before.size());
        EXPECT_TRUE(g.indices == before) << "an unsplit primitive must keep its index order";
        EXPECT_EQ(chunks[0].bounds.min, glm::vec3(0.0f));
        EXPECT_EQ(chunks[0].bounds.max, glm::vec3(8.0f, 0.0f, 8.0f));
    }
    std::vector<std::uint32_t> none;
    EXPECT_TRUE(splitIntoChunks(g.vertices, none, 4).empty());
    // Just over the limit: two chunks.
    const std::vector<TriangleChunk> two = splitIntoChunks(g.vertices, g.indices, 127);
    EXPECT_EQ(two.size(), 2u);
    expectPartition(g.vertices, before, g.indices, two, 127);
}

TEST(TriangleChunks, CoincidentCentroidsStillSplit) {
    // 100 copies of one triangle: no axis separates them, the median split must still halve.
    std::vector<Vertex> vertices(3);
    vertices[1].position = glm::vec3(1.0f, 0.0f, 0.0f);
    vertices[2].position = glm::vec3(0.0f, 1.0f, 0.0f);
    std::vector<std::uint32_t> indices;
    for (int i = 0; i < 100; ++i) indices.insert(indices.end(), {0u, 1u, 2u});
    const std::vector<std::uint32_t> before = indices;
    const std::vector<TriangleChunk> chunks = splitIntoChunks(vertices, indices, 10);
    EXPECT_EQ(chunks.size(), 16u);  // 100 → 50 → 25 → 12/13 → 6/7
    expectPartition(vertices, before, indices, chunks, 10);
}

TEST(TriangleChunks, BadInputIsRejected) {
    std::vector<Vertex> vertices(3);
    std::vector<std::uint32_t> partial{0, 1};
    EXPECT_THROW(splitIntoChunks(vertices, partial, 1), std::invalid_argument);
    std::vector<std::uint32_t> outOfRange{0, 1, 3};
    EXPECT_THROW(splitIntoChunks(vertices, outOfRange, 1), std::invalid_argument);
}

}  // namespace
}  // namespace lit
