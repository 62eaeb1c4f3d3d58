#pragma once
#include <glm/glm.hpp>

#include <limits>

namespace lit {

// Axis-aligned bounding box. Empty when min > max (the default).
struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        if (b.empty()) return;
        extend(b.min);
        extend(b.max);
    }
    // Corner i of 8: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
    glm::vec3 corner(int i) const {
        return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 size() const { return max - min; }
    float radius() const { return 0.5f * glm::length(size()); }

    // The box of this box's eight corners after an affine transform.
    Aabb transformed(const glm::mat4& m) const {
        Aabb out;
        if (empty()) return out;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner{(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
            out.extend(glm::vec3(m * glm::vec4(corner, 1.0f)));
        }
        return out;
    }
};

}  // namespace lit
