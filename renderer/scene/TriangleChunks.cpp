#include "scene/TriangleChunks.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace lit {

namespace {

struct Splitter {
    std::vector<glm::vec3> centroids;        // per triangle
    std::vector<std::uint32_t> order;        // triangle indices, grouped by chunk as splitting goes
    std::uint32_t maxTriangles = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;  // (first, count) into order, in order

    // Splits order[first, first + count) at the median centroid along the longest axis of the
    // centroids' bounds until every part is small enough. Depth is log2(triangles / max): the
    // count halves at every level, even when all centroids coincide.
    void split(std::uint32_t first, std::uint32_t count) {
        if (count <= maxTriangles) {
            ranges.emplace_back(first, count);
            return;
        }
        Aabb box;
        for (std::uint32_t i = first; i < first + count; ++i) box.extend(centroids[order[i]]);
        const glm::vec3 size = box.size();
        const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
        const std::uint32_t half = count / 2;
        const auto begin = order.begin() + first;
        // Ties broken by triangle index, so the split does not depend on the library's sort.
        std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t a, std::uint32_t b) {
            const float ca = centroids[a][axis], cb = centroids[b][axis];
            return ca < cb || (ca == cb && a < b);
        });
        split(first, half);
        split(first + half, count - half);
    }
};

}  // namespace

std::vector<TriangleChunk> splitIntoChunks(std::span<const Vertex> vertices, std::span<std::uint32_t> indices,
                                           std::uint32_t maxTriangles) {
    if (indices.size() % 3 != 0)
        throw std::invalid_argument("splitIntoChunks: " + std::to_string(indices.size()) +
                                    " indices is not a whole number of triangles");
    for (const std::uint32_t index : indices)
        if (index >= vertices.size())
            throw std::invalid_argument("splitIntoChunks: index " + std::to_string(index) + " is past the " +
                                        std::to_string(vertices.size()) + " vertices");
    const auto triangles = static_cast<std::uint32_t>(indices.size() / 3);
    const auto boundsOf = [&](std::span<const std::uint32_t> range) {
        Aabb box;
        for (const std::uint32_t index : range) box.extend(vertices[index].position);
        return box;
    };
    if (triangles == 0) return {};
    if (maxTriangles == 0 || triangles <= maxTriangles)
        return {{0, static_cast<std::uint32_t>(indices.size()), boundsOf(indices)}};

    const std::vector<std::uint32_t> original(indices.begin(), indices.end());
    Splitter splitter{{}, std::vector<std::uint32_t>(triangles), maxTriangles, {}};
    splitter.centroids.reserve(triangles);
    for (std::uint32_t t = 0; t < triangles; ++t)
        splitter.centroids.push_back((vertices[original[3 * t]].position + vertices[original[3 * t + 1]].position +
                                      vertices[original[3 * t + 2]].position) /
                                     3.0f);
    std::iota(splitter.order.begin(), splitter.order.end(), 0u);
    splitter.split(0, triangles);

    std::vector<TriangleChunk> chunks;
    chunks.reserve(splitter.ranges.size());
    for (const auto& [first, count] : splitter.ranges) {
        // Inside a chunk the triangles keep their original relative order (cache locality of
        // the source mesh, and a stable draw order for coplanar triangles).
        std::sort(splitter.order.begin() + first, splitter.order.begin() + first + count);
        for (std::uint32_t i = first; i < first + count; ++i)
            for (std::uint32_t corner = 0; corner < 3; ++corner)
                indices[3 * i + corner] = original[3 * splitter.order[i] + corner];
        const std::span<const std::uint32_t> range = indices.subspan(3 * first, 3 * count);
        chunks.push_back({3 * first, 3 * count, boundsOf(range)});
    }
    return chunks;
}

}  // namespace lit
