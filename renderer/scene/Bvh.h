#pragma once
// A bounding volume hierarchy over the scene's draw items (GpuScene::items), for frustum culling.
//
// Built top-down with a binned surface-area heuristic (Wald, "On fast Construction of SAH-based
// Bounding Volume Hierarchies", 2007) over the items' world-space boxes; leaves hold a few items.
// When transforms change, refit recomputes the boxes bottom-up and keeps the tree's shape (the
// tree gets looser as things move, never wrong). Culling walks the tree from the root: a subtree
// outside the frustum is skipped whole, a subtree inside it is accepted whole without testing its
// children, and only straddling nodes go deeper — so the result equals testing every item's box
// on its own (tests/unit/test_frustum_bvh.cpp checks that on randomized scenes).

#include "scene/Aabb.h"

#include <cstdint>
#include <span>
#include <vector>

namespace lit {

class Frustum;
struct DrawItem;
struct Scene;

// The world-space box of each item: its localBounds under its node's world matrix (needs
// Scene::updateWorldTransforms). Throws std::invalid_argument when an item's node is not in
// `scene` (the items belong to another scene: rebuild them).
std::vector<Aabb> itemWorldBounds(const Scene& scene, std::span<const DrawItem> items);

class Bvh {
public:
    static constexpr std::uint32_t kMaxLeafItems = 4;  // a leaf never holds more items

    Bvh() = default;
    // Over the world boxes of `items` (see itemWorldBounds); refit(scene) follows their nodes.
    Bvh(const Scene& scene, std::span<const DrawItem> items);
    // Over arbitrary world-space boxes: item i is itemBounds[i]. Empty boxes are never visible.
    explicit Bvh(std::vector<Aabb> itemBounds);

    // New world boxes from the scene's current world matrices (after a transform edit), then the
    // node boxes bottom-up. Only for a tree built from a scene. Throws std::invalid_argument when
    // the scene no longer has an item's node.
    void refit(const Scene& scene);
    // New boxes for the same items (same count, else std::invalid_argument). Rebuilds instead
    // when a box became empty or non-empty, since empty boxes are kept out of the tree.
    void refit(std::vector<Aabb> itemBounds);

    // Indices of the items whose boxes are not outside `frustum` (Frustum::classify), in
    // ascending order — the order of GpuScene::items(), so culled and unculled frames draw the
    // survivors in the same order. `visibleItems` is overwritten.
    void cull(const Frustum& frustum, std::vector<std::uint32_t>& visibleItems) const;

    std::size_t itemCount() const { return itemBounds_.size(); }
    std::size_t nodeCount() const { return nodes_.size(); }
    int depth() const { return depth_; }  // levels from the root to the deepest leaf (1 = root only)
    const std::vector<Aabb>& itemBounds() const { return itemBounds_; }
    // The root's box: every non-empty item box is inside it. Empty for a tree without items.
    Aabb bounds() const { return nodes_.empty() ? Aabb{} : nodes_.front().bounds; }

private:
    struct Node {
        Aabb bounds;
        std::uint32_t firstItem = 0;  // this subtree's items are order_[firstItem, firstItem + itemCount)
        std::uint32_t itemCount = 0;
        std::uint32_t left = 0, right = 0;  // children; 0 in a leaf (the root is nobody's child)
        bool leaf() const { return left == 0; }
    };

    void build();
    std::uint32_t buildNode(std::uint32_t first, std::uint32_t count, int level);
    void refitNodes();
    void cullNode(std::uint32_t node, const Frustum& frustum, unsigned planeMask, std::vector<std::uint32_t>& out) const;

    std::vector<Aabb> itemBounds_;  // world space, per item
    std::vector<Node> nodes_;       // nodes_[0] is the root; children come after their parent
    std::vector<std::uint32_t> order_;  // item indices grouped by subtree; items with empty boxes left out
    int depth_ = 0;
    // Where refit(scene) finds each item's box: its node and object-space box.
    struct Source {
        int node = -1;
        Aabb localBounds;
    };
    std::vector<Source> sources_;  // empty when built from raw boxes
};

}  // namespace lit
