#pragma once
// The transform gizmo: translate (three arrows), rotate (three rings) and scale (three axes with
// boxes at their ends and a centre handle for uniform scale), in world or local space, with
// optional snapping. Window-free maths, as TranslateGizmo.h: handles are picked by their distance
// to the mouse on screen, and a drag turns the mouse position into a transform delta:
//   translate: the point of the axis line closest to the mouse ray (TranslateGizmo's rule);
//   rotate:    the angle the mouse swept around the gizmo's centre on screen, signed by whether
//              the axis points towards the camera (so dragging along the visible ring turns the
//              object the way the ring moves), unwrapped so a drag can turn more than 180°;
//   scale:     1 + (distance moved along the axis) / (drawn axis length): dragging one handle
//              length outwards doubles the size; the centre handle scales all axes by the
//              horizontal mouse motion over the same length in pixels.
// Scale always acts along the node's own axes (as in Unity and Godot: a world-space scale of a
// rotated node would shear it).

#include <glm/glm.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "Overlay.h"
#include "TranslateGizmo.h"
#include "scene/CameraView.h"

namespace lit::editor {

enum class GizmoMode { Translate, Rotate, Scale };
enum class GizmoSpace { World, Local };

const char* gizmoModeName(GizmoMode mode);  // "translate", "rotate", "scale"
std::optional<GizmoMode> parseGizmoMode(std::string_view name);

// Snapping (Ctrl held during a drag, or always on): each step is an editor setting.
struct GizmoSnap {
    bool enabled = false;
    float translateStep = 0.25f;     // metres
    float rotateStepDegrees = 15.0f; // degrees
    float scaleStep = 0.1f;          // scale factor
};

// The gizmo as the user set it up: the viewport bar, W / E / R / T and the script's gizmo,
// space and snap commands edit it; drags and the overlay read it.
struct GizmoTool {
    GizmoMode mode = GizmoMode::Translate;
    GizmoSpace space = GizmoSpace::World;
    GizmoSnap snap;  // snap.enabled: always on; Ctrl snaps during a drag either way
};

// The gizmo's three axes in world space (unit columns): the world axes, or the node's own axes
// (the columns of its world matrix, normalised) for local space. Scale always uses local axes.
glm::mat3 gizmoAxes(GizmoMode mode, GizmoSpace space, const glm::mat4& nodeWorld);

// What a drag has done so far, relative to where it began.
struct GizmoDelta {
    glm::vec3 translation{0.0f};  // world offset (m)
    glm::vec3 rotationAxis{0.0f, 1.0f, 0.0f};  // world, unit
    float angle = 0.0f;           // radians, right-handed about rotationAxis
    glm::vec3 scale{1.0f};        // factors along the node's own X, Y, Z
};

// The world matrix of a node whose world matrix was `startWorld` when the drag began: moved by
// the translation, rotated about `pivot` (m, world), or scaled along its own axes about its own
// origin.
glm::mat4 applyGizmoDelta(GizmoMode mode, const GizmoDelta& delta, glm::vec3 pivot, const glm::mat4& startWorld);

class TransformGizmo {
public:
    static constexpr float kAxisPixels = TranslateGizmo::kAxisPixels;  // arrow / scale axis length
    static constexpr float kRingPixels = 80.0f;   // rotate ring radius on screen
    static constexpr float kPickPixels = 8.0f;    // how close the mouse must be to grab a handle
    static constexpr float kCentrePixels = 10.0f; // the uniform scale handle's half size
    static constexpr int kUniformHandle = 3;      // hitTest's answer for the centre (scale) handle
    static constexpr int kRingSegments = 64;

    // The handle under the mouse: 0 X, 1 Y, 2 Z, kUniformHandle (scale mode's centre), or -1.
    static int hitTest(GizmoMode mode, const CameraView& view, glm::vec2 viewport, glm::vec3 origin,
                       const glm::mat3& axes, glm::vec2 mouse);

    // Starts dragging `handle`. Returns false when it cannot be dragged from here (an axis
    // pointing straight at the camera for translate and scale).
    bool begin(GizmoMode mode, int handle, const CameraView& view, glm::vec2 viewport, glm::vec3 origin,
               const glm::mat3& axes, glm::vec2 mouse);
    // The delta for the mouse now, snapped when snap.enabled. Not const: a rotation remembers
    // the last angle to unwrap the next one.
    GizmoDelta drag(const CameraView& view, glm::vec2 viewport, glm::vec2 mouse, const GizmoSnap& snap);
    void end() { handle_ = -1; }
    bool active() const { return handle_ >= 0; }
    int handle() const { return handle_; }
    GizmoMode mode() const { return mode_; }
    glm::vec3 origin() const { return origin_; }

private:
    GizmoMode mode_ = GizmoMode::Translate;
    int handle_ = -1;
    glm::vec3 origin_{0.0f};
    glm::vec3 axis_{1.0f, 0.0f, 0.0f};  // world direction of the handle's axis
    float startParameter_ = 0.0f;       // translate / scale: position along the axis at the start
    float axisLength_ = 1.0f;           // scale: drawn axis length at the start (m)
    glm::vec2 startMouse_{0.0f};
    glm::vec2 centre_{0.0f};            // rotate: the origin on screen
    float previousRawAngle_ = 0.0f;     // rotate: last screen angle, for unwrapping
    float angle_ = 0.0f;                // rotate: accumulated angle (rad)
};

// The gizmo's lines (drawn on top of everything): per axis X red, Y green, Z blue; the hovered
// or dragged handle yellow. Translate: arrows; rotate: rings of radius kRingPixels; scale: axes
// with a small box at each end and a square at the centre.
std::vector<OverlayLine> gizmoLines(GizmoMode mode, const CameraView& view, glm::vec2 viewport, glm::vec3 origin,
                                    const glm::mat3& axes, int highlightedHandle);

// Snapping helpers (also used by tests): value rounded to the nearest multiple of step (step
// <= 0: unchanged).
float snapTo(float value, float step);

}  // namespace lit::editor
