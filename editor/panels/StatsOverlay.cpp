#include "panels/StatsOverlay.h"

#include "gi/GiPacer.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace lit::editor {

namespace {

constexpr float kGraphHeight = 48.0f;  // ImGui units
constexpr float kBarHeight = 14.0f;

// The GPU cost of a pass to show: this frame's when it ran, else what it cost the last time it
// ran (greyed in the table), so the bar does not flicker between "voxelize" and nothing.
struct ShownTiming {
    const PassTiming* timing = nullptr;
    bool current = false;
};

ShownTiming shownTiming(const Profiler& profiler, const PassTiming& pass) {
    if (pass.ran) return {&pass, true};
    return {profiler.lastRun(pass.name), false};
}

void drawFrameGraph(const FrameTimer& timer, float width) {
    const std::vector<float> history = timer.historyMs();
    if (history.empty()) return;
    const float worst = *std::max_element(history.begin(), history.end());
    // Round the scale up to a readable value so the graph does not rescale every frame.
    constexpr std::array<float, 10> kScales = {8.0f, 17.0f, 34.0f, 50.0f, 100.0f, 250.0f, 500.0f, 1000.0f, 2500.0f, 10000.0f};
    float scale = kScales.back();
    for (float s : kScales)
        if (worst <= s) {
            scale = s;
            break;
        }
    char label[64];
    std::snprintf(label, sizeof label, "0-%.0f ms", static_cast<double>(scale));
    ImGui::PlotLines("##frame-times", history.data(), static_cast<int>(history.size()), 0, label, 0.0f, scale,
                     ImVec2(width, kGraphHeight));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Frame time over the last %.0f s (%zu frames); worst %.1f ms", FrameTimer::kHistorySeconds,
                          history.size(), static_cast<double>(worst));
}

void drawStackedBar(const Profiler& profiler, float width) {
    double total = 0.0;
    for (const PassTiming& pass : profiler.timings()) {
        const ShownTiming shown = shownTiming(profiler, pass);
        if (shown.timing && shown.current) total += shown.timing->gpuMs;
    }
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + kBarHeight), IM_COL32(40, 40, 40, 200));
    float x = origin.x;
    const PassTiming* hovered = nullptr;
    if (total > 0.0) {
        for (const PassTiming& pass : profiler.timings()) {
            const ShownTiming shown = shownTiming(profiler, pass);
            if (!shown.timing || !shown.current || shown.timing->gpuMs <= 0.0) continue;
            const float w = static_cast<float>(shown.timing->gpuMs / total) * width;
            const ImVec2 a(x, origin.y), b(x + w, origin.y + kBarHeight);
            draw->AddRectFilled(a, b, passColor(pass.name));
            if (ImGui::IsMouseHoveringRect(a, b)) hovered = &pass;
            x += w;
        }
    }
    ImGui::Dummy(ImVec2(width, kBarHeight));
    if (hovered && ImGui::IsItemHovered())
        ImGui::SetTooltip("%s: %.2f ms (%.0f%% of the GPU frame)", hovered->name.c_str(), hovered->gpuMs,
                          100.0 * hovered->gpuMs / total);
}

}  // namespace

ImU32 passColor(const std::string& passName) {
    struct Entry {
        const char* name;
        ImU32 color;
    };
    static constexpr std::array<Entry, 10> kColors = {{
        {"shadow", IM_COL32(120, 120, 200, 255)},
        {"g-buffer", IM_COL32(90, 170, 230, 255)},
        {"voxelize", IM_COL32(230, 160, 60, 255)},
        {"inject", IM_COL32(240, 210, 80, 255)},
        {"mipmap", IM_COL32(200, 120, 60, 255)},
        {"lighting", IM_COL32(110, 200, 120, 255)},
        {"cone trace", IM_COL32(220, 90, 90, 255)},
        {"post", IM_COL32(180, 110, 200, 255)},
        {"GPU wait", IM_COL32(90, 90, 90, 255)},
        {"overlay", IM_COL32(160, 160, 160, 255)},
    }};
    for (const Entry& entry : kColors)
        if (passName == entry.name) return entry.color;
    // Unknown passes: a stable colour from the name.
    std::size_t hash = std::hash<std::string>{}(passName);
    return IM_COL32(100 + hash % 130, 100 + (hash >> 8) % 130, 100 + (hash >> 16) % 130, 255);
}

