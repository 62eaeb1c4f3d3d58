#include "scene/OpeningView.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <vector>

#include "scene/Scene.h"

namespace lit {

namespace {

class OccupancyGrid {
public:
    OccupancyGrid(const Aabb& bounds, int cellsAlongLongestSide) : min_(bounds.min) {
        const glm::vec3 extent = bounds.max - bounds.min;
        const float longest = std::max({extent.x, extent.y, extent.z, 1e-6f});
        cell_ = longest / static_cast<float>(std::max(cellsAlongLongestSide, 4));
        for (int a = 0; a < 3; ++a) dims_[a] = std::clamp(static_cast<int>(std::ceil(extent[a] / cell_)) + 1, 1, 1024);
        occupied_.assign(count(), 0);
    }

    std::size_t count() const {
        return static_cast<std::size_t>(dims_[0]) * static_cast<std::size_t>(dims_[1]) * static_cast<std::size_t>(dims_[2]);
    }
    int dim(int axis) const { return dims_[axis]; }
    float cell() const { return cell_; }
    bool inside(glm::ivec3 c) const {
        return c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < dims_[0] && c.y < dims_[1] && c.z < dims_[2];
    }
    std::size_t index(glm::ivec3 c) const {
        return static_cast<std::size_t>(c.x) +
               static_cast<std::size_t>(dims_[0]) *
                   (static_cast<std::size_t>(c.y) + static_cast<std::size_t>(dims_[1]) * static_cast<std::size_t>(c.z));
    }
    glm::ivec3 cellOf(const glm::vec3& p) const {
        const glm::vec3 g = (p - min_) / cell_;
        return glm::clamp(glm::ivec3(glm::floor(g)), glm::ivec3(0), glm::ivec3(dims_[0] - 1, dims_[1] - 1, dims_[2] - 1));
    }
    glm::ivec3 unclampedCellOf(const glm::vec3& p) const { return glm::ivec3(glm::floor((p - min_) / cell_)); }
    glm::vec3 centre(glm::ivec3 c) const { return min_ + (glm::vec3(c) + 0.5f) * cell_; }
    bool occupied(glm::ivec3 c) const { return occupied_[index(c)] != 0; }

    // Marks the cells a triangle passes through: points on it no further apart than half a cell.
    void addTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        const float longest = std::max({glm::length(b - a), glm::length(c - a), glm::length(c - b)});
        const int steps = std::clamp(static_cast<int>(std::ceil(longest / (0.5f * cell_))), 1, 2048);
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; i + j <= steps; ++j) {
                const float u = static_cast<float>(i) / static_cast<float>(steps);
                const float v = static_cast<float>(j) / static_cast<float>(steps);
                occupied_[index(cellOf(a + u * (b - a) + v * (c - a)))] = 1;
            }
    }

private:
    glm::vec3 min_;
    float cell_ = 1.0f;
    std::array<int, 3> dims_{1, 1, 1};
    std::vector<std::uint8_t> occupied_;
};

constexpr std::array<glm::ivec3, 6> kAxisSteps{glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0),
                                               glm::ivec3(0, -1, 0), glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)};
constexpr int kDown = 3;  // kAxisSteps[3]: −y (glTF's up is +y)

// For each cell and axis direction, whether an occupied cell lies that way (the cell itself not
// counted): one sweep per direction.
std::vector<std::uint8_t> blockedDirections(const OccupancyGrid& grid) {
    std::vector<std::uint8_t> blocked(grid.count(), 0);
    for (int d = 0; d < 6; ++d) {
        const int axis = d / 2;
        const bool positive = d % 2 == 0;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int a = 0; a < grid.dim(u); ++a)
            for (int b = 0; b < grid.dim(v); ++b) {
                bool seen = false;  // an occupied cell further along the direction
                for (int k = 0; k < grid.dim(axis); ++k) {
                    glm::ivec3 c;
                    c[axis] = positive ? grid.dim(axis) - 1 - k : k;
                    c[u] = a;
                    c[v] = b;
                    if (seen) blocked[grid.index(c)] |= static_cast<std::uint8_t>(1u << d);
                    if (grid.occupied(c)) seen = true;
                }
            }
    }
    return blocked;
}

// Chessboard distance, in cells, from every cell to the nearest occupied one (breadth first).
std::vector<int> clearanceCells(const OccupancyGrid& grid) {
    std::vector<int> distance(grid.count(), -1);
    std::deque<glm::ivec3> queue;
    for (int z = 0; z < grid.dim(2); ++z)
        for (int y = 0; y < grid.dim(1); ++y)
            for (int x = 0; x < grid.dim(0); ++x)
                if (grid.occupied({x, y, z})) {
                    distance[grid.index({x, y, z})] = 0;
                    queue.push_back({x, y, z});
                }
    while (!queue.empty()) {
        const glm::ivec3 c = queue.front();
        queue.pop_front();
        const int next = distance[grid.index(c)] + 1;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 n = c + glm::ivec3(dx, dy, dz);
                    if (!grid.inside(n) || distance[grid.index(n)] >= 0) continue;
                    distance[grid.index(n)] = next;
                    queue.push_back(n);
                }
    }
    return distance;
}

