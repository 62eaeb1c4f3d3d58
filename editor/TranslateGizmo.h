#pragma once
// The translate gizmo's geometry and dragging, window-free: three axis handles at a node's
// world position, picked by distance to their projection on screen, and dragged by following
// the point of the axis line closest to the mouse ray (so the node stays under the cursor
// along the axis, however the axis is foreshortened).

#include <glm/glm.hpp>
#include <optional>

#include "scene/CameraView.h"

namespace lit::editor {

// Mouse positions are window pixels with a top-left origin; `viewport` is the window size in
// the same pixels.
struct ScreenRay {
    glm::vec3 origin;
    glm::vec3 direction;  // unit
};
ScreenRay screenRay(const CameraView& view, glm::vec2 viewport, glm::vec2 mouse);
// Where a world point lands on screen (top-left origin); nullopt behind the camera.
std::optional<glm::vec2> projectToScreen(const CameraView& view, glm::vec2 viewport, glm::vec3 point);

class TranslateGizmo {
public:
    static constexpr float kAxisPixels = 90.0f;  // drawn length of each axis on screen
    static constexpr float kPickPixels = 8.0f;   // how close the mouse must be to grab an axis

    // World length of an axis at `origin` so it spans about kAxisPixels on screen.
    static float axisLength(const CameraView& view, glm::vec2 viewport, glm::vec3 origin);
    // The axis (0 X, 1 Y, 2 Z) whose on-screen segment is nearest the mouse within kPickPixels,
    // or -1.
    static int hitTest(const CameraView& view, glm::vec2 viewport, glm::vec3 origin, glm::vec2 mouse);

    // Starts dragging `axis` of a gizmo at `origin`. Returns false when the axis points (nearly)
    // straight at the camera, where a drag along it is undefined.
    bool begin(int axis, const CameraView& view, glm::vec2 viewport, glm::vec3 origin, glm::vec2 mouse);
    // The gizmo origin for the mouse now (the start origin moved along the axis).
    glm::vec3 drag(const CameraView& view, glm::vec2 viewport, glm::vec2 mouse) const;
    void end() { axis_ = -1; }
    bool active() const { return axis_ >= 0; }
    int axis() const { return axis_; }

private:
    int axis_ = -1;
    glm::vec3 startOrigin_{0.0f};
    float startParameter_ = 0.0f;  // position along the axis where the drag began
};

// World size of one window pixel at the depth of `point` (perspective), for things drawn at a
// constant size on screen.
float worldPerPixel(const CameraView& view, glm::vec2 viewport, glm::vec3 point);

// The parameter s of the point origin + s·axis closest to the ray; nullopt when they are
// (nearly) parallel.
std::optional<float> closestOnAxis(glm::vec3 origin, glm::vec3 axis, const ScreenRay& ray);

}  // namespace lit::editor
