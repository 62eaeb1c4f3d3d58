#include "ViewportInput.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include "EditorViews.h"
#include "FlyController.h"
#include "GizmoChoice.h"
#include "ViewportArea.h"
#include "SceneEdits.h"
#include "scene/SceneBuilder.h"

namespace lit::editor {

ViewportInput::ViewportInput(const Window& window, Document& doc, FlyCamera& camera, ViewportSettings& viewport,
                             GizmoTool& gizmoTool, const Renderer& renderer, Log& log)
    : window_(window),
      doc_(doc),
      camera_(camera),
      viewport_(viewport),
      gizmoTool_(gizmoTool),
      renderer_(renderer),
      log_(log) {}

ViewportInput::~ViewportInput() {
    if (looking_) glfwSetInputMode(window_.handle(), GLFW_CURSOR, GLFW_CURSOR_NORMAL);
}

CameraView ViewportInput::currentView() const {
    const glm::ivec2 framebuffer = window_.framebufferSize();
    const float aspect = framebuffer.x > 0 && framebuffer.y > 0
                             ? static_cast<float>(framebuffer.x) / static_cast<float>(framebuffer.y)
                             : 1.0f;
    // Near/far follow the camera: fitted to where it is in the scene, not to where it started
    // (a framing camera's near plane of metres would clip everything once inside a building).
    const glm::vec2 range = depthRangeFor(camera_.position, doc_.scene.worldBounds());
    return camera_.view(aspect, range.x, range.y);
}

void ViewportInput::updateFlyCamera(float dtSeconds) {
    ImGuiIO& io = ImGui::GetIO();
    GLFWwindow* window = window_.handle();
    FlyInput input;

    // Right-drag looks around. The drag starts only over the viewport (not over a panel) and
    // then keeps going wherever the cursor goes, which is hidden and unbounded meanwhile.
    const bool rightDown = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (!looking_ && rightDown && !io.WantCaptureMouse) {
        looking_ = true;
        // GLFW locks the cursor only for a focused window (X11 without a window manager gives
        // none focus); otherwise the visible cursor's motion is used, which works as well until
        // it reaches the screen's edge.
        if (glfwGetWindowAttrib(window, GLFW_FOCUSED) == GLFW_TRUE)
            glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
        glfwGetCursorPos(window, &lastCursor_.x, &lastCursor_.y);  // after the mode change, which moves it
        io.ConfigFlags |= ImGuiConfigFlags_NoMouse;                // panels ignore the hidden cursor
    } else if (looking_ && !rightDown) {
        looking_ = false;
        glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
        io.ConfigFlags &= ~ImGuiConfigFlags_NoMouse;
    }
    if (looking_) {
        glm::dvec2 cursor;
        glfwGetCursorPos(window, &cursor.x, &cursor.y);
        input.lookPixels = glm::vec2(cursor - lastCursor_);
        lastCursor_ = cursor;
    }

    // Keys fly the camera only while the right mouse button looks around (as in Unity, Godot
    // and Unreal), so W / E / R are free to pick the gizmo otherwise; not while a text field or
    // a dragged widget has the keyboard, nor with Ctrl (Ctrl+S saves rather than backing away).
    if (looking_ && !io.WantCaptureKeyboard && !io.KeyCtrl) {
        auto held = [window](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
        input.move.x = held(GLFW_KEY_D) - held(GLFW_KEY_A);
        input.move.y = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
        input.move.z = held(GLFW_KEY_W) - held(GLFW_KEY_S);
        input.fast = held(GLFW_KEY_LEFT_SHIFT) > 0.0f || held(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
    }
    if (looking_ || !io.WantCaptureMouse) input.wheelSteps = io.MouseWheel;
    applyFlyInput(camera_, input, dtSeconds);
}

void ViewportInput::handleMouse(const CameraView& view) {
    const ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 mouse(io.MousePos.x, io.MousePos.y);
    const bool selection = doc_.selectedNode >= 0 && doc_.selectedNode < static_cast<int>(doc_.scene.nodes.size());
    const bool gizmoShown = selection && viewport_.markers && !viewport_.coneDirections;

    // Alt + left drag orbits around the selection (Blender's and Godot's orbit), whatever view.
    if (orbiting_) {
        if (!io.MouseDown[ImGuiMouseButton_Left]) {
            orbiting_ = false;
        } else {
            orbitAround(camera_, orbitPivot_, glm::vec2(glm::dvec2(io.MousePos.x, io.MousePos.y) - orbitCursor_));
            orbitCursor_ = glm::dvec2(io.MousePos.x, io.MousePos.y);
        }
        return;
    }
    if (gizmo_.active()) {
        if (io.MouseDown[ImGuiMouseButton_Left] && selection)
            continueGizmoDrag(view, mouse, io.KeyCtrl);
        else
            endGizmoDrag();
        return;
    }
    hoveredGizmoAxis_ = -1;
    if (io.WantCaptureMouse || looking_) return;
    // Only the visible viewport answers: not the gaps between the panels, nor the picture behind
    // a docked one (the whole window until the first layout).
    if (visibleArea_.z > 1.0f && !insideArea(visibleArea_, mouse)) return;
    if (io.KeyAlt && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        orbiting_ = true;
        orbitCursor_ = glm::dvec2(io.MousePos.x, io.MousePos.y);
        // Around the selection; without one, around the point as far ahead as the scene's centre.
        const Aabb bounds = doc_.scene.worldBounds();
        const float ahead = bounds.empty() ? 2.0f : std::max(glm::length(bounds.center() - camera_.position), 0.5f);
        orbitPivot_ =
            selection ? nodeWorldPosition(doc_.scene, doc_.selectedNode) : camera_.position + camera_.forward() * ahead;
        return;
    }
    // The shadow map and the voxel slice are 2D images: clicks there point at nothing.
    if (isFlatView(doc_.settings.debug.view)) return;
    if (gizmoShown) {
        const glm::vec2 display(io.DisplaySize.x, io.DisplaySize.y);
        const GizmoMode mode = gizmoMode();
        const glm::mat3 axes =
            gizmoAxes(mode, gizmoTool_.space, doc_.scene.nodes[static_cast<std::size_t>(doc_.selectedNode)].world);
        hoveredGizmoAxis_ = TransformGizmo::hitTest(mode, view, display,
                                                    nodeWorldPosition(doc_.scene, doc_.selectedNode), axes, mouse);
    }
    if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
    if (hoveredGizmoAxis_ >= 0 && beginGizmoDrag(view, mouse)) return;
    pickAt(mouse);
}

bool ViewportInput::dragGizmo(const CameraView& view, glm::vec2 from, glm::vec2 to) {
    if (!beginGizmoDrag(view, from)) return false;
    constexpr int kSteps = 16;
    for (int i = 1; i <= kSteps; ++i) {
        const float t = static_cast<float>(i) / kSteps;
        continueGizmoDrag(view, from + t * (to - from), false);
    }
    endGizmoDrag();
    return true;
}

bool ViewportInput::beginGizmoDrag(const CameraView& view, glm::vec2 mouse) {
    if (doc_.selectedNode < 0 || doc_.selectedNode >= static_cast<int>(doc_.scene.nodes.size())) return false;
    const ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 display(io.DisplaySize.x, io.DisplaySize.y);
    const Node& active = doc_.scene.nodes[static_cast<std::size_t>(doc_.selectedNode)];
    const glm::vec3 origin = nodeWorldPosition(doc_.scene, doc_.selectedNode);
    const GizmoMode mode = gizmoMode();
    const glm::mat3 axes = gizmoAxes(mode, gizmoTool_.space, active.world);
    const int handle = TransformGizmo::hitTest(mode, view, display, origin, axes, mouse);
    if (handle < 0 || !gizmo_.begin(mode, handle, view, display, origin, axes, mouse)) return false;
    const std::vector<int> top = topLevelSelection(doc_);
    dragged_.clear();
    for (const int node : top) {
        const Node& n = doc_.scene.nodes[static_cast<std::size_t>(node)];
        dragged_.push_back({node, n.world, n.translation, n.scale});
    }
    const std::string what = top.size() == 1 ? (active.name.empty() ? std::string("node") : active.name)
                                             : std::to_string(top.size()) + " nodes";
    const char* verb = mode == GizmoMode::Translate ? "Move " : mode == GizmoMode::Rotate ? "Rotate " : "Scale ";
    doc_.beginEdit(verb + what);
    hoveredGizmoAxis_ = handle;
    return true;
}

void ViewportInput::continueGizmoDrag(const CameraView& view, glm::vec2 mouse, bool snap) {
    const ImGuiIO& io = ImGui::GetIO();
    GizmoSnap steps = gizmoTool_.snap;
    steps.enabled = steps.enabled || snap;
    const GizmoDelta delta = gizmo_.drag(view, {io.DisplaySize.x, io.DisplaySize.y}, mouse, steps);
    Scene& scene = doc_.scene;
    for (const DraggedNode& d : dragged_) {
        if (d.node >= static_cast<int>(scene.nodes.size())) continue;
        Node& node = scene.nodes[static_cast<std::size_t>(d.node)];
        const glm::mat4 parentWorld =
            node.parent >= 0 ? scene.nodes[static_cast<std::size_t>(node.parent)].world : glm::mat4(1.0f);
        switch (gizmo_.mode()) {
            case GizmoMode::Translate:
                // Only the translation changes: no rotation or scale noise from a matrix round trip.
                node.translation =
                    d.translation + glm::vec3(glm::inverse(parentWorld) * glm::vec4(delta.translation, 0.0f));
                break;
            case GizmoMode::Scale:
                node.scale = d.scale * delta.scale;
                break;
            case GizmoMode::Rotate:
                setWorldMatrix(scene, d.node, applyGizmoDelta(GizmoMode::Rotate, delta, gizmo_.origin(), d.world));
                node.scale = d.scale;  // a rotation changes no scale; keep it exact
                break;
        }
    }
    doc_.touched(Change::Transform);
}

void ViewportInput::endGizmoDrag() {
    gizmo_.end();
    dragged_.clear();
    doc_.endEdit();
}

std::string ViewportInput::pickAt(glm::vec2 windowPixel) {
    // Window pixels → the renderer's output, which is the window scaled by the render scale.
    const glm::vec2 display(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
    const glm::vec2 output(static_cast<float>(doc_.settings.output.width),
                           static_cast<float>(doc_.settings.output.height));
    if (display.x <= 0.0f || display.y <= 0.0f || windowPixel.x < 0.0f || windowPixel.y < 0.0f ||
        windowPixel.x >= display.x || windowPixel.y >= display.y)
        return "pick: (" + std::to_string(windowPixel.x) + ", " + std::to_string(windowPixel.y) +
               ") is outside the window";
    const glm::ivec2 pixel(glm::floor(windowPixel * output / display));
    if (viewport_.coneDirections) {
        coneSurface_ = renderer_.surfaceAt(pixel);
        coneCameraPosition_ = camera_.position;
        if (!coneSurface_) log_.info("cone directions: no surface under the cursor");
        return "";
    }
    const std::optional<PickedPrimitive> picked = renderer_.pickPrimitive(pixel);
    // Shift+click adds to (or takes from) the selection; a click on nothing with Shift keeps it.
    if (ImGui::GetIO().KeyShift || !picked) {
        doc_.select(picked ? picked->node : -1, ImGui::GetIO().KeyShift);
        return "";
    }
    doc_.clickPrimitive(picked->node, picked->primitive);
    return "";
}

std::string ViewportInput::setView(const std::string& name) {
    viewport_.coneDirections = name == kConeDirectionsView;
    if (viewport_.coneDirections) {
        doc_.settings.debug.view = View::Final;
        return "";
    }
    coneSurface_.reset();
    const std::optional<View> view = parseView(name);
    if (!view) return "unknown view '" + name + "'";
    doc_.settings.debug.view = *view;
    return "";
}

void ViewportInput::frameSelection() {
    const std::vector<int> selected = doc_.selection();
    if (selected.empty()) return;
    Aabb bounds;
    for (const int node : selected) {
        const Aabb b = nodeWorldBounds(doc_.scene, node);
        bounds.extend(b.min);
        bounds.extend(b.max);
    }
    // The near plane follows the camera each frame (currentView, depthRangeFor), so the framed
    // object is never clipped.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    frameBoundsInArea(camera_, bounds, {display.x, display.y}, visibleArea_);
}

void ViewportInput::forgetConeSurface() { coneSurface_.reset(); }

GizmoMode ViewportInput::gizmoMode() const { return gizmoModeFor(gizmoTool_, doc_.scene, doc_.selectedNode); }

OverlayOptions ViewportInput::overlayOptions(bool cleanViewport) const {
    OverlayOptions options;
    options.markers = viewport_.markers && !cleanViewport;
    options.gizmo = viewport_.markers && !viewport_.coneDirections && !cleanViewport;
    options.cameraPath = viewport_.markers && !cleanViewport;
    options.selectionOutline = !cleanViewport;
    options.hoveredGizmoAxis = gizmo_.active() ? gizmo_.handle() : hoveredGizmoAxis_;
    options.gizmoMode = gizmo_.active() ? gizmo_.mode() : gizmoMode();
    options.gizmoSpace = gizmoTool_.space;
    if (viewport_.coneDirections && coneSurface_) {
        options.coneSurface = coneSurface_;
        options.coneCameraPosition = coneCameraPosition_;
    }
    return options;
}

}  // namespace lit::editor
