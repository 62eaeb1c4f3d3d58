#include "ReferenceViewer.h"

#include "Renderer.h"
#include "RenderSettings.h"
#include "reference/DifferenceImage.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace lit {

namespace {

double nowSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

void ReferenceViewer::update(const Scene& scene, const CameraView& camera, const RenderSettings& settings,
                             Renderer& renderer) {
    unsupportedView_ = !reference::referenceRendersView(settings.debug.view);
    if (mode_ == ReferenceMode::Off || unsupportedView_) {
        tracer_.stop();
        haveImage_ = false;
        return;
    }
    reference::ReferenceSettings referenceSettings;
    // The VCT's light paths: its bounces with GI on, direct light only with GI off.
    referenceBounces_ = !settings.gi.enabled                 ? 0
                        : settings.gi.bounces == kAllBounces ? reference::kAllBounces
                                                             : std::clamp(settings.gi.bounces, 1, kMaxBounces);
    referenceSettings.bounces = referenceBounces_;
    // The same sky and default sun as the rasterizer (docs/REFERENCE.md).
    tracer_.update(scene, camera, settings.output.width, settings.output.height, referenceSettings, &settings);

    const double now = nowSeconds();
    const reference::ProgressiveStatus status = tracer_.status();
    if (now - lastUpload_ < kRefreshSeconds && status.samplesPerPixel == uploadedSamples_) return;
    if (now - lastUpload_ < kRefreshSeconds && haveImage_) return;
    std::vector<float> rgb;
    int width = 0, height = 0;
    if (!tracer_.latest(settings.debug.view, settings, rgb, width, height) || width != settings.output.width ||
        height != settings.output.height) {
        haveImage_ = false;
        return;
    }
    std::vector<std::uint8_t> bytes;
    if (mode_ == ReferenceMode::Reference) {
        // The exposure the rasterizer's last frame used (the metered one with auto exposure on),
        // so the two views compare at the same brightness.
        bytes = reference::toneMapToRgba8(rgb, std::exp2(renderer.exposureEv(settings)));
    } else {
        // The ramp is meant as display colour: encoded for the sRGB blit.
        bytes = reference::displayColoursToRgba8(reference::relativeErrorColours(renderer.readHdrRgb(), rgb, maxError_));
    }
    if (!texture_ || texture_.desc().width != width || texture_.desc().height != height)
        texture_ = gl::Texture("reference view", {GL_TEXTURE_2D, GL_SRGB8_ALPHA8, width, height, 1, 1});
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(texture_.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    haveImage_ = true;
    lastUpload_ = now;
    uploadedSamples_ = status.samplesPerPixel;
}

const gl::Texture* ReferenceViewer::output() const {
    return mode_ != ReferenceMode::Off && haveImage_ && texture_ ? &texture_ : nullptr;
}

bool ReferenceViewer::accumulating() const {
    if (mode_ == ReferenceMode::Off || unsupportedView_) return false;
    const reference::ProgressiveStatus status = tracer_.status();
    return status.running || status.samplesPerPixel != uploadedSamples_;
}

void ReferenceViewer::drawWindow(ImVec2 topRight, ImGuiCond placeCondition) {
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    // Without a place ImGui puts a new window at (60, 60), over the hierarchy panel.
    ImGui::SetNextWindowPos(topRight, placeCondition, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(300, 0), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Reference")) {
        ImGui::End();
        return;
    }
    int mode = static_cast<int>(mode_);
    ImGui::RadioButton("Rasterizer", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("Reference", &mode, 1);
    ImGui::SameLine();
    ImGui::RadioButton("Difference", &mode, 2);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Relative error of the rasterizer's image against the path-traced reference, per pixel");
    mode_ = static_cast<ReferenceMode>(mode);
    if (mode_ != ReferenceMode::Off) {
        if (unsupportedView_) {
            ImGui::TextWrapped("The reference renders the final image and the four lighting terms; pick one of those views.");
        } else {
            const reference::ProgressiveStatus s = tracer_.status();
            ImGui::Text("%d spp, %.0f samples/s, %.2f Mrays/s%s", s.samplesPerPixel, s.samplesPerSecond,
                        s.raysPerSecond * 1e-6, s.running ? "" : " (done)");
            if (referenceBounces_ == reference::kAllBounces)
                ImGui::TextDisabled("Every bounce, as the GI's; restarts on any edit");
            else if (referenceBounces_ > 0)
                ImGui::TextDisabled("%d bounce%s, as the GI's; restarts on any edit", referenceBounces_,
                                    referenceBounces_ > 1 ? "s" : "");
            else
                ImGui::TextDisabled("Direct light only (GI off); restarts on any edit");
        }
    }
    if (mode_ == ReferenceMode::Difference) {
        ImGui::SliderFloat("Range", &maxError_, 0.05f, 2.0f, "±%.2f");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Relative error shown at either end of the colour bar (1 = 100 %%)");
        // The colour bar: blue (rasterizer too dark) → white (equal) → red (too bright).
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const ImVec2 origin = ImGui::GetCursorScreenPos();
        const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
        constexpr int kSteps = 64;
        for (int i = 0; i < kSteps; ++i) {
            const glm::vec3 c = reference::differenceRampColour(2.0f * (i + 0.5f) / kSteps - 1.0f);
            draw->AddRectFilled(ImVec2(origin.x + width * i / kSteps, origin.y),
                                ImVec2(origin.x + width * (i + 1) / kSteps + 1.0f, origin.y + height),
                                ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f)));
        }
        ImGui::Dummy(ImVec2(width, height));
        ImGui::Text("-%.0f %%", 100.0f * maxError_);
        ImGui::SameLine(width * 0.5f - 4.0f);
        ImGui::Text("0");
        char right[32];
        std::snprintf(right, sizeof right, "+%.0f %%", 100.0f * maxError_);
        ImGui::SameLine(width - ImGui::CalcTextSize(right).x);
        ImGui::TextUnformatted(right);
    }
    ImGui::End();
}

}  // namespace lit