// Metres from `from` along the horizontal unit `direction` to the first occupied cell or the
// grid's edge.
float freeRun(const OccupancyGrid& grid, const glm::vec3& from, const glm::vec3& direction) {
    const float step = 0.5f * grid.cell();
    glm::vec3 p = from;
    float run = 0.0f;
    for (int i = 0; i < 4096; ++i) {
        p += step * direction;
        const glm::ivec3 c = grid.unclampedCellOf(p);
        if (!grid.inside(c) || grid.occupied(c)) break;
        run += step;
    }
    return run;
}

}  // namespace

std::optional<OpeningView> findOpeningView(const Scene& scene, const OpeningViewOptions& options) {
    const Aabb bounds = scene.worldBounds();
    if (bounds.empty()) return std::nullopt;
    OccupancyGrid grid(bounds, options.cellsAlongLongestSide);
    bool anyTriangle = false;
    for (const Node& node : scene.nodes) {
        if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= scene.meshes.size()) continue;
        for (const Primitive& primitive : scene.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
            const std::size_t count = primitive.vertices.size();
            for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
                const std::uint32_t i0 = primitive.indices[t], i1 = primitive.indices[t + 1], i2 = primitive.indices[t + 2];
                if (i0 >= count || i1 >= count || i2 >= count) continue;
                const auto world = [&](std::uint32_t i) {
                    return glm::vec3(node.world * glm::vec4(primitive.vertices[i].position, 1.0f));
                };
                grid.addTriangle(world(i0), world(i1), world(i2));
                anyTriangle = true;
            }
        }
    }
    if (!anyTriangle) return std::nullopt;

    const std::vector<std::uint8_t> blocked = blockedDirections(grid);
    const std::vector<int> clearance = clearanceCells(grid);
    const int minCells = static_cast<int>(std::ceil(options.minClearance / grid.cell()));
    const glm::vec3 middle = 0.5f * (bounds.min + bounds.max);
    glm::ivec3 best(-1);
    int bestClearance = 0;
    float bestToMiddle = 0.0f;
    for (int z = 0; z < grid.dim(2); ++z)
        for (int y = 0; y < grid.dim(1); ++y)
            for (int x = 0; x < grid.dim(0); ++x) {
                const glm::ivec3 c(x, y, z);
                const std::size_t i = grid.index(c);
                if (grid.occupied(c) || !(blocked[i] & (1u << kDown))) continue;
                int sides = 0;
                for (int d = 0; d < 6; ++d) sides += (blocked[i] >> d) & 1u;
                if (sides < 5 || clearance[i] < minCells) continue;
                const float toMiddle = glm::length(grid.centre(c) - middle);
                if (clearance[i] > bestClearance || (clearance[i] == bestClearance && toMiddle < bestToMiddle)) {
                    best = c;
                    bestClearance = clearance[i];
                    bestToMiddle = toMiddle;
                }
            }
    if (best.x < 0) return std::nullopt;

    // Stand on the floor below the space, at eye height (half the room's height in a low room).
    glm::ivec3 floor = best;
    while (floor.y > 0 && !grid.occupied(floor)) --floor.y;
    glm::ivec3 ceiling = best;
    while (ceiling.y + 1 < grid.dim(1) && !grid.occupied(ceiling)) ++ceiling.y;
    const float floorTop = grid.centre(floor).y + 0.5f * grid.cell();
    const float above = grid.occupied(ceiling) ? grid.centre(ceiling).y - 0.5f * grid.cell() : bounds.max.y;
    if (above - floorTop < options.minRoomHeight) return std::nullopt;
    OpeningView view;
    view.position = grid.centre(best);
    view.position.y = floorTop + std::min(options.eyeHeight, 0.5f * (above - floorTop));
    view.clearance = static_cast<float>(clearance[grid.index(grid.cellOf(view.position))]) * grid.cell();
    // Look along the longest free horizontal line of sight (16 headings).
    float longest = -1.0f;
    for (int k = 0; k < 16; ++k) {
        const float angle = 6.28318530718f * static_cast<float>(k) / 16.0f;
        const glm::vec3 direction(std::sin(angle), 0.0f, -std::cos(angle));
        const float run = freeRun(grid, view.position, direction);
        if (run > longest) {
            longest = run;
            view.forward = direction;
        }
    }
    return view;
}

}  // namespace lit
