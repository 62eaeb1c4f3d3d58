#include "scene/Frustum.h"

#include <cmath>

namespace lit {

namespace {

// Signed distance of `p` to `plane`, always summed in the same order: float rounding is then
// monotonic in p, so a box inside another never gets a larger distance than the outer box's
// (the BVH relies on this to agree exactly with per-object tests).
float planeDistance(const glm::vec4& plane, const glm::vec3& p) {
    return plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w;
}

}  // namespace

Frustum::Frustum() { planes_.fill(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)); }

Frustum::Frustum(const glm::mat4& m) {
    // glm is column-major: row i of M is (m[0][i], m[1][i], m[2][i], m[3][i]).
    const auto row = [&m](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    const glm::vec4 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    planes_[Left] = r3 + r0;    // −w ≤ x
    planes_[Right] = r3 - r0;   //  x ≤ w
    planes_[Bottom] = r3 + r1;  // −w ≤ y
    planes_[Top] = r3 - r1;     //  y ≤ w
    planes_[Near] = r3 + r2;    // −w ≤ z (GL clip space; depth [0,1] comes after the divide)
    planes_[Far] = r3 - r2;     //  z ≤ w
    for (glm::vec4& plane : planes_) {
        const float length = std::sqrt(plane.x * plane.x + plane.y * plane.y + plane.z * plane.z);
        // A zero normal constrains nothing (the far plane of an infinite projection): keep all.
        plane = length > 0.0f && std::isfinite(length) ? plane / length : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    }
}

Containment Frustum::classify(const Aabb& box) const {
    unsigned mask = kAllPlanes;
    return classify(box, mask);
}

Containment Frustum::classify(const Aabb& box, unsigned& planeMask) const {
    if (box.empty()) return Containment::Outside;
    bool straddles = false;
    for (int i = 0; i < PlaneCount; ++i) {
        const unsigned bit = 1u << i;
        if (!(planeMask & bit)) continue;
        const glm::vec4& plane = planes_[static_cast<std::size_t>(i)];
        // The corner farthest along the normal (p) decides "outside"; the nearest (n), "inside".
        const glm::vec3 farCorner{plane.x >= 0.0f ? box.max.x : box.min.x, plane.y >= 0.0f ? box.max.y : box.min.y,
                                  plane.z >= 0.0f ? box.max.z : box.min.z};
        if (planeDistance(plane, farCorner) < -kTouchTolerance) return Containment::Outside;
        const glm::vec3 nearCorner{plane.x >= 0.0f ? box.min.x : box.max.x, plane.y >= 0.0f ? box.min.y : box.max.y,
                                   plane.z >= 0.0f ? box.min.z : box.max.z};
        if (planeDistance(plane, nearCorner) >= 0.0f)
            planeMask &= ~bit;  // entirely on the inner side: boxes inside this one are too
        else
            straddles = true;
    }
    return straddles ? Containment::Intersecting : Containment::Inside;
}

}  // namespace lit
