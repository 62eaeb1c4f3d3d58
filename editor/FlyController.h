#pragma once
// Turns one frame of input into FlyCamera motion. Input is gathered by ViewportInput (from GLFW,
// filtered by what ImGui wants), so this stays free of any window library and is unit-tested.

#include <glm/glm.hpp>

#include "scene/CameraView.h"

namespace lit::editor {

struct FlyInput {
    // Requested motion in camera terms, each axis in [−1, 1]: x right, y world up, z forward.
    glm::vec3 move{0.0f};
    bool fast = false;
    // Mouse movement while looking, in pixels (x right, y down as windows report it).
    glm::vec2 lookPixels{0.0f};
    // Mouse wheel steps this frame (positive = away from the user = faster).
    float wheelSteps = 0.0f;
};

struct FlyControlSettings {
    float radiansPerPixel = 0.003f;  // look sensitivity: ~0.17° per pixel
    float fastMultiplier = 5.0f;     // speed factor while Shift is held
    float speedStepFactor = 1.2f;    // speed multiplied per wheel step
    float minSpeed = 0.01f;          // metres per second
    float maxSpeed = 500.0f;         // metres per second
    // Pitch stays just short of straight up/down so "forward" keeps a horizontal part.
    float maxPitch = 1.55334f;  // radians (89°)
};

// Applies `input` over `dtSeconds`: moves along the camera's forward/right and world up,
// turns (mouse right = turn right, mouse down = look down) and scales the speed by the wheel.
void applyFlyInput(FlyCamera& camera, const FlyInput& input, float dtSeconds, const FlyControlSettings& settings = {});

// Points the camera at `target` (yaw and pitch; pitch clamped to ±maxPitch). No-op when the
// target is the camera's own position.
void lookAt(FlyCamera& camera, glm::vec3 target, const FlyControlSettings& settings = {});

// Orbit (Alt + left drag): turns the camera around `pivot` by the mouse motion (pixels, x right,
// y down; the same sensitivity as looking), keeping its distance and looking at the pivot.
void orbitAround(FlyCamera& camera, glm::vec3 pivot, glm::vec2 pixels, const FlyControlSettings& settings = {});

// Frame selected (F): moves the camera back along its view direction until the sphere around
// `bounds` fills about 80 % of the vertical field of view, centred. Orientation is kept.
// Returns the distance from the camera to the bounds' centre (m); empty bounds: no change, 0.
float frameBounds(FlyCamera& camera, const Aabb& bounds);

// Frame selected into part of the window: the camera keeps its orientation and moves so that the
// bounds' centre lands on the centre of `area` (x, y, width, height from the window's top-left
// corner, in the units of `window`, the whole window's size, which the camera's view fills) and
// the sphere around the bounds fills about 80 % of the area's shorter side. The editor passes the
// viewport area left free by its panels, so the framed object is not hidden behind one. An
// empty or degenerate area frames in the whole window (frameBounds). Returns the distance along
// the view direction (m); empty bounds: no change, 0.
float frameBoundsInArea(FlyCamera& camera, const Aabb& bounds, glm::vec2 window, glm::vec4 area);

// A comfortable default speed for a scene of this size: crossing it takes about 4 seconds.
float flySpeedForBounds(const Aabb& bounds);

}  // namespace lit::editor
