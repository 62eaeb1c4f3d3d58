#include "TransformGizmo.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/OverlayShapes.h"

namespace lit::editor {

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr glm::vec4 kHighlight{1.0f, 0.95f, 0.2f, 1.0f};
constexpr glm::vec4 kCentreColor{0.9f, 0.9f, 0.9f, 1.0f};
// Smallest scale factor a drag can reach: glTF forbids zero scale, and below this the node is
// lost from sight anyway.
constexpr float kMinScale = 0.01f;

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float lengthSquared = glm::dot(ab, ab);
    const float t = lengthSquared > 0.0f ? glm::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

// Two unit vectors spanning the plane perpendicular to `axis`.
void planeBasis(glm::vec3 axis, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    u = glm::normalize(glm::cross(helper, axis));
    v = glm::cross(axis, u);
}

// The ring of `axis` as world points (closed: the last equals the first).
std::vector<glm::vec3> ringPoints(glm::vec3 origin, glm::vec3 axis, float radius) {
    glm::vec3 u, v;
    planeBasis(axis, u, v);
    std::vector<glm::vec3> points;
    for (int i = 0; i <= TransformGizmo::kRingSegments; ++i) {
        const float a = 2.0f * kPi * static_cast<float>(i) / TransformGizmo::kRingSegments;
        points.push_back(origin + radius * (std::cos(a) * u + std::sin(a) * v));
    }
    return points;
}

// The mouse's angle around `centre` on screen, counter-clockwise as seen (screen y points down).
float screenAngle(glm::vec2 centre, glm::vec2 mouse) {
    const glm::vec2 d = mouse - centre;
    return std::atan2(-d.y, d.x);
}

glm::vec4 axisColor(int axis) { return axis == 0 ? kGizmoColorX : axis == 1 ? kGizmoColorY : kGizmoColorZ; }

void addBox(std::vector<OverlayLine>& lines, glm::vec3 centre, const glm::mat3& axes, float half, glm::vec4 color) {
    glm::vec3 corners[8];
    for (int i = 0; i < 8; ++i)
        corners[i] = centre + half * ((i & 1 ? 1.0f : -1.0f) * axes[0] + (i & 2 ? 1.0f : -1.0f) * axes[1] +
                                      (i & 4 ? 1.0f : -1.0f) * axes[2]);
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) lines.push_back({corners[i], corners[i | bit], color});
}

}  // namespace

const char* gizmoModeName(GizmoMode mode) {
    switch (mode) {
    case GizmoMode::Translate: return "translate";
    case GizmoMode::Rotate: return "rotate";
    case GizmoMode::Scale: return "scale";
    }
    return "translate";
}

std::optional<GizmoMode> parseGizmoMode(std::string_view name) {
    for (GizmoMode mode : {GizmoMode::Translate, GizmoMode::Rotate, GizmoMode::Scale})
        if (name == gizmoModeName(mode)) return mode;
    return std::nullopt;
}

float snapTo(float value, float step) { return step > 0.0f ? std::round(value / step) * step : value; }

glm::mat3 gizmoAxes(GizmoMode mode, GizmoSpace space, const glm::mat4& nodeWorld) {
    if (space == GizmoSpace::World && mode != GizmoMode::Scale) return glm::mat3(1.0f);
    glm::mat3 axes(nodeWorld);
    for (int i = 0; i < 3; ++i) {
        const float length = glm::length(axes[i]);
        axes[i] = length > 1e-12f ? axes[i] / length : glm::mat3(1.0f)[i];
    }
    return axes;
}

glm::mat4 applyGizmoDelta(GizmoMode mode, const GizmoDelta& delta, glm::vec3 pivot, const glm::mat4& startWorld) {
    switch (mode) {
    case GizmoMode::Translate: return glm::translate(glm::mat4(1.0f), delta.translation) * startWorld;
    case GizmoMode::Rotate: {
        const glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), delta.angle, delta.rotationAxis);
        return glm::translate(glm::mat4(1.0f), pivot) * rotation * glm::translate(glm::mat4(1.0f), -pivot) * startWorld;
    }
    case GizmoMode::Scale: return startWorld * glm::scale(glm::mat4(1.0f), delta.scale);
    }
    return startWorld;
}

int TransformGizmo::hitTest(GizmoMode mode, const CameraView& view, glm::vec2 viewport, glm::vec3 origin,
                            const glm::mat3& axes, glm::vec2 mouse) {
    const auto centre = projectToScreen(view, viewport, origin);
    if (!centre) return -1;
    if (mode == GizmoMode::Scale && std::abs(mouse.x - centre->x) <= kCentrePixels &&
        std::abs(mouse.y - centre->y) <= kCentrePixels)
        return kUniformHandle;
    int best = -1;
    float bestDistance = kPickPixels;
    for (int axis = 0; axis < 3; ++axis) {
        float distance = bestDistance + 1.0f;
        if (mode == GizmoMode::Rotate) {
            const std::vector<glm::vec3> ring =
                ringPoints(origin, axes[axis], kRingPixels * worldPerPixel(view, viewport, origin));
            std::optional<glm::vec2> previous;
            for (const glm::vec3& point : ring) {
                const auto screen = projectToScreen(view, viewport, point);
                if (screen && previous) distance = std::min(distance, distanceToSegment(mouse, *previous, *screen));
                previous = screen;
            }
        } else {
            const float length = TranslateGizmo::axisLength(view, viewport, origin);
            const auto end = projectToScreen(view, viewport, origin + axes[axis] * length);
            if (!end) continue;
            // An axis seen end-on is a dot: not grabbable (its drag would be undefined).
            if (glm::length(*end - *centre) < 4.0f) continue;
            distance = distanceToSegment(mouse, *centre, *end);
        }
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = axis;
        }
    }
    return best;
}

