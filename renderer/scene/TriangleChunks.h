#pragma once
// Splitting a large primitive into spatially compact runs of triangles ("chunks") for frustum
// culling. A glTF primitive can cover a whole building (Sponza's floor, walls and columns are a
// few primitives of tens of thousands of triangles each); as one draw item its box is always in
// view. GpuScene reorders each large primitive's index buffer so that every chunk is one
// contiguous index range and makes each chunk a draw item with its own box. The CPU Scene keeps
// its primitives as loaded; only the GPU copy of the indices is reordered.

#include "scene/Aabb.h"
#include "scene/Scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace lit {

// Triangles per chunk at most, by default. Large enough that a scene of a few hundred thousand
// triangles stays at a few dozen to a hundred draws (each draw costs CPU time to issue), small
// enough that a chunk spans a room-sized part of a big primitive, not the whole building.
inline constexpr std::uint32_t kDefaultChunkTriangles = 8192;

// One contiguous range of a primitive's reordered index buffer.
struct TriangleChunk {
    std::uint32_t firstIndex = 0;  // into the reordered indices (a multiple of 3)
    std::uint32_t indexCount = 0;  // a multiple of 3
    Aabb bounds;                   // object space: the vertices of exactly these triangles
};

// Partitions the triangles of `indices` (a triangle list into `vertices`) into chunks of at most
// `maxTriangles` triangles each by recursive median splits of the triangle centroids along the
// longest axis of their bounds, and reorders `indices` so each chunk is contiguous (triangles keep
// their vertex order, so winding is unchanged). Returns the chunks in index order; they cover
// every triangle exactly once. A primitive with at most `maxTriangles` triangles, or
// `maxTriangles` == 0 (splitting off), is one chunk and keeps its order.
// Throws std::invalid_argument when indices.size() is not a multiple of 3 or an index is not a
// vertex.
std::vector<TriangleChunk> splitIntoChunks(std::span<const Vertex> vertices, std::span<std::uint32_t> indices,
                                           std::uint32_t maxTriangles = kDefaultChunkTriangles);

}  // namespace lit
