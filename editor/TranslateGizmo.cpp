#include "TranslateGizmo.h"

#include <cmath>
#include <limits>

namespace lit::editor {

namespace {

glm::vec3 axisDirection(int axis) {
    glm::vec3 direction(0.0f);
    direction[axis] = 1.0f;
    return direction;
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float lengthSquared = glm::dot(ab, ab);
    const float t = lengthSquared > 0.0f ? glm::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

}  // namespace

ScreenRay screenRay(const CameraView& view, glm::vec2 viewport, glm::vec2 mouse) {
    const glm::vec2 ndc{2.0f * mouse.x / viewport.x - 1.0f, 1.0f - 2.0f * mouse.y / viewport.y};
    const glm::mat4 inverse = glm::inverse(view.viewProjection());
    glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    nearPoint /= nearPoint.w;
    farPoint /= farPoint.w;
    return {glm::vec3(nearPoint), glm::normalize(glm::vec3(farPoint - nearPoint))};
}

std::optional<glm::vec2> projectToScreen(const CameraView& view, glm::vec2 viewport, glm::vec3 point) {
    const glm::vec4 clip = view.viewProjection() * glm::vec4(point, 1.0f);
    if (clip.w <= 1e-6f) return std::nullopt;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::vec2((ndc.x + 1.0f) * 0.5f * viewport.x, (1.0f - ndc.y) * 0.5f * viewport.y);
}

std::optional<float> closestOnAxis(glm::vec3 origin, glm::vec3 axis, const ScreenRay& ray) {
    // Minimise |origin + s·axis − (ray.origin + t·ray.direction)| over s and t.
    const glm::vec3 w = origin - ray.origin;
    const float a = glm::dot(axis, axis), b = glm::dot(axis, ray.direction), c = 1.0f;
    const float d = glm::dot(axis, w), e = glm::dot(ray.direction, w);
    const float denominator = a * c - b * b;
    if (std::abs(denominator) < 1e-6f * a) return std::nullopt;
    return (b * e - c * d) / denominator;
}

float worldPerPixel(const CameraView& view, glm::vec2 viewport, glm::vec3 point) {
    const float distance = std::max(glm::dot(point - view.position, view.forward()), view.znear);
    return 2.0f * distance * std::tan(view.yfov * 0.5f) / std::max(viewport.y, 1.0f);
}

float TranslateGizmo::axisLength(const CameraView& view, glm::vec2 viewport, glm::vec3 origin) {
    return kAxisPixels * worldPerPixel(view, viewport, origin);
}

int TranslateGizmo::hitTest(const CameraView& view, glm::vec2 viewport, glm::vec3 origin, glm::vec2 mouse) {
    const auto start = projectToScreen(view, viewport, origin);
    if (!start) return -1;
    const float length = axisLength(view, viewport, origin);
    int best = -1;
    float bestDistance = kPickPixels;
    for (int axis = 0; axis < 3; ++axis) {
        const auto end = projectToScreen(view, viewport, origin + axisDirection(axis) * length);
        if (!end) continue;
        const float distance = distanceToSegment(mouse, *start, *end);
        // An axis seen end-on is a dot: not grabbable (its drag would be undefined).
        if (glm::length(*end - *start) < 4.0f) continue;
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = axis;
        }
    }
    return best;
}

bool TranslateGizmo::begin(int axis, const CameraView& view, glm::vec2 viewport, glm::vec3 origin, glm::vec2 mouse) {
    if (axis < 0 || axis > 2) return false;
    const auto parameter = closestOnAxis(origin, axisDirection(axis), screenRay(view, viewport, mouse));
    if (!parameter) return false;
    axis_ = axis;
    startOrigin_ = origin;
    startParameter_ = *parameter;
    return true;
}

glm::vec3 TranslateGizmo::drag(const CameraView& view, glm::vec2 viewport, glm::vec2 mouse) const {
    if (axis_ < 0) return startOrigin_;
    const glm::vec3 direction = axisDirection(axis_);
    const auto parameter = closestOnAxis(startOrigin_, direction, screenRay(view, viewport, mouse));
    if (!parameter) return startOrigin_;
    // Near the horizon a tiny mouse move is a huge distance: cap a single drag at a sane range.
    const float length = axisLength(view, viewport, startOrigin_);
    const float moved = glm::clamp(*parameter - startParameter_, -1000.0f * length, 1000.0f * length);
    return startOrigin_ + direction * moved;
}

}  // namespace lit::editor