bool TransformGizmo::begin(GizmoMode mode, int handle, const CameraView& view, glm::vec2 viewport, glm::vec3 origin,
                           const glm::mat3& axes, glm::vec2 mouse) {
    if (handle < 0 || handle > kUniformHandle || (handle == kUniformHandle && mode != GizmoMode::Scale)) return false;
    mode_ = mode;
    origin_ = origin;
    startMouse_ = mouse;
    axisLength_ = TranslateGizmo::axisLength(view, viewport, origin);
    angle_ = 0.0f;
    if (handle < 3) axis_ = glm::normalize(axes[handle]);
    if (mode == GizmoMode::Rotate) {
        const auto centre = projectToScreen(view, viewport, origin);
        if (!centre) return false;
        centre_ = *centre;
        previousRawAngle_ = screenAngle(centre_, mouse);
    } else if (handle < 3) {
        const auto parameter = closestOnAxis(origin, axis_, screenRay(view, viewport, mouse));
        if (!parameter) return false;
        startParameter_ = *parameter;
    }
    handle_ = handle;
    return true;
}

GizmoDelta TransformGizmo::drag(const CameraView& view, glm::vec2 viewport, glm::vec2 mouse, const GizmoSnap& snap) {
    GizmoDelta delta;
    if (handle_ < 0) return delta;
    switch (mode_) {
    case GizmoMode::Translate: {
        const auto parameter = closestOnAxis(origin_, axis_, screenRay(view, viewport, mouse));
        if (!parameter) return delta;
        // Near the horizon a tiny mouse move is a huge distance: cap a single drag at a sane range.
        float moved = glm::clamp(*parameter - startParameter_, -1000.0f * axisLength_, 1000.0f * axisLength_);
        if (snap.enabled) moved = snapTo(moved, snap.translateStep);
        delta.translation = axis_ * moved;
        return delta;
    }
    case GizmoMode::Rotate: {
        const float raw = screenAngle(centre_, mouse);
        float step = raw - previousRawAngle_;
        if (step > kPi) step -= 2.0f * kPi;
        if (step < -kPi) step += 2.0f * kPi;
        angle_ += step;
        previousRawAngle_ = raw;
        // Counter-clockwise on screen is a positive turn about an axis pointing at the viewer.
        const bool towardsViewer = glm::dot(axis_, view.position - origin_) > 0.0f;
        float angle = towardsViewer ? angle_ : -angle_;
        if (snap.enabled) angle = glm::radians(snapTo(glm::degrees(angle), snap.rotateStepDegrees));
        delta.rotationAxis = axis_;
        delta.angle = angle;
        return delta;
    }
    case GizmoMode::Scale: {
        float factor = 1.0f;
        if (handle_ == kUniformHandle) {
            factor = 1.0f + (mouse.x - startMouse_.x) / kAxisPixels;
        } else {
            const auto parameter = closestOnAxis(origin_, axis_, screenRay(view, viewport, mouse));
            if (!parameter) return delta;
            factor = 1.0f + (*parameter - startParameter_) / axisLength_;
        }
        if (snap.enabled) factor = snapTo(factor, snap.scaleStep);
        factor = glm::clamp(factor, kMinScale, 1000.0f);
        if (handle_ == kUniformHandle) delta.scale = glm::vec3(factor);
        else delta.scale[handle_] = factor;
        return delta;
    }
    }
    return delta;
}

std::vector<OverlayLine> gizmoLines(GizmoMode mode, const CameraView& view, glm::vec2 viewport, glm::vec3 origin,
                                    const glm::mat3& axes, int highlightedHandle) {
    std::vector<OverlayLine> lines;
    const float pixel = worldPerPixel(view, viewport, origin);
    const float length = TransformGizmo::kAxisPixels * pixel;
    for (int axis = 0; axis < 3; ++axis) {
        const glm::vec4 color = axis == highlightedHandle ? kHighlight : axisColor(axis);
        const glm::vec3 direction = axes[axis];
        const glm::vec3 tip = origin + direction * length;
        switch (mode) {
        case GizmoMode::Translate: {
            lines.push_back({origin, tip, color});
            // Arrow head: four lines from the tip back to a point 20 % down the axis.
            glm::vec3 u, v;
            planeBasis(direction, u, v);
            const glm::vec3 back = tip - direction * (0.2f * length);
            for (const glm::vec3& side : {u, -u, v, -v}) lines.push_back({tip, back + side * (0.06f * length), color});
            break;
        }
        case GizmoMode::Rotate: {
            const std::vector<glm::vec3> ring = ringPoints(origin, direction, TransformGizmo::kRingPixels * pixel);
            for (std::size_t i = 1; i < ring.size(); ++i) lines.push_back({ring[i - 1], ring[i], color});
            break;
        }
        case GizmoMode::Scale:
            lines.push_back({origin, tip, color});
            addBox(lines, tip, axes, 0.05f * length, color);
            break;
        }
    }
    if (mode == GizmoMode::Scale)
        addBox(lines, origin, axes, TransformGizmo::kCentrePixels * 0.7f * pixel,
               highlightedHandle == TransformGizmo::kUniformHandle ? kHighlight : kCentreColor);
    return lines;
}

}  // namespace lit::editor
