#pragma once
// Where a scene without a camera is first seen from (the editor's opening view): inside its
// largest enclosed open space, at eye height above its floor, looking along the longest free line
// of sight there. A room, a building or a courtyard is entered rather than seen from outside, where
// its roof hides everything; a scene that encloses no space a person could stand in (an object on
// its own) has no opening view, and is framed from outside (frameBounds).
//
// The space is found on a coarse occupancy grid of the scene's triangles (cells of 1/96 of the
// bounds' longest side): an empty cell is enclosed when geometry lies below it and in at least
// four of the five other axis directions (a courtyard open to the sky counts); the opening view
// stands in the enclosed cell farthest from any geometry.

#include <optional>

#include <glm/glm.hpp>

namespace lit {

struct Scene;

struct OpeningView {
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit, horizontal
    float clearance = 0.0f;                // metres from the position to the nearest geometry (grid estimate)
};

struct OpeningViewOptions {
    int cellsAlongLongestSide = 96;
    float eyeHeight = 1.6f;       // metres above the floor (less in a room lower than twice that)
    float minClearance = 0.75f;   // metres: a space narrower than this is no place to stand
    float minRoomHeight = 2.0f;   // metres from the floor to whatever is above
};

// Needs the scene's world transforms (Scene::updateWorldTransforms). nullopt: no enclosed space.
std::optional<OpeningView> findOpeningView(const Scene& scene, const OpeningViewOptions& options = {});

}  // namespace lit
