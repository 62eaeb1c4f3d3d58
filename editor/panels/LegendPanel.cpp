#include "panels/LegendPanel.h"

#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName: where the viewport bar is this frame

#include <algorithm>
#include <array>
#include <string>

namespace lit::editor {

namespace {

// Text width of the box, ImGui units: a sentence in three or four lines, and at most a bit under
// half the free area so the picture's centre stays clear.
constexpr float kMaxTextWidth = 260.0f;
constexpr float kMinTextWidth = 160.0f;
constexpr float kRampHeight = 12.0f;
constexpr float kSwatchSize = 10.0f;

ImU32 color(const std::array<float, 3>& c, float alpha = 1.0f) {
    return ImGui::GetColorU32(ImVec4(c[0], c[1], c[2], alpha));
}

void drawRamp(const LegendRamp& ramp, float width) {
    ImGui::TextUnformatted(ramp.label.c_str());
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    for (std::size_t i = 0; i + 1 < ramp.stops.size(); ++i) {
        const LegendStop& a = ramp.stops[i];
        const LegendStop& b = ramp.stops[i + 1];
        const float x0 = origin.x + a.position * width, x1 = origin.x + b.position * width;
        draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + kRampHeight), color(a.color),
                                      color(b.color), color(b.color), color(a.color));
    }
    draw->AddRect(origin, ImVec2(origin.x + width, origin.y + kRampHeight), IM_COL32(128, 128, 128, 255));
    // The stops' numbers under the ramp, centred on their stop and kept inside it.
    const float textY = origin.y + kRampHeight + 1.0f;
    for (const LegendStop& stop : ramp.stops) {
        const float w = ImGui::CalcTextSize(stop.label.c_str()).x;
        const float x = std::clamp(origin.x + stop.position * width - 0.5f * w, origin.x, origin.x + width - w);
        draw->AddLine(ImVec2(origin.x + stop.position * width, origin.y + kRampHeight - 3.0f),
                      ImVec2(origin.x + stop.position * width, origin.y + kRampHeight), IM_COL32(200, 200, 200, 255));
        draw->AddText(ImVec2(x, textY), ImGui::GetColorU32(ImGuiCol_Text), stop.label.c_str());
    }
    ImGui::Dummy(ImVec2(width, kRampHeight + ImGui::GetTextLineHeight() + 2.0f));
}

void drawSwatch(const LegendSwatch& swatch) {
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float h = ImGui::GetTextLineHeight();
    const ImVec2 a(p.x, p.y + 0.5f * (h - kSwatchSize)), b(a.x + kSwatchSize, a.y + kSwatchSize);
    ImGui::GetWindowDrawList()->AddRectFilled(
        a, b, ImGui::GetColorU32(ImVec4(swatch.color[0], swatch.color[1], swatch.color[2], swatch.color[3])));
    ImGui::GetWindowDrawList()->AddRect(a, b, IM_COL32(128, 128, 128, 255));
    ImGui::Dummy(ImVec2(kSwatchSize, h));
    ImGui::SameLine();
    ImGui::TextWrapped("%s", swatch.meaning.c_str());
}

bool drawVoxelControls(const ViewLegend& legend, DebugViewSettings& debug, int mipCount, float width) {
    bool changed = false;
    ImGui::PushItemWidth(width - ImGui::CalcTextSize("Channel").x - ImGui::GetStyle().ItemInnerSpacing.x);
    if (legend.sliceControls) {
        ImGui::TextUnformatted("Axis");
        for (int axis = 0; axis < 3; ++axis) {
            ImGui::SameLine();
            constexpr const char* kAxes[] = {"X", "Y", "Z"};
            changed |= ImGui::RadioButton(kAxes[axis], &debug.voxelSliceAxis, axis);
        }
        changed |= ImGui::SliderFloat("Slice", &debug.voxelSlice, 0.0f, 1.0f, "%.3f");
    }
    const int lastMip = std::max(mipCount - 1, 0);
    changed |= ImGui::SliderInt("Mip", &debug.voxelMip, 0, lastMip);
    constexpr std::array kChannels = {VoxelChannel::Radiance, VoxelChannel::Albedo, VoxelChannel::Normal,
                                      VoxelChannel::Opacity, VoxelChannel::Emission};
    const std::string preview(toString(debug.voxelChannel));
    if (ImGui::BeginCombo("Channel", preview.c_str())) {
        for (const VoxelChannel channel : kChannels) {
            const std::string name(toString(channel));
            if (ImGui::Selectable(name.c_str(), channel == debug.voxelChannel) && channel != debug.voxelChannel) {
                debug.voxelChannel = channel;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    ImGui::PopItemWidth();
    return changed;
}

}  // namespace

LegendBox drawLegend(const ViewLegend& legend, DebugViewSettings& debug, int mipCount, glm::vec4 area, bool* open) {
    LegendBox box;
    if (legend.empty()) return box;
    const float width = std::clamp(area.z * 0.45f, kMinTextWidth, kMaxTextWidth);
    // Flush in the area's bottom-left corner, as the viewport bar is in the bottom-right one; on
    // top of the bar's row when the area is too narrow for both side by side.
    float bottom = area.y + area.w;
    const float boxWidth = width + 2.0f * ImGui::GetStyle().WindowPadding.x;
    if (const ImGuiWindow* bar = ImGui::FindWindowByName("Viewport bar");
        bar != nullptr && bar->Active && bar->Pos.x < area.x + boxWidth)
        bottom = std::min(bottom, bar->Pos.y - ImGui::GetStyle().ItemSpacing.y);
    ImGui::SetNextWindowPos(ImVec2(area.x, bottom), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(boxWidth + 2.0f, std::max(bottom - area.y, 60.0f)));
    ImGui::SetNextWindowBgAlpha(0.72f);  // the picture stays visible behind it
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize |
                                        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("Legend", nullptr, kFlags)) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
        ImGui::TextUnformatted(legend.title.c_str());
        ImGui::SameLine(ImGui::GetCursorPosX() + width - ImGui::CalcTextSize("x").x -
                        2.0f * ImGui::GetStyle().FramePadding.x);
        if (ImGui::SmallButton("x")) *open = false;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Hide the legends (View > Legend brings them back)");
        ImGui::Separator();
        for (const std::string& line : legend.lines) ImGui::TextWrapped("%s", line.c_str());
        for (const LegendRamp& ramp : legend.ramps) drawRamp(ramp, width);
        for (const LegendSwatch& swatch : legend.swatches) drawSwatch(swatch);
        if (!legend.note.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.4f, 1.0f));
            ImGui::TextWrapped("%s", legend.note.c_str());
            ImGui::PopStyleColor();
        }
        if (legend.voxelControls) {
            ImGui::Separator();
            box.changed = drawVoxelControls(legend, debug, mipCount, width);
        }
        ImGui::PopTextWrapPos();
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        box.rect = {pos.x, pos.y, size.x, size.y};
    }
    ImGui::End();
    return box;
}

}  // namespace lit::editor
