#include "panels/RenderSettingsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace lit::editor {

namespace {

// Every lit::View, in menu order. Keep in step with the enum in RenderSettings.h.
constexpr std::array kViews = {
    View::Final,  View::DirectDiffuse, View::IndirectDiffuse, View::DirectSpecular, View::IndirectSpecular,
    View::Albedo, View::Normal,        View::RoughnessMetalness, View::ShadowMap,     View::Voxels,
    View::VoxelSlice,
};

constexpr std::array kVoxelChannels = {VoxelChannel::Radiance, VoxelChannel::Albedo, VoxelChannel::Normal,
                                       VoxelChannel::Opacity, VoxelChannel::Emission};

// A combo over a fixed list of choices, each shown as name(choice); returns true on change.
template <class T, std::size_t N, class Name>
bool combo(const char* label, T& value, const std::array<T, N>& choices, Name&& name) {
    bool changed = false;
    const std::string preview(name(value));
    if (ImGui::BeginCombo(label, preview.c_str())) {
        for (const T& choice : choices) {
            const std::string text(name(choice));
            if (ImGui::Selectable(text.c_str(), choice == value)) {
                changed |= value != choice;
                value = choice;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

// Texture sizes and voxel resolutions.
template <std::size_t N>
bool comboInt(const char* label, int& value, const std::array<int, N>& choices) {
    return combo(label, value, choices, [](int v) { return std::to_string(v); });
}

// Enums with a toString() (views, voxel channels).
template <class T, std::size_t N>
bool comboEnum(const char* label, T& value, const std::array<T, N>& choices) {
    return combo(label, value, choices, [](T v) { return toString(v); });
}

// Angles are stored in radians and shown in degrees.
bool sliderDegrees(const char* label, float& radians, float minDegrees, float maxDegrees) {
    constexpr float kDegPerRad = 57.2957795f;
    float degrees = radians * kDegPerRad;
    if (!ImGui::SliderFloat(label, &degrees, minDegrees, maxDegrees, "%.1f deg")) return false;
    radians = degrees / kDegPerRad;
    return true;
}

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

bool drawOutput(RenderSettings& s, ViewportSettings& viewport) {
    bool changed = comboEnum("View", s.view, kViews);
    changed |= ImGui::SliderFloat("Exposure", &s.exposureEv, -10.0f, 20.0f, "%+.1f EV");
    tooltip(s.autoExposure ? "Compensation in stops added to the metered exposure"
                           : "Stops, as Blender's Film > Exposure: radiance x 2^EV before tone mapping");
    changed |= ImGui::Checkbox("Auto exposure", &s.autoExposure);
    tooltip("Meter the image (log-luminance histogram) and expose its mean to middle grey");
    if (s.autoExposure) {
        changed |= ImGui::SliderFloat("Adaptation", &s.autoExposureSpeed, 0.0f, 10.0f, "%.1f /s");
        tooltip("How fast the exposure follows the image (exponential rate per second; 0 = at once)");
    }
    ImGui::SliderFloat("Render scale", &viewport.renderScale, 0.25f, 1.0f, "%.2f");
    tooltip("Render resolution as a fraction of the window (stretched to fit)");
    changed |= ImGui::SliderFloat("Interactive FPS", &s.interactiveFpsTarget, 0.0f, 60.0f, "%.0f FPS");
    tooltip("While the camera moves or a value is dragged, lower the render scale to hold this frame rate\n"
            "(0 = never); full scale again when still");
    ImGui::Checkbox("Markers and gizmo", &viewport.markers);
    tooltip("Light and camera markers, the camera path and the translate gizmo");
    ImGui::Checkbox("Cone directions", &viewport.coneDirections);
    tooltip("Click a pixel in the viewport to draw the cones the cone-trace pass traces from it:\n"
            "green = the six diffuse cones, pink = the specular cones");
    return changed;
}

bool drawSky(RenderSettings& s) {
    bool changed = comboEnum("Sky", s.skyMode, std::array{SkyMode::Auto, SkyMode::None, SkyMode::Uniform,
                                                          SkyMode::Gradient, SkyMode::Hdr});
    tooltip("auto: a gradient sky and a sun when the scene has no lights, else none.\n"
            "The background shows the sky and GI cones that leave the scene receive it.");
    changed |= ImGui::SliderFloat("Sky intensity", &s.skyIntensity, 0.0f, 100.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    tooltip("Multiplier of the sky colours or the .hdr image (radiance, W/(sr m^2))");
    if (s.skyMode == SkyMode::Uniform || s.skyMode == SkyMode::Gradient || s.skyMode == SkyMode::Auto) {
        changed |= ImGui::ColorEdit3("Zenith", s.skyZenith.data(), ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
        if (s.skyMode != SkyMode::Uniform) {
            changed |= ImGui::ColorEdit3("Horizon", s.skyHorizon.data(), ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
            changed |= ImGui::ColorEdit3("Ground", s.skyGround.data(), ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
        }
    }
    if (s.skyMode == SkyMode::Hdr) {
        std::array<char, 512> path{};
        s.skyHdrPath.copy(path.data(), path.size() - 1);
        if (ImGui::InputText(".hdr file", path.data(), path.size(), ImGuiInputTextFlags_EnterReturnsTrue)) {
            s.skyHdrPath = path.data();
            changed = true;
        }
        tooltip("Equirectangular Radiance .hdr (press Enter to load)");
    }
    changed |= ImGui::SliderFloat("Default sun", &s.defaultSunIrradiance, 0.0f, 20.0f, "%.2f W/m^2");
    tooltip("Irradiance of the sun added to scenes without lights (x 683 = lux); 0 = none");
    changed |= sliderDegrees("Sun elevation", s.defaultSunElevation, 1.0f, 90.0f);
    changed |= sliderDegrees("Sun azimuth", s.defaultSunAzimuth, -180.0f, 180.0f);
    return changed;
}

bool drawTerms(RenderSettings& s) {
    bool changed = false;
    // Two columns (diffuse | specular); a table clips labels in a narrow panel instead of
    // letting them run into each other.
    if (ImGui::BeginTable("terms", 2)) {
        ImGui::TableNextColumn();
        changed |= ImGui::Checkbox("Direct diffuse", &s.directDiffuse);
        ImGui::TableNextColumn();
        changed |= ImGui::Checkbox("Direct specular", &s.directSpecular);
        ImGui::TableNextColumn();
        changed |= ImGui::Checkbox("Indirect diffuse", &s.indirectDiffuse);
        ImGui::TableNextColumn();
        changed |= ImGui::Checkbox("Indirect specular", &s.indirectSpecular);
        ImGui::EndTable();
    }
    return changed;
}

bool drawShadows(RenderSettings& s, int lightCount) {
    bool changed = ImGui::Checkbox("Shadows", &s.shadows);
    ImGui::BeginDisabled(!s.shadows);
    changed |= comboInt("Map size", s.shadowMapSize, std::array{256, 512, 1024, 2048, 4096});
    tooltip("Texels per side of each shadow map (and of each cube face)");
    changed |= ImGui::DragFloat("Depth bias", &s.shadowDepthBias, 0.00001f, 0.0f, 0.01f, "%.5f");
    tooltip("Constant bias in light clip-space depth");
    changed |= ImGui::DragFloat("Slope bias", &s.shadowSlopeBias, 0.05f, 0.0f, 10.0f, "%.2f");
    tooltip("Multiplies the depth slope (glPolygonOffset factor)");
    changed |= ImGui::DragFloat("Normal offset", &s.shadowNormalOffset, 0.05f, 0.0f, 10.0f, "%.2f texels");
    tooltip("Receiver offset along its normal, in shadow-map texels");
    changed |= ImGui::SliderFloat("PCF radius", &s.shadowPcfRadius, 0.0f, 5.0f, "%.2f texels");
    tooltip("Filter kernel radius, in shadow-map texels");
    ImGui::EndDisabled();
    if (s.view == View::ShadowMap) {
        const int lastLight = std::max(lightCount - 1, 0);
        changed |= ImGui::SliderInt("Shown light", &s.shadowDebugLight, 0, lastLight);
        s.shadowDebugLight = std::clamp(s.shadowDebugLight, 0, lastLight);
    }
    return changed;
}

bool drawGlobalIllumination(RenderSettings& s) {
    bool changed = ImGui::Checkbox("Cone-traced GI", &s.gi);
    ImGui::BeginDisabled(!s.gi);
    changed |= comboInt("Voxels per side", s.voxelResolution, std::array{64, 128, 256, 512});
    // The preset over the three GI fields below; it reads "custom" when they match none.
    GiMode mode = giModeOf(s);
    if (combo("GI mode", mode, std::array{GiMode::Fast, GiMode::Accurate, GiMode::Cached, GiMode::Custom},
              [](GiMode m) { return toString(m); }) &&
        mode != GiMode::Custom) {
        setGiMode(s, mode);
        changed = true;
    }
    tooltip("cached (the default): the accurate mode's cones traced once per voxel after each light or\n"
            "geometry edit, their irradiance gathered per pixel: the accurate light at about the fast mode's\n"
            "frame cost, but a light edit re-traces every occupied voxel (seconds at 128^3 on a software\n"
            "rasterizer; spread it with 'Irradiance voxels / frame').\n"
            "accurate: anisotropic voxels + footprint / height 0.25, cones traced per pixel: the mode measured\n"
            "against the path-traced reference (within 20 % on the Cornell box), 5-13x the fast mode's frame.\n"
            "fast: isotropic voxels, unbounded cones per pixel (too dark far from lit surfaces and too bright\n"
            "near them, docs/GI.md). custom: the three fields below set by hand");
    changed |= ImGui::SliderFloat("Indirect intensity", &s.indirectIntensity, 0.0f, 4.0f, "%.2f");
    changed |= ImGui::SliderInt("Specular cones", &s.specularSamples, 1, 8);
    changed |= sliderDegrees("Diffuse aperture", s.diffuseConeAperture, 10.0f, 90.0f);
    tooltip("Full opening angle of each diffuse cone");
    changed |= ImGui::SliderFloat("Max distance", &s.maxTraceDistance, 0.05f, 1.0f, "%.2f");
    tooltip("Longest cone, as a fraction of the voxel volume's side");
    changed |= ImGui::SliderFloat("Step scale", &s.coneStepScale, 0.1f, 2.0f, "%.2f");
    tooltip("Step along a cone = scale x cone diameter (smaller is slower and smoother)");
    changed |= ImGui::SliderInt("Bounces", &s.bounces, 1, kMaxBounces);
    tooltip("Light bounces (count; default 2). 1: only direct light is injected into the voxels; each more\n"
            "re-injects the voxels' own traced indirect light (one extra pass over the occupied voxels per\n"
            "bounce after each light or geometry edit, spread over frames in the cached mode: seconds per\n"
            "bounce on a software rasterizer)");
    changed |= ImGui::SliderInt("Voxel rays", &s.voxelRays, 0, kMaxVoxelRays, s.voxelRays == 0 ? "cones" : "%d rays");
    tooltip("Rays per voxel (count) for the light the voxels gather themselves: the cached mode's irradiance\n"
            "and bounces 2..N. Each ray marches the voxel grid to the first occupied voxel: light past edges,\n"
            "through gaps and at grazing angles comes out right where cones blur it (docs/GI.md, \"Voxel rays\").\n"
            "0 = the accurate mode's cones. 32 (the default) cost about what the cones cost; more are smoother\n"
            "and slower");
    changed |= ImGui::Checkbox("Anisotropic voxels", &s.anisotropicVoxels);
    tooltip("Six directional volumes per mip level (x6/7 more voxel memory): walls block and emit light\n"
            "only on the side a cone looks at, so no light leaks or self-illumination through them.\n"
            "Per pixel 2-3x the cone-trace time and a slower mipmap pass on a software rasterizer.\n"
            "With Footprint / height 0.25: the accurate and cached GI modes measured in docs/GI.md");
    changed |= ImGui::SliderFloat("Footprint / height", &s.coneFootprintPerHeight, 0.0f, 2.0f, "%.2f");
    tooltip("Largest voxel a cone leaving a surface samples, as a multiple of its height above that\n"
            "surface (ratio; 0 = unbounded). Smaller keeps cones out of their own surface's voxels\n"
            "(no self-illumination) at the cost of more steps (3-5x the cone-trace time per pixel).\n"
            "0.25 with anisotropic voxels: the accurate and cached GI modes; 0: the fast mode");
    changed |= ImGui::Checkbox("Diffuse from voxel irradiance", &s.diffuseFromVoxelIrradiance);
    tooltip("Indirect diffuse gathered from irradiance cached in the voxels (traced once per light or\n"
            "geometry edit with the accurate mode's cone sets) instead of cones per pixel: ~10-30x\n"
            "cheaper per frame, seconds per light edit on llvmpipe (docs/GI.md, \"Irradiance cached in\n"
            "the voxels\"). On in the cached GI mode");
    if (s.diffuseFromVoxelIrradiance) {
        changed |= ImGui::DragInt("Irradiance voxels / frame", &s.voxelIrradianceVoxelsPerFrame, 256.0f, 0, 1 << 24,
                                  s.voxelIrradianceVoxelsPerFrame == 0 ? "all at once" : "%d voxels");
        tooltip("Occupied voxels traced per frame after an edit, for each bounce past the first and then\n"
                "the irradiance (count; 0 = all in the edit's frame); voxels not reached yet keep the old\n"
                "light. After a voxelization the first bounce marches the voxel rays (~5 us per voxel on\n"
                "llvmpipe) and records their hits; the passes after it replay them, 4x as many voxels a\n"
                "frame at about the same cost, so a light edit takes bounces x occupied / (4 x this)\n"
                "frames. The performance overlay shows the progress");
        changed |= ImGui::DragInt("Refine voxels / frame", &s.voxelIrradianceRefineVoxelsPerFrame, 256.0f, 0, 1 << 24,
                                  s.voxelIrradianceRefineVoxelsPerFrame == 0 ? "off" : "%d voxels");
        tooltip("Once the light is traced, occupied voxels traced again per frame with the other cone sets\n"
                "(count; 0 = off) until each holds all 16: 15 more passes over the voxels, spread over frames.\n"
                "Removes the bands a few voxels wide that one set per voxel leaves");
    }
    changed |= comboInt("Indirect scale", s.indirectScale, std::array{1, 2, 4});
    tooltip("Trace indirect light for one pixel in N x N and upsample edge-aware (1 = every pixel)");
    changed |= ImGui::SliderFloat("Full-res specular below", &s.specularFullResRoughness, 0.0f, 1.0f, "roughness %.2f");
    tooltip("Surfaces smoother than this trace indirect specular for every pixel (sharp reflections)");
    changed |= ImGui::Checkbox("Temporal accumulation", &s.temporalAccumulation);
    tooltip("Average indirect light over frames (reprojected; history dropped on disocclusion and edits)");
    changed |= ImGui::SliderInt("History frames", &s.temporalMaxFrames, 1, 64);
    tooltip("Frames averaged at most: more is smoother, slower to follow changes");
    changed |= ImGui::Checkbox("Cone subsets", &s.temporalConeSubsets);
    tooltip("With temporal accumulation: each traced pixel marches the normal cone and 2 of the 5 side\n"
            "cones per frame, a different pair each frame, and the accumulation averages them (half\n"
            "the cone-trace time; in the accurate mode, pairs of each pixel's stratified set)");
    ImGui::EndDisabled();
    if (s.view == View::Voxels || s.view == View::VoxelSlice) {
        ImGui::Separator();
        ImGui::TextDisabled(s.view == View::Voxels ? "Voxel view (ray-marched)" : "Voxel slice");
        changed |= comboEnum("Channel", s.voxelChannel, kVoxelChannels);
        const int lastMip = std::max(static_cast<int>(std::log2(std::max(s.voxelResolution, 1))), 0);
        changed |= ImGui::SliderInt("Mip", &s.voxelMip, 0, lastMip);
        if (s.view == View::VoxelSlice) {
            constexpr std::array kAxes = {"X", "Y", "Z"};
            changed |= ImGui::Combo("Slice axis", &s.voxelSliceAxis, kAxes.data(), static_cast<int>(kAxes.size()));
            // Shown as a voxel index at the chosen mip; stored as a fraction so it survives
            // resolution changes.
            const int voxels = std::max(s.voxelResolution >> std::clamp(s.voxelMip, 0, lastMip), 1);
            int slice = std::clamp(static_cast<int>(s.voxelSlice * static_cast<float>(voxels)), 0, voxels - 1);
            if (ImGui::SliderInt("Slice", &slice, 0, voxels - 1)) {
                s.voxelSlice = (static_cast<float>(slice) + 0.5f) / static_cast<float>(voxels);
                changed = true;
            }
        }
    }
    return changed;
}

}  // namespace

RenderSettingsRequests drawRenderSettingsPanel(RenderSettings& settings, ViewportSettings& viewport, int lightCount,
                                               const Placement& placement, bool* open) {
    placeNextWindow(placement);
    RenderSettingsRequests requests;
    if (!ImGui::Begin("Render settings", open)) {
        ImGui::End();
        return requests;
    }
    // Labels on the right take ~45% of the width; sliders get the rest.
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    bool changed = drawOutput(settings, viewport);
    if (ImGui::CollapsingHeader("Terms", ImGuiTreeNodeFlags_DefaultOpen)) changed |= drawTerms(settings);
    if (ImGui::CollapsingHeader("Sky and default light")) changed |= drawSky(settings);
    if (ImGui::CollapsingHeader("Shadows", ImGuiTreeNodeFlags_DefaultOpen))
        changed |= drawShadows(settings, lightCount);
    if (ImGui::CollapsingHeader("Global illumination", ImGuiTreeNodeFlags_DefaultOpen)) {
        changed |= drawGlobalIllumination(settings);
        ImGui::BeginDisabled(!settings.gi);
        requests.revoxelize = ImGui::Button("Re-voxelize");
        tooltip("Rebuild the voxel volume and re-inject light now (edits do this by themselves)");
        ImGui::EndDisabled();
    }
    changed |= ImGui::Checkbox("Frustum culling", &settings.frustumCulling);
    tooltip("Camera and shadow views draw only what their frustum may see (a BVH over the draw items)");
    ImGui::Separator();
    if (ImGui::Button("Reset to defaults")) {
        // Keep the output size: it belongs to the window, not to the user's choices.
        RenderSettings defaults;
        defaults.width = settings.width;
        defaults.height = settings.height;
        changed |= defaults != settings;
        settings = defaults;
        viewport = ViewportSettings{};
    }
    ImGui::PopItemWidth();
    ImGui::End();
    requests.changed = changed;
    return requests;
}

}  // namespace lit::editor
