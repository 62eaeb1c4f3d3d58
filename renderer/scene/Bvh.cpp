#include "scene/Bvh.h"

#include "scene/Frustum.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace lit {

namespace {

constexpr int kBins = 16;  // SAH candidate planes per axis: 16 is within a few % of a full sweep (Wald 2007)
// Cost of testing a node relative to testing an item: both are one box-frustum test.
constexpr float kNodeTestCost = 1.0f;
// Below this depth the tree splits at the median instead, so it stays O(log n) deep even for
// item layouts that make the SAH peel off one item at a time.
constexpr int kMaxSahLevel = 40;

// Half the surface area: the SAH only compares areas, so the factor 2 cancels.
float halfArea(const Aabb& box) {
    if (box.empty()) return 0.0f;
    const glm::vec3 d = box.size();
    return d.x * d.y + d.y * d.z + d.z * d.x;
}

int binOf(float centroid, float lowest, float binsPerUnit) {
    return std::clamp(static_cast<int>((centroid - lowest) * binsPerUnit), 0, kBins - 1);
}

Aabb worldBoxOf(const Scene& scene, int node, const Aabb& localBounds, std::size_t item) {
    if (node < 0 || static_cast<std::size_t>(node) >= scene.nodes.size())
        throw std::invalid_argument("draw item " + std::to_string(item) + " refers to node " + std::to_string(node) +
                                    ", but the scene has " + std::to_string(scene.nodes.size()) +
                                    " nodes: the items belong to another scene");
    return localBounds.transformed(scene.nodes[static_cast<std::size_t>(node)].world);
}

}  // namespace

std::vector<Aabb> itemWorldBounds(const Scene& scene, std::span<const DrawItem> items) {
    std::vector<Aabb> boxes;
    boxes.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) boxes.push_back(worldBoxOf(scene, items[i].node, items[i].localBounds, i));
    return boxes;
}

Bvh::Bvh(const Scene& scene, std::span<const DrawItem> items) : itemBounds_(itemWorldBounds(scene, items)) {
    sources_.reserve(items.size());
    for (const DrawItem& item : items) sources_.push_back({item.node, item.localBounds});
    build();
}

Bvh::Bvh(std::vector<Aabb> itemBounds) : itemBounds_(std::move(itemBounds)) { build(); }

void Bvh::build() {
    nodes_.clear();
    order_.clear();
    depth_ = 0;
    for (std::size_t i = 0; i < itemBounds_.size(); ++i)
        if (!itemBounds_[i].empty()) order_.push_back(static_cast<std::uint32_t>(i));
    if (order_.empty()) return;
    nodes_.reserve(2 * order_.size());  // a binary tree with n leaves' worth of items has < 2n nodes
    buildNode(0, static_cast<std::uint32_t>(order_.size()), 1);
}

std::uint32_t Bvh::buildNode(std::uint32_t first, std::uint32_t count, int level) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Aabb bounds, centroids;
    for (std::uint32_t k = first; k < first + count; ++k) {
        const Aabb& box = itemBounds_[order_[k]];
        bounds.extend(box);
        centroids.extend(box.center());
    }
    nodes_[index].bounds = bounds;
    nodes_[index].firstItem = first;
    nodes_[index].itemCount = count;
    depth_ = std::max(depth_, level);
    if (count <= 1) return index;

    const auto begin = order_.begin() + first, end = begin + count;
    const glm::vec3 spread = centroids.size();
    std::uint32_t split = 0;  // items in the left child; 0 = make a leaf
    const float parentArea = halfArea(bounds);
    if (level < kMaxSahLevel && parentArea > 0.0f) {
        // Binned SAH: bin the centroids along each axis, then sweep the 15 planes between bins.
        // Cost of a split = node test + Σ (child area / parent area) × child item count.
        float bestCost = static_cast<float>(count);  // a leaf tests every item
        int bestAxis = -1, bestBin = 0;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(spread[axis] > 0.0f)) continue;
            const float binsPerUnit = static_cast<float>(kBins) / spread[axis];
            std::array<Aabb, kBins> binBounds;
            std::array<std::uint32_t, kBins> binCounts{};
            for (auto it = begin; it != end; ++it) {
                const Aabb& box = itemBounds_[*it];
                const int bin = binOf(box.center()[axis], centroids.min[axis], binsPerUnit);
                binBounds[static_cast<std::size_t>(bin)].extend(box);
                ++binCounts[static_cast<std::size_t>(bin)];
            }
            // Right-hand sweep: area × count of bins (b, kBins).
            std::array<float, kBins> rightCost{};
            Aabb right;
            std::uint32_t rightCount = 0;
            for (int b = kBins - 1; b > 0; --b) {
                right.extend(binBounds[static_cast<std::size_t>(b)]);
                rightCount += binCounts[static_cast<std::size_t>(b)];
                rightCost[static_cast<std::size_t>(b)] = rightCount ? halfArea(right) * static_cast<float>(rightCount) : -1.0f;
            }
            Aabb left;
            std::uint32_t leftCount = 0;
            for (int b = 0; b < kBins - 1; ++b) {  // plane between bin b and b + 1
                left.extend(binBounds[static_cast<std::size_t>(b)]);
                leftCount += binCounts[static_cast<std::size_t>(b)];
                const float rightPart = rightCost[static_cast<std::size_t>(b + 1)];
                if (leftCount == 0 || rightPart < 0.0f) continue;  // one side empty: not a split
                const float cost =
                    kNodeTestCost + (halfArea(left) * static_cast<float>(leftCount) + rightPart) / parentArea;
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = b;
                }
            }
        }
        if (bestAxis >= 0) {
            const float binsPerUnit = static_cast<float>(kBins) / spread[bestAxis];
            const float lowest = centroids.min[bestAxis];
            const auto middle = std::partition(begin, end, [&](std::uint32_t item) {
                return binOf(itemBounds_[item].center()[bestAxis], lowest, binsPerUnit) <= bestBin;
            });
            split = static_cast<std::uint32_t>(middle - begin);
        }
    }
    if (split == 0 && count > kMaxLeafItems) {
        // The SAH prefers a leaf, or cannot separate the centroids (all equal), or the tree is
        // deep: split at the median along the widest centroid axis (by position in the list
        // when the centroids coincide), so leaves stay small.
        const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;
        split = count / 2;
        std::nth_element(begin, begin + split, end, [&](std::uint32_t a, std::uint32_t b) {
            return itemBounds_[a].center()[axis] < itemBounds_[b].center()[axis];
        });
    }
    if (split == 0 || split >= count) return index;

    const std::uint32_t leftChild = buildNode(first, split, level + 1);
    const std::uint32_t rightChild = buildNode(first + split, count - split, level + 1);
    nodes_[index].left = leftChild;  // by index: building the children may have moved nodes_
    nodes_[index].right = rightChild;
    return index;
}

