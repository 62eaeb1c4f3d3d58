#include "panels/StatsOverlay.h"

#include <imgui.h>

namespace lit::editor {

void drawStatsOverlay(const FrameTimer& timer, const Profiler& profiler, const FrameStats& stats, glm::ivec2 renderSize,
                      ImFont* monoFont, const Placement& placement, bool* open) {
    placeNextWindow(placement);
    ImGui::SetNextWindowBgAlpha(0.6f);  // an overlay: the image stays visible behind it
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                        ImGuiWindowFlags_NoSavedSettings;
    if (!ImGui::Begin("Stats", open, kFlags)) {
        ImGui::End();
        return;
    }
    ImGui::PushFont(monoFont);
    ImGui::Text("Frame %8.1f ms  %6.1f FPS", timer.averageMs(), timer.fps());
    ImGui::Text("GPU   %8.1f ms  (all passes)", profiler.totalGpuMs());
    ImGui::Text("Render %d x %d px", renderSize.x, renderSize.y);
    ImGui::Text("Draw calls %d   Triangles %zu", stats.drawCalls, stats.triangles);
    ImGui::Text("Culled views: %d of %d draws submitted, %.3f ms CPU", stats.drawsSubmitted, stats.drawsTotal,
                stats.cullMs);
    constexpr double kMiB = 1024.0 * 1024.0;
    ImGui::Text("Voxels %.1f MiB%s%s", static_cast<double>(stats.voxelBytes) / kMiB,
                stats.voxelized ? "  [voxelized]" : "", stats.injected ? "  [injected]" : "");

    const auto& timings = profiler.timings();
    if (timings.empty()) {
        ImGui::TextDisabled("GPU timings arrive a few frames late");
    } else if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("Pass");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableSetupColumn("CPU ms");
        ImGui::TableHeadersRow();
        for (const PassTiming& pass : timings) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            // Passes that did not run in that frame (nothing to redo) are greyed out.
            if (pass.ran) {
                ImGui::TextUnformatted(pass.name.c_str());
                ImGui::TableNextColumn();
                ImGui::Text("%8.2f", pass.gpuMs);
                ImGui::TableNextColumn();
                ImGui::Text("%7.2f", pass.cpuMs);
            } else {
                // Passes that run only when something changed (shadows, voxelize, inject,
                // mipmap) show, greyed, what they cost the last time they ran.
                ImGui::TextDisabled("%s", pass.name.c_str());
                const PassTiming* last = profiler.lastRun(pass.name);
                ImGui::TableNextColumn();
                if (last) ImGui::TextDisabled("%8.2f", last->gpuMs); else ImGui::TextDisabled("%8s", "-");
                ImGui::TableNextColumn();
                if (last) ImGui::TextDisabled("%7.2f", last->cpuMs); else ImGui::TextDisabled("%7s", "-");
            }
        }
        ImGui::EndTable();
    }
    ImGui::PopFont();
    ImGui::End();
}

}  // namespace lit::editor
