#include "panels/TimelinePanel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

#include "DocumentIO.h"
#include "animation/CameraPathIO.h"
#include "animation/NodeAnimation.h"

namespace lit::editor {

namespace {

constexpr float kRulerHeight = 44.0f;  // ImGui units
constexpr float kKeyRadius = 6.0f;     // half the diamond's width
constexpr float kDegPerRad = 57.2957795f;

using TimeRange = TimelinePanel::TimeRange;

// Time shown across the ruler: the span the playhead can be scrubbed over (PathEditing's
// scrubSpan, which reaches past the last key and the node animations' end) with a small margin
// either side.
TimeRange rangeOf(const CameraPath& path, double animationEnd) {
    const TimeSpan span = scrubSpan(path, animationEnd);
    const double margin = (span.end - span.start) * 0.03;
    return {span.start - margin, span.end + margin};
}

// Tick spacing that leaves at least ~60 units between labels.
double tickStep(const TimeRange& range, float width) {
    const double seconds = range.end - range.start;
    for (double step : {0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 30.0, 60.0, 120.0, 300.0})
        if (step / seconds * width >= 60.0) return step;
    return 600.0;
}

void lookAtPlayhead(const Document& doc, const PathPlayback& playback, FlyCamera& camera) {
    if (!playback.lookThrough) return;
    lookThroughPath(doc.cameraPath, playback.time, camera);
}

}  // namespace

// The ruler: ticks, keys, playhead. Click a key to select it (and jump there), drag it to
// retime (one undo step per drag), click or drag elsewhere to scrub. While the mouse is held the
// ruler keeps the scale it had when pressed: dragging the last key would otherwise stretch the
// ruler under the mouse, and the key would run away from it.
void TimelinePanel::drawRuler(Document& doc, PathPlayback& playback, FlyCamera& camera) {
    int& draggedKey = draggedKey_;
    const double animationEnd = summarizeNodeAnimations(doc.scene).endTime;
    const float width = std::max(ImGui::GetContentRegionAvail().x, 50.0f);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##ruler", ImVec2(width, kRulerHeight));
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    if (!active) heldRange_.reset();
    const TimeRange range = heldRange_ ? *heldRange_ : rangeOf(doc.cameraPath, animationEnd);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + kRulerHeight), IM_COL32(30, 30, 34, 255), 3.0f);

    // Ticks with labels along the top.
    const double step = tickStep(range, width);
    for (double t = std::ceil(range.start / step) * step; t <= range.end; t += step) {
        const float x = range.toX(t, origin.x, width);
        draw->AddLine(ImVec2(x, origin.y), ImVec2(x, origin.y + 8.0f), IM_COL32(150, 150, 150, 255));
        char label[32];
        std::snprintf(label, sizeof label, "%gs", t);
        draw->AddText(ImVec2(x + 2.0f, origin.y), IM_COL32(150, 150, 150, 255), label);
    }

    // The node animations' span, a thin bar along the bottom: they play from 0 s on the same clock.
    if (animationEnd > 0.0) {
        const float startX = range.toX(0.0, origin.x, width), endX = range.toX(animationEnd, origin.x, width);
        draw->AddRectFilled(ImVec2(startX, origin.y + kRulerHeight - 4.0f), ImVec2(endX, origin.y + kRulerHeight),
                            IM_COL32(90, 150, 90, 255), 1.0f);
    }
    // The path's own span, lighter: the ruler goes on past its end for scrubbing and adding keys.
    if (!doc.cameraPath.empty()) {
        const float startX = range.toX(doc.cameraPath.startTime(), origin.x, width);
        const float endX = range.toX(doc.cameraPath.endTime(), origin.x, width);
        draw->AddRectFilled(ImVec2(startX, origin.y + 12.0f), ImVec2(endX, origin.y + kRulerHeight - 4.0f),
                            IM_COL32(52, 56, 68, 255), 2.0f);
    }
    // Keys as diamonds on the middle line.
    const float keyY = origin.y + kRulerHeight * 0.62f;
    draw->AddLine(ImVec2(origin.x, keyY), ImVec2(origin.x + width, keyY), IM_COL32(70, 70, 80, 255));
    const std::vector<CameraKey>& keys = doc.cameraPath.keys();
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const float x = range.toX(keys[i].time, origin.x, width);
        const bool selected = static_cast<int>(i) == doc.selectedKey;
        const float r = selected ? kKeyRadius + 1.5f : kKeyRadius;
        const ImU32 color = selected ? IM_COL32(255, 170, 40, 255) : IM_COL32(200, 200, 210, 255);
        draw->AddQuadFilled(ImVec2(x, keyY - r), ImVec2(x + r, keyY), ImVec2(x, keyY + r), ImVec2(x - r, keyY), color);
    }
    // The key nearest the mouse within a diamond's reach (plus 2 units of slack) is the one picked.
    const double secondsPerUnit = (range.end - range.start) / width;
    const int keyUnderMouse = hovered && std::abs(mouse.y - keyY) <= kKeyRadius + 4.0f
                                  ? keyNear(doc.cameraPath, range.toTime(mouse.x, origin.x, width),
                                            (kKeyRadius + 2.0f) * secondsPerUnit)
                                  : -1;

    // Playhead.
    if (hasTimeline(doc.cameraPath, animationEnd)) {
        const float x = range.toX(playback.time, origin.x, width);
        draw->AddLine(ImVec2(x, origin.y), ImVec2(x, origin.y + kRulerHeight), IM_COL32(80, 200, 255, 255), 2.0f);
    }

    if (ImGui::IsItemActivated()) {
        heldRange_ = range;
        if (keyUnderMouse >= 0) {
            draggedKey = keyUnderMouse;
            doc.selectedKey = keyUnderMouse;
            playback.time = keys[static_cast<std::size_t>(keyUnderMouse)].time;
            playback.playing = false;
            doc.beginEdit("Retime Key");
            lookAtPlayhead(doc, playback, camera);
        } else {
            draggedKey = -1;
        }
    }
    if (active) {
        const double t = range.toTime(mouse.x, origin.x, width);
        if (draggedKey >= 0 && static_cast<std::size_t>(draggedKey) < keys.size()) {
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2.0f)) {
                CameraKey key = keys[static_cast<std::size_t>(draggedKey)];
                key.time = static_cast<float>(t);
                setKeyValues(doc, static_cast<std::size_t>(draggedKey), key);
                playback.time = doc.cameraPath.keys()[static_cast<std::size_t>(draggedKey)].time;
            }
        } else if (hasTimeline(doc.cameraPath, animationEnd)) {
            // The whole ruler scrubs, past the last key too (the camera stays at the last pose there).
            const TimeSpan span = scrubSpan(doc.cameraPath, animationEnd);
            playback.playing = false;
            playback.time = std::clamp(t, span.start, span.end);
            lookAtPlayhead(doc, playback, camera);
        }
    }
    if (ImGui::IsItemDeactivated() && draggedKey >= 0) {
        doc.endEdit();  // one undo step for the whole drag (none if the key did not move)
        draggedKey = -1;
    }
    if (hovered && keyUnderMouse >= 0)
        ImGui::SetTooltip("key %d at %.3f s (drag to retime)", keyUnderMouse,
                          static_cast<double>(keys[static_cast<std::size_t>(keyUnderMouse)].time));
}

