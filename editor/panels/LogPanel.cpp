#include "panels/LogPanel.h"

#include <string>
#include <vector>

namespace lit::editor {

namespace {
ImVec4 colourOf(LogLevel level) {
    switch (level) {
        case LogLevel::Info:
            return {0.80f, 0.80f, 0.80f, 1.0f};
        case LogLevel::Warning:
            return {1.00f, 0.80f, 0.30f, 1.0f};
        case LogLevel::Error:
            return {1.00f, 0.40f, 0.40f, 1.0f};
    }
    return {1.0f, 1.0f, 1.0f, 1.0f};
}
}  // namespace

void LogPanel::draw(const Log& log, ImFont* monoFont, const Placement& placement, bool* open) {
    placeNextWindow(placement);
    if (!ImGui::Begin("Log", open)) {
        ImGui::End();
        return;
    }
    const std::size_t warnings = log.countAtLeast(LogLevel::Warning) - log.countAtLeast(LogLevel::Error);
    const std::size_t errors = log.countAtLeast(LogLevel::Error);
    ImGui::Checkbox("Info", &showInfo_);
    ImGui::SameLine();
    ImGui::Checkbox("Warnings", &showWarnings_);
    ImGui::SameLine();
    ImGui::Checkbox("Errors", &showErrors_);
    ImGui::SameLine();
    ImGui::Checkbox("Auto-scroll", &autoScroll_);
    ImGui::SameLine();
    filter_.Draw("Filter", 160.0f);
    ImGui::SameLine();
    ImGui::TextDisabled("(%zu warnings, %zu errors)", warnings, errors);
    ImGui::Separator();

    const std::vector<LogMessage> messages = log.recent();
    if (ImGui::BeginChild("messages", ImVec2(0.0f, 0.0f), false, ImGuiWindowFlags_HorizontalScrollbar)) {
        ImGui::PushFont(monoFont);
        for (const LogMessage& message : messages) {
            const bool shown = (message.level == LogLevel::Info && showInfo_) ||
                               (message.level == LogLevel::Warning && showWarnings_) ||
                               (message.level == LogLevel::Error && showErrors_);
            if (!shown || !filter_.PassFilter(message.text.c_str())) continue;
            ImGui::PushStyleColor(ImGuiCol_Text, colourOf(message.level));
            // A folded run of repeats shows its newest text once, with the count.
            const std::string count = message.repeats > 1 ? "  (x" + std::to_string(message.repeats) + ")" : std::string();
            if (message.level == LogLevel::Info)
                ImGui::Text("%s%s", message.text.c_str(), count.c_str());
            else
                ImGui::Text("%s: %s%s", toString(message.level), message.text.c_str(), count.c_str());
            ImGui::PopStyleColor();
        }
        // Stay at the bottom while the user is there, so new messages come into view; once they
        // scroll up to read older ones, leave the view alone.
        if (autoScroll_ && ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
        ImGui::PopFont();
    }
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace lit::editor
