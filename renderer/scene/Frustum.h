#pragma once
// A view frustum as six world-space planes, for culling axis-aligned boxes.
//
// The planes come from a view-projection matrix by Gribb & Hartmann's extraction ("Fast
// Extraction of Viewing Frustum Planes from the World-View-Projection Matrix", 2001): a point p
// is inside clip space when −w ≤ x, y, z ≤ w with (x, y, z, w) = M·p, so each plane is row 3 ± row
// i of M. That is OpenGL's clip volume (docs/CONVENTIONS.md), for perspective and orthographic
// matrices alike. Planes are normalized, so a plane's value at a point is a distance in world
// units (metres), positive inside.

#include "scene/Aabb.h"

#include <glm/glm.hpp>

#include <array>

namespace lit {

enum class Containment { Outside, Intersecting, Inside };

class Frustum {
public:
    enum PlaneIndex { Left, Right, Bottom, Top, Near, Far, PlaneCount };

    // A box closer than this to the outer side of a plane still counts as touching it (metres):
    // float rounding in the plane extraction must never cull an object that touches the frustum.
    static constexpr float kTouchTolerance = 1e-5f;

    // Everything is inside (all planes degenerate): culling against it keeps every box.
    Frustum();
    // The frustum of clip space under `viewProjection` (world → clip). A plane that degenerates
    // (zero normal, as the far plane of an infinite projection) keeps everything on its side.
    explicit Frustum(const glm::mat4& viewProjection);

    // Where `box` lies. A box touching a plane from outside (within kTouchTolerance) is
    // Intersecting, never Outside. An empty box (Aabb::empty) is Outside: it has nothing to draw.
    Containment classify(const Aabb& box) const;
    bool intersects(const Aabb& box) const { return classify(box) != Containment::Outside; }

    // Like classify, testing only the planes whose bit is set in `planeMask` (bit i = plane i).
    // Clears the bits of planes the box lies entirely inside of, so children of a box (boxes
    // contained in it) need not test those planes again.
    Containment classify(const Aabb& box, unsigned& planeMask) const;

    // Plane i as (normal, offset): inside where dot(normal, p) + offset ≥ 0; |normal| = 1 or 0.
    const std::array<glm::vec4, PlaneCount>& planes() const { return planes_; }

    static constexpr unsigned kAllPlanes = (1u << PlaneCount) - 1u;

private:
    std::array<glm::vec4, PlaneCount> planes_;
};

}  // namespace lit
