#include "panels/LoadingWindow.h"

#include <imgui.h>

#include <cstdio>

#include "LoadStages.h"

namespace lit::editor {

void drawLoadingWindow(const std::filesystem::path& file, const LoadProgress& progress, double seconds) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(420.0f, 0.0f), ImGuiCond_Always);
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize;
    if (ImGui::Begin("Loading", nullptr, kFlags)) {
        ImGui::Text("Loading %s", file.filename().string().c_str());
        // The overall bar stays short of 100 % until the document is in.
        const auto fractions = loadStageFractions(progress);
        const int current = loadStageIndex(progress.stage);
        for (std::size_t i = 0; i < kLoadStages.size(); ++i) {
            const int index = static_cast<int>(i);
            char overlay[64];
            if (index < current)
                std::snprintf(overlay, sizeof overlay, "done");
            else if (index > current)
                std::snprintf(overlay, sizeof overlay, "waiting");
            else if (progress.total > 1)
                std::snprintf(overlay, sizeof overlay, "%d / %d", progress.done, progress.total);
            else
                std::snprintf(overlay, sizeof overlay, "running");
            ImGui::TextUnformatted(kLoadStages[i].label);
            ImGui::SameLine(140.0f);
            ImGui::ProgressBar(fractions[i], ImVec2(-1.0f, 0.0f), overlay);
        }
        ImGui::Separator();
        char total[32];
        const float overall = overallLoadFraction(progress);
        std::snprintf(total, sizeof total, "%.0f %%", 100.0 * overall);
        ImGui::ProgressBar(overall, ImVec2(-1.0f, 0.0f), total);
        ImGui::TextDisabled("%.1f s", seconds);
    }
    ImGui::End();
}

}  // namespace lit::editor