namespace {

// Undo bracket for one widget: the whole interaction (a drag, a typed value) is one step.
void bracket(Document& doc, const char* label, bool changed, auto&& apply) {
    if (ImGui::IsItemActivated()) doc.beginEdit(label);
    if (changed) apply();
    if (ImGui::IsItemDeactivated()) doc.endEdit();
}

void drawSelectedKey(Document& doc, FlyCamera& camera, PathPlayback& playback) {
    const std::vector<CameraKey>& keys = doc.cameraPath.keys();
    if (doc.selectedKey < 0 || static_cast<std::size_t>(doc.selectedKey) >= keys.size()) {
        ImGui::TextDisabled("No key selected: click a key on the ruler");
        return;
    }
    const std::size_t index = static_cast<std::size_t>(doc.selectedKey);
    CameraKey key = keys[index];
    ImGui::Text("Key %zu", index);
    ImGui::SameLine();
    if (ImGui::SmallButton("Update from view")) updateKeyFromCamera(doc, index, camera);
    ImGui::SameLine();
    if (ImGui::SmallButton("Delete")) {
        deleteKey(doc, index);
        return;
    }
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.3f);
    float time = key.time;
    bool changed = ImGui::DragFloat("Time (s)", &time, 0.01f, 0.0f, 0.0f, "%.3f");
    bracket(doc, "Retime Key", changed, [&] {
        key.time = time;
        setKeyValues(doc, index, key);
        playback.time = doc.cameraPath.keys()[index].time;
    });
    ImGui::SameLine();
    float fov = key.yfov * kDegPerRad;
    changed = ImGui::DragFloat("FOV (deg)", &fov, 0.2f, 1.0f, 170.0f, "%.1f");
    bracket(doc, "Key FOV", changed, [&] {
        key.yfov = fov / kDegPerRad;
        setKeyValues(doc, index, key);
    });
    ImGui::PopItemWidth();
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    glm::vec3 position = key.position;
    changed = ImGui::DragFloat3("Position (m)", &position.x, 0.01f);
    bracket(doc, "Move Key", changed, [&] {
        key.position = position;
        setKeyValues(doc, index, key);
    });
    glm::vec3 euler = glm::degrees(glm::eulerAngles(key.rotation));
    changed = ImGui::DragFloat3("Rotation (deg)", &euler.x, 0.5f);
    bracket(doc, "Rotate Key", changed, [&] {
        key.rotation = glm::quat(glm::radians(euler));
        setKeyValues(doc, index, key);
    });
    ImGui::PopItemWidth();
}

}  // namespace