void Bvh::refit(const Scene& scene) {
    if (sources_.size() != itemBounds_.size())
        throw std::invalid_argument("Bvh::refit(scene): this tree was built from boxes, not from a scene's items");
    std::vector<Aabb> boxes;
    boxes.reserve(sources_.size());
    for (std::size_t i = 0; i < sources_.size(); ++i)
        boxes.push_back(worldBoxOf(scene, sources_[i].node, sources_[i].localBounds, i));
    refit(std::move(boxes));
}

void Bvh::refit(std::vector<Aabb> itemBounds) {
    if (itemBounds.size() != itemBounds_.size())
        throw std::invalid_argument("Bvh::refit: got " + std::to_string(itemBounds.size()) + " boxes for a tree of " +
                                    std::to_string(itemBounds_.size()) + " items; build a new tree instead");
    bool sameItemsInTree = true;
    for (std::size_t i = 0; i < itemBounds.size(); ++i)
        sameItemsInTree = sameItemsInTree && itemBounds[i].empty() == itemBounds_[i].empty();
    itemBounds_ = std::move(itemBounds);
    if (!sameItemsInTree) {
        build();
        return;
    }
    refitNodes();
}

void Bvh::refitNodes() {
    // Children are stored after their parent, so a reverse sweep visits children first.
    for (std::size_t i = nodes_.size(); i-- > 0;) {
        Node& node = nodes_[i];
        Aabb bounds;
        if (node.leaf()) {
            for (std::uint32_t k = node.firstItem; k < node.firstItem + node.itemCount; ++k)
                bounds.extend(itemBounds_[order_[k]]);
        } else {
            bounds.extend(nodes_[node.left].bounds);
            bounds.extend(nodes_[node.right].bounds);
        }
        node.bounds = bounds;
    }
}

void Bvh::cull(const Frustum& frustum, std::vector<std::uint32_t>& visibleItems) const {
    visibleItems.clear();
    if (nodes_.empty()) return;
    cullNode(0, frustum, Frustum::kAllPlanes, visibleItems);
    std::sort(visibleItems.begin(), visibleItems.end());
}

void Bvh::cullNode(std::uint32_t index, const Frustum& frustum, unsigned planeMask, std::vector<std::uint32_t>& out) const {
    const Node& node = nodes_[index];
    // classify narrows the mask to the planes this box straddles: the boxes below are inside
    // this one, so they are inside every plane this one is inside of.
    const Containment containment = frustum.classify(node.bounds, planeMask);
    if (containment == Containment::Outside) return;
    const auto items = std::span(order_).subspan(node.firstItem, node.itemCount);
    if (containment == Containment::Inside) {
        out.insert(out.end(), items.begin(), items.end());
    } else if (node.leaf()) {
        for (const std::uint32_t item : items) {
            unsigned itemMask = planeMask;
            if (frustum.classify(itemBounds_[item], itemMask) != Containment::Outside) out.push_back(item);
        }
    } else {
        cullNode(node.left, frustum, planeMask, out);
        cullNode(node.right, frustum, planeMask, out);
    }
}

}  // namespace lit