namespace {

// The compact overlay's second line: is the image this frame's, and is the light done.
std::string frameState(const FrameStats& stats, const ViewportFrameInfo& frame) {
    std::string state = frame.rendered ? "rendered (" + std::string(frame.reason) + ")"
                        : frame.giOnly ? "GI only, image reused " + std::to_string(frame.framesReused)
                                       : "idle, reused " + std::to_string(frame.framesReused);
    char gi[64] = "";
    if (stats.giUpdateDone < 1.0f)
        std::snprintf(gi, sizeof gi, "  GI %.0f %%", 100.0 * static_cast<double>(stats.giUpdateDone));
    else if (!stats.giUpdateStage.empty())
        std::snprintf(gi, sizeof gi, "  GI %s", stats.giUpdateStage.c_str());
    else if (stats.giBounces > 0 && !stats.giRefining)
        std::snprintf(gi, sizeof gi, "  GI converged");
    return state + gi;
}

// A small button at the end of the first line that shows or hides the details.
void detailsButton(bool* details) {
    ImGui::SameLine();
    if (ImGui::SmallButton(*details ? "-" : "+")) *details = !*details;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(*details ? "Back to the two-line summary" : "Frame-time graph, GPU time per pass, draws, voxels");
}

}  // namespace

glm::vec4 drawStatsOverlay(const FrameTimer& timer, const Profiler& profiler, const FrameStats& stats,
                           glm::ivec2 renderSize, ImFont* monoFont, const Placement& placement, bool* open,
                           bool* details, const VoxelVolume* voxels, const ViewportFrameInfo& frame) {
    placeNextWindow(placement);
    ImGui::SetNextWindowBgAlpha(0.72f);  // an overlay: the image stays visible behind it
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                        ImGuiWindowFlags_NoSavedSettings;
    if (!ImGui::Begin("Performance", open, kFlags)) {
        ImGui::End();
        return glm::vec4(0.0f);
    }
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    const glm::vec4 rect(pos.x, pos.y, size.x, size.y);
    if (!*details) {
        // By default two lines, so the overlay does not hide the scene it measures.
        ImGui::PushFont(monoFont);
        ImGui::Text("%5.1f FPS %7.1f ms  GPU %6.1f ms", timer.fps(), timer.averageMs(), profiler.totalGpuMs());
        detailsButton(details);
        ImGui::TextDisabled("%s", frameState(stats, frame).c_str());
        ImGui::PopFont();
        ImGui::End();
        return rect;
    }
    ImGui::PushFont(monoFont);
    const float width = std::max(ImGui::CalcTextSize("Draws 000000  Triangles 00000000000").x, 260.0f);
    ImGui::Text("%6.1f FPS  frame %7.1f ms", timer.fps(), timer.averageMs());
    detailsButton(details);
    ImGui::Text("CPU %7.1f ms  GPU %7.1f ms", profiler.lastCpuFrameMs(), profiler.totalGpuMs());
    drawFrameGraph(timer, width);
    // Redraw on demand: say whether the image and the numbers below come from this frame.
    if (frame.rendered) {
        ImGui::Text("3D frame rendered (%.*s)", static_cast<int>(frame.reason.size()), frame.reason.data());
    } else if (frame.giOnly) {
        ImGui::TextDisabled("GI only: last image reused (%d)", frame.framesReused);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "The GI worked under its time budget (GI ms / frame) without rendering the image;\n"
                "it is rendered again when the update completes, and now and then meanwhile.");
    } else {
        ImGui::TextDisabled("idle: last frame reused (%d)", frame.framesReused);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Nothing the 3D image shows changed: the last rendered image is shown again\n"
                "under the UI. The timings below are of that frame (%.1f ms).",
                frame.renderFrameMs);
    }
    ImGui::Text("Render %d x %d px  scale %.2f", renderSize.x, renderSize.y, frame.renderScale);
    ImGui::Text("Draws %d  Triangles %zu", stats.drawCalls, stats.triangles);
    ImGui::Text("Culling: %d of %d draws, %.2f ms", stats.drawsSubmitted, stats.drawsTotal, stats.cullMs);
    constexpr double kMiB = 1024.0 * 1024.0;
    ImGui::Text("Voxels %.1f MiB%s%s", static_cast<double>(stats.voxelBytes) / kMiB, stats.voxelized ? " [voxelized]" : "",
                stats.injected ? " [injected]" : "");
    // The report is formatted only while someone reads it, not every frame.
    if (voxels && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", voxels->memoryReport().c_str());
    if (!stats.nearLevels.empty()) {
        // Each volume's share: the scene's, then the near levels around the camera, finest first.
        std::size_t nearBytes = 0;
        for (const FrameStats::NearLevelMemory& level : stats.nearLevels) nearBytes += level.bytes;
        char part[64];
        std::snprintf(part, sizeof part, "  scene volume %.1f",
                      static_cast<double>(stats.voxelBytes - nearBytes) / kMiB);
        std::string text = part;
        for (const FrameStats::NearLevelMemory& level : stats.nearLevels) {
            std::snprintf(part, sizeof part, ", %g m level %.1f", static_cast<double>(level.side),
                          static_cast<double>(level.bytes) / kMiB);
            text += part;
        }
        ImGui::TextDisabled("%s MiB", text.c_str());
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "GPU memory of each voxel volume with its caches and ray hits: the one around the\n"
                "scene, then the near levels around the camera (Render settings, Near level side)");
    }
    if (stats.shadowCascadesDrawn > 0)
        ImGui::Text("Shadow maps %.1f MiB [cascades %d]", static_cast<double>(stats.shadowMapBytes) / kMiB,
                    stats.shadowCascadesDrawn);
    else
        ImGui::Text("Shadow maps %.1f MiB", static_cast<double>(stats.shadowMapBytes) / kMiB);
    // The cached mode's update after an edit runs over frames: how far it is, so that nobody
    // judges the light before it is right.
    if (stats.giUpdateDone < 1.0f) {
        ImGui::Text("GI update %3.0f %% (%s)%s", 100.0 * static_cast<double>(stats.giUpdateDone),
                    stats.giUpdateStage.c_str(), stats.giShowingPrevious ? ": showing the light before the edit" : "");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(stats.giShowingPrevious
                                  ? "The light of the edited geometry is traced a part of the voxels a frame (Render "
                                    "settings, GI ms / frame); the indirect diffuse light shown is the last "
                                    "complete one until then, and swaps to the new one at 100 %%"
                                  : "The light of the last edit is traced a part of the voxels a frame (Render "
                                    "settings, GI ms / frame); until 100 %% some voxels hold the light from "
                                    "before the edit");
    } else if (!stats.giUpdateStage.empty()) {
        ImGui::TextDisabled("GI %s", stats.giUpdateStage.c_str());
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s", stats.giUpdateStage.find("uncovered slabs") != std::string::npos
                                        ? "The near level moved with the camera: the voxels it uncovered are lit a "
                                          "part a frame (Render settings, GI ms / frame); until then the pixels "
                                          "there gather the coarser volume's light"
                                        : "The light is right; each round traces every voxel again with other "
                                          "directions, averaging out the faint bands of a one-frame trace");
    }
    // While GI work is in flight: how much of its time budget the last measured frame used.
    if ((stats.giUpdateDone < 1.0f || !stats.giUpdateStage.empty()) && frame.giBudgetMs > 0.0) {
        ImGui::TextDisabled("GI work %.1f of %.1f ms a frame", spreadGiMs(profiler.timings()), frame.giBudgetMs);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("GPU time of the bounces, the voxel irradiance and its filter in the last measured frame,\n"
                              "against Render settings, GI ms / frame (the edit's own voxelization and injection\n"
                              "are not spread and not counted)");
    } else if (stats.giBounces > 0 && !stats.giRefining && stats.giUpdateDone >= 1.0f && stats.giUpdateStage.empty()) {
        if (stats.giEveryBounce)
            ImGui::TextDisabled("GI converged: every bounce (%d)", stats.giBounces);
        else
            ImGui::TextDisabled("GI converged: %d bounce%s", stats.giBounces, stats.giBounces > 1 ? "s" : "");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The voxels hold the light of the last edit, refined; nothing is left to trace");
    }

    const auto& timings = profiler.timings();
    if (timings.empty()) {
        ImGui::TextDisabled("GPU timings arrive a few frames late");
    } else {
        drawStackedBar(profiler, width);
        if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
            ImGui::TableSetupColumn("Pass");
            ImGui::TableSetupColumn("GPU ms");
            ImGui::TableSetupColumn("CPU ms");
            ImGui::TableHeadersRow();
            for (const PassTiming& pass : timings) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                // A colour swatch ties the row to its segment in the bar.
                const ImVec2 p = ImGui::GetCursorScreenPos();
                const float h = ImGui::GetTextLineHeight();
                ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 2.0f), ImVec2(p.x + h - 4.0f, p.y + h - 2.0f),
                                                          passColor(pass.name));
                ImGui::Dummy(ImVec2(h - 2.0f, h));
                ImGui::SameLine();
                // Passes that run only when something changed (shadows, voxelize, inject,
                // mipmap) show, greyed, what they cost the last time they ran.
                const ShownTiming shown = shownTiming(profiler, pass);
                if (shown.current) {
                    ImGui::TextUnformatted(pass.name.c_str());
                    if (pass.name == "GPU wait" && ImGui::IsItemHovered())
                        ImGui::SetTooltip("Software rasterizer (llvmpipe): the CPU waits here for the passes above,\n"
                                          "which run when their result is first needed. Their own cost is their GPU ms.");
                    ImGui::TableNextColumn();
                    ImGui::Text("%8.2f", pass.gpuMs);
                    ImGui::TableNextColumn();
                    ImGui::Text("%7.2f", pass.cpuMs);
                } else {
                    ImGui::TextDisabled("%s", pass.name.c_str());
                    ImGui::TableNextColumn();
                    if (shown.timing) ImGui::TextDisabled("%8.2f", shown.timing->gpuMs); else ImGui::TextDisabled("%8s", "-");
                    ImGui::TableNextColumn();
                    if (shown.timing) ImGui::TextDisabled("%7.2f", shown.timing->cpuMs); else ImGui::TextDisabled("%7s", "-");
                }
            }
            ImGui::EndTable();
        }
    }
    ImGui::TextDisabled("F2 hides this overlay");
    ImGui::PopFont();
    ImGui::End();
    return rect;
}

}  // namespace lit::editor
