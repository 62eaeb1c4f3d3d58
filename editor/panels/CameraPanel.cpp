#include "panels/CameraPanel.h"

#include <imgui.h>

#include <algorithm>

namespace lit::editor {

namespace {
constexpr float kDegPerRad = 57.2957795f;
}

float cameraPanelHeight() {
    const ImGuiStyle& style = ImGui::GetStyle();
    // Title bar, five widget rows (four fields and the button), two lines of help.
    return ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y + 5.0f * ImGui::GetFrameHeightWithSpacing() +
           2.0f * ImGui::GetTextLineHeightWithSpacing();
}

CameraPanelRequests drawCameraPanel(FlyCamera& camera, const Placement& placement, bool* open) {
    CameraPanelRequests requests;
    placeNextWindow(placement);
    if (!ImGui::Begin("Camera", open)) {
        ImGui::End();
        return requests;
    }
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    ImGui::SliderFloat("Speed", &camera.speed, 0.01f, 500.0f, "%.2f m/s", ImGuiSliderFlags_Logarithmic);
    float fovDegrees = camera.yfov * kDegPerRad;
    if (ImGui::SliderFloat("Vertical FOV", &fovDegrees, 10.0f, 120.0f, "%.1f deg"))
        camera.yfov = std::clamp(fovDegrees, 10.0f, 120.0f) / kDegPerRad;
    ImGui::DragFloat3("Position", &camera.position.x, 0.01f, 0.0f, 0.0f, "%.2f");
    // "+ 0.0f" turns −0 into +0, so a level camera does not read "-0.0 deg".
    float yawPitch[2] = {camera.yaw * kDegPerRad + 0.0f, camera.pitch * kDegPerRad + 0.0f};
    if (ImGui::DragFloat2("Yaw, pitch", yawPitch, 0.5f, 0.0f, 0.0f, "%.1f deg")) {
        camera.yaw = yawPitch[0] / kDegPerRad;
        camera.pitch = std::clamp(yawPitch[1], -89.0f, 89.0f) / kDegPerRad;
    }
    ImGui::PopItemWidth();
    if (ImGui::Button("Reset to scene camera")) requests.resetToSceneCamera = true;
    ImGui::TextDisabled("Right-drag look, WASD move, Q/E down/up,");
    ImGui::TextDisabled("Shift fast, wheel changes speed");
    ImGui::End();
    return requests;
}

}  // namespace lit::editor