void TimelinePanel::draw(Document& doc, PathPlayback& playback, FlyCamera& camera, const Placement& placement, bool* open) {
    placeNextWindow(placement);
    if (!ImGui::Begin("Timeline", open)) {
        ImGui::End();
        return;
    }
    // Which camera animation of the file the path edits (a Blender file's "fly", the editor's own
    // "camera path"); switching is one undo step.
    {
        std::vector<std::string> names = doc.cameraAnimations;
        if (std::find(names.begin(), names.end(), doc.cameraPathName) == names.end()) names.insert(names.begin(), doc.cameraPathName);
        if (std::find(names.begin(), names.end(), std::string(kDefaultCameraAnimation)) == names.end())
            names.push_back(kDefaultCameraAnimation);
        ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Animation").x - 8.0f, 60.0f));
        if (ImGui::BeginCombo("Animation", doc.cameraPathName.c_str())) {
            for (const std::string& name : names) {
                const bool inFile = std::find(doc.cameraAnimations.begin(), doc.cameraAnimations.end(), name) !=
                                    doc.cameraAnimations.end();
                const std::string label = inFile ? name : name + " (new)";
                if (ImGui::Selectable(label.c_str(), name == doc.cameraPathName)) {
                    chooseError_ = chooseCameraAnimation(doc, name);
                    playback.playing = false;
                    if (!doc.cameraPath.empty()) playback.time = doc.cameraPath.startTime();
                }
            }
            ImGui::EndCombo();
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The camera animation of the file that the keys below edit; saved under this name");
        if (!chooseError_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", chooseError_.c_str());
    }
    CameraPath& path = doc.cameraPath;
    const NodeAnimationSummary animations = summarizeNodeAnimations(doc.scene);
    // Transport and the key actions that need no selection.
    if (ImGui::Button(playback.playing ? "Pause" : "Play")) {
        if (playback.playing) playback.playing = false; else playback.play(path, animations.endTime);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Play the path and the animated nodes from the playhead (Space)");
    ImGui::SameLine();
    if (ImGui::Button("|<") && hasTimeline(path, animations.endTime)) {
        playback.time = playSpan(path, animations.endTime).start;
        lookAtPlayhead(doc, playback, camera);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the start");
    ImGui::SameLine();
    if (ImGui::Button("+ Key")) addKeyFromView(doc, playback, camera);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Add a key with the current view: %.2f s after the last key, or at the playhead when it is "
                          "between keys or past the end; the playhead moves to it",
                          path.keys().size() < 2 ? static_cast<double>(kDefaultKeyInterval)
                                                 : static_cast<double>(nextKeyTime(path, path.endTime()) - path.endTime()));
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Speed").x - 8.0f, 60.0f));
    ImGui::SliderFloat("Speed", &playback.speed, kMinPlaybackSpeed, kMaxPlaybackSpeed, "%.2fx",
                       ImGuiSliderFlags_Logarithmic);

    // Path options, each one undo step.
    CameraPathOptions options = path.options();
    bool optionsChanged = ImGui::Checkbox("Loop", &options.loop);
    ImGui::SameLine();
    optionsChanged |= ImGui::Checkbox("Even speed", &options.constantSpeed);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Constant speed along the curve, whatever the key spacing");
    ImGui::SameLine();
    optionsChanged |= ImGui::Checkbox("Ease", &options.easeInOut);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Start and stop at rest (open paths)");
    if (optionsChanged) setPathOptions(doc, options);
    ImGui::SameLine();
    ImGui::Checkbox("Look through", &playback.lookThrough);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The viewport follows the path while playing or scrubbing");

    if (animations.channels > 0) {
        ImGui::Text("%d animated node%s, 0 to %.2f s", animations.nodes, animations.nodes == 1 ? "" : "s",
                    animations.endTime);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The file's node animations play with the path on one clock. They override the "
                              "channels they drive: a gizmo edit of an animated node changes its other channels");
    }
    if (path.empty()) {
        if (animations.channels > 0) ImGui::Text("%.2f s%s", playback.time, playback.playing ? ", playing" : "");
        ImGui::TextDisabled("No keys: fly to a view, + Key; next view, + Key");
    } else {
        ImGui::Text("%.2f s, %zu keys%s", playback.time, path.keys().size(), playback.playing ? ", playing" : "");
        // The duration scales every key's time about the first key; one undo step per drag.
        ImGui::SameLine();
        ImGui::BeginDisabled(path.keys().size() < 2);
        float duration = path.duration();
        ImGui::SetNextItemWidth(90.0f);
        const bool changed = ImGui::DragFloat("Duration (s)", &duration, 0.02f, kMinKeySpacing, 3600.0f, "%.2f");
        bracket(doc, "Path Duration", changed, [&] { scalePathDuration(doc, duration); });
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("From the first key to the last; changing it spreads the keys in proportion");
        ImGui::EndDisabled();
    }

    drawRuler(doc, playback, camera);
    drawSelectedKey(doc, camera, playback);
    ImGui::End();
}

}  // namespace lit::editor
