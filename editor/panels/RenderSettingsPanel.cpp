#include "panels/RenderSettingsPanel.h"

#include <imgui.h>
#include <shared.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace lit::editor {

namespace {

// Every lit::View, in menu order. Keep in step with the enum in RenderSettings.h.
constexpr std::array kViews = {
    View::Final,      View::DirectDiffuse, View::IndirectDiffuse,    View::DirectSpecular, View::IndirectSpecular,
    View::Albedo,     View::Normal,        View::RoughnessMetalness, View::ShadowMap,      View::Voxels,
    View::VoxelSlice, View::VoxelLevels,
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
    bool changed = comboEnum("View", s.debug.view, kViews);
    changed |= ImGui::SliderFloat("Exposure", &s.output.exposureEv, -10.0f, 20.0f, "%+.1f EV");
    tooltip(s.output.autoExposure ? "Compensation in stops added to the metered exposure"
                                  : "Stops, as Blender's Film > Exposure: radiance x 2^EV before tone mapping");
    changed |= ImGui::Checkbox("Auto exposure", &s.output.autoExposure);
    tooltip("Meter the image (log-luminance histogram) and expose its mean to middle grey");
    if (s.output.autoExposure) {
        changed |= ImGui::SliderFloat("Adaptation", &s.output.autoExposureSpeed, 0.0f, 10.0f, "%.1f /s");
        tooltip("How fast the exposure follows the image (exponential rate per second; 0 = at once)");
    }
    changed |= ImGui::Checkbox("Anti-aliasing", &s.output.antialiasing);
    tooltip(
        "Temporal: each frame drawn at a sub-pixel offset and blended with the last ones, so edges,\n"
        "shadow edges and small highlights show each pixel's mean; a still view settles in that many frames");
    if (s.output.antialiasing) {
        changed |= ImGui::SliderInt("AA frames", &s.output.antialiasingFrames, 2, 64);
        tooltip("Offsets in the cycle and frames in the history (the blend weight never drops below 1/N)");
    }
    changed |= ImGui::Checkbox("Specular AA", &s.output.specularAntialiasing);
    tooltip(
        "Widen the lights' highlights by the spread of the normal over the pixel, so highlights smaller\n"
        "than a pixel neither alias nor flicker (curved, smooth surfaces read a little rougher)");
    ImGui::SliderFloat("Render scale", &viewport.renderScale, 0.25f, 1.0f, "%.2f");
    tooltip("Render resolution as a fraction of the window (stretched to fit)");
    ImGui::SliderFloat("Interactive FPS", &viewport.interactiveFpsTarget, 0.0f, 60.0f, "%.0f FPS");
    tooltip("While the camera moves or a value is dragged, lower the render scale to hold this frame rate\n"
            "(0 = never); full scale again when still");
    ImGui::Checkbox("Redraw on demand", &viewport.redrawOnDemand);
    tooltip(
        "Render the 3D image only when something in it changed or is still converging;\n"
        "otherwise show the last one again (off: render every frame)");
    ImGui::Checkbox("Markers and gizmo", &viewport.markers);
    tooltip("Light and camera markers, the camera path and the translate gizmo");
    ImGui::Checkbox("Cone directions", &viewport.coneDirections);
    tooltip("Click a pixel in the viewport to draw the cones the cone-trace pass traces from it:\n"
            "green = the six diffuse cones, pink = the specular cones");
    return changed;
}

bool drawSky(RenderSettings& s) {
    bool changed = comboEnum(
        "Sky", s.sky.mode, std::array{SkyMode::Auto, SkyMode::None, SkyMode::Uniform, SkyMode::Gradient, SkyMode::Hdr});
    tooltip("auto: a gradient sky and a sun when the scene has no lights, else none.\n"
            "The background shows the sky and GI cones that leave the scene receive it.");
    changed |=
        ImGui::SliderFloat("Sky intensity", &s.sky.intensity, 0.0f, 100.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    tooltip("Multiplier of the sky colours or the .hdr image (radiance, W/(sr m^2))");
    if (s.sky.mode == SkyMode::Uniform || s.sky.mode == SkyMode::Gradient || s.sky.mode == SkyMode::Auto) {
        changed |=
            ImGui::ColorEdit3("Zenith", s.sky.zenith.data(), ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
        if (s.sky.mode != SkyMode::Uniform) {
            changed |=
                ImGui::ColorEdit3("Horizon", s.sky.horizon.data(), ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
            changed |=
                ImGui::ColorEdit3("Ground", s.sky.ground.data(), ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
        }
    }
    if (s.sky.mode == SkyMode::Hdr) {
        std::array<char, 512> path{};
        s.sky.hdrPath.copy(path.data(), path.size() - 1);
        if (ImGui::InputText(".hdr file", path.data(), path.size(), ImGuiInputTextFlags_EnterReturnsTrue)) {
            s.sky.hdrPath = path.data();
            changed = true;
        }
        tooltip("Equirectangular Radiance .hdr (press Enter to load)");
    }
    changed |= ImGui::SliderFloat("Default sun", &s.sky.sunIrradiance, 0.0f, 20.0f, "%.2f W/m^2");
    tooltip("Irradiance of the sun added to scenes without lights (x 683 = lux); 0 = none");
    changed |= sliderDegrees("Sun elevation", s.sky.sunElevation, 1.0f, 90.0f);
    changed |= sliderDegrees("Sun azimuth", s.sky.sunAzimuth, -180.0f, 180.0f);
    return changed;
}

bool drawTerms(RenderSettings& s) {
    bool changed = false;
    // Two columns (diffuse | specular); a table clips labels in a narrow panel instead of
    // letting them run into each other.
    if (ImGui::BeginTable("terms", 2)) {
        ImGui::TableNextColumn();
        changed |= ImGui::Checkbox("Direct diffuse", &s.terms.directDiffuse);
        ImGui::TableNextColumn();
        changed |= ImGui::Checkbox("Direct specular", &s.terms.directSpecular);
        ImGui::TableNextColumn();
        changed |= ImGui::Checkbox("Indirect diffuse", &s.terms.indirectDiffuse);
        ImGui::TableNextColumn();
        changed |= ImGui::Checkbox("Indirect specular", &s.terms.indirectSpecular);
        ImGui::EndTable();
    }
    return changed;
}

bool drawShadows(RenderSettings& s, int lightCount) {
    bool changed = ImGui::Checkbox("Shadows", &s.shadows.enabled);
    ImGui::BeginDisabled(!s.shadows.enabled);
    changed |= comboInt("Map size", s.shadows.mapSize, std::array{256, 512, 1024, 2048, 4096});
    tooltip("Texels per side of each shadow map (and of each cube face)");
    changed |= ImGui::DragFloat("Depth bias", &s.shadows.depthBias, 0.00001f, 0.0f, 0.01f, "%.5f");
    tooltip("Constant bias in light clip-space depth");
    changed |= ImGui::DragFloat("Slope bias", &s.shadows.slopeBias, 0.05f, 0.0f, 10.0f, "%.2f");
    tooltip("Multiplies the depth slope (glPolygonOffset factor)");
    changed |= ImGui::DragFloat("Normal offset", &s.shadows.normalOffset, 0.05f, 0.0f, 10.0f, "%.2f texels");
    tooltip("Receiver offset along its normal, in shadow-map texels");
    changed |= ImGui::SliderFloat("PCF radius", &s.shadows.pcfRadius, 0.0f, 5.0f, "%.2f texels");
    tooltip("Filter kernel radius, in shadow-map texels");
    changed |= ImGui::SliderInt("Cascades", &s.shadows.cascades, 0, LIT_MAX_SHADOW_CASCADES);
    tooltip("Directional lights: maps fitted to slices of the camera's view (0 = one map over the scene)");
    ImGui::BeginDisabled(s.shadows.cascades == 0);
    changed |= ImGui::DragFloat("Cascade distance", &s.shadows.cascadeDistance, 1.0f, 0.0f, 1e5f, "%.0f m");
    tooltip("How far from the camera the cascades reach (0 = the scene's diagonal)");
    changed |= ImGui::SliderFloat("Cascade split", &s.shadows.cascadeSplit, 0.0f, 1.0f, "%.2f");
    tooltip("Slice spacing: 1 = logarithmic (finer near the camera), 0 = uniform");
    ImGui::EndDisabled();
    ImGui::EndDisabled();
    if (s.debug.view == View::ShadowMap) {
        const int lastLight = std::max(lightCount - 1, 0);
        changed |= ImGui::SliderInt("Shown light", &s.debug.shadowMapLight, 0, lastLight);
        s.debug.shadowMapLight = std::clamp(s.debug.shadowMapLight, 0, lastLight);
    }
    return changed;
}

bool drawGlobalIllumination(RenderSettings& s, ViewportSettings& viewport) {
    bool changed = ImGui::Checkbox("Cone-traced GI", &s.gi.enabled);
    ImGui::BeginDisabled(!s.gi.enabled);
    changed |= comboInt("Voxels per side", s.gi.voxelResolution, std::array{64, 128, 256, 512});
    changed |= combo("GI mode", s.gi.mode, std::array{GiMode::Fast, GiMode::Accurate, GiMode::Cached},
                     [](GiMode m) { return toString(m); });
    tooltip(
        "cached (the default): the voxels gather their own irradiance once per light or geometry edit\n"
        "(spread over frames: 'Update voxels / frame'), and each pixel gathers it from the voxels around it.\n"
        "accurate: directional voxels and footprint-bounded, stratified cones traced per pixel;\n"
        "several times the fast mode's frame.\n"
        "fast: the classic six cones per pixel over isotropic voxels; wrong in places (docs/GI.md)");
    changed |= ImGui::SliderFloat("Indirect intensity", &s.gi.indirectIntensity, 0.0f, 4.0f, "%.2f");
    changed |= ImGui::SliderInt("Specular cones", &s.indirect.specularSamples, 1, 8);
    tooltip("1: one cone, the reflection lobe's core around the mirror direction (no noise).\n"
            "More: importance samples of the lobe, cones that differ from pixel to pixel");
    changed |= sliderDegrees("Diffuse aperture", s.gi.diffuseConeAperture, 10.0f, 90.0f);
    tooltip("Full opening angle of each diffuse cone");
    changed |= ImGui::SliderFloat("Max distance", &s.gi.maxTraceDistance, 0.05f, 1.0f, "%.2f");
    tooltip("Longest cone, as a fraction of the voxel volume's side");
    changed |= ImGui::SliderFloat("Step scale", &s.gi.coneStepScale, 0.1f, 2.0f, "%.2f");
    tooltip("Step along a cone = scale x cone diameter (smaller is slower and smoother)");
    changed |= ImGui::SliderInt("Bounces", &s.gi.bounces, kAllBounces, kMaxBounces,
                                s.gi.bounces == kAllBounces ? "all" : "%d");
    tooltip(
        "Light bounces (count, or all: the default). all: the voxels reflect their own light bounce after\n"
        "bounce until it stops changing (the full light, as a path tracer's every bounce). 1: only direct\n"
        "light is injected into the voxels; each more re-injects the voxels' own gathered light. Each\n"
        "bounce is one more pass over the occupied voxels after a light or geometry edit, spread over\n"
        "frames in the cached mode; the overlay shows the update's progress");
    changed |=
        ImGui::SliderInt("Voxel rays", &s.gi.voxelRays, 0, kMaxVoxelRays, s.gi.voxelRays == 0 ? "cones" : "%d rays");
    tooltip("Rays per voxel (count) for the light the voxels gather themselves: the cached mode's irradiance\n"
            "and bounces 2..N. Each ray marches the voxel grid to the first occupied voxel: light past edges,\n"
            "through gaps and at grazing angles comes out right where cones blur it (docs/GI.md, \"Voxel rays\").\n"
            "0 = the accurate mode's cones. 32 (the default) cost about what the cones cost; more are smoother\n"
            "and slower");
    changed |= ImGui::SliderInt("Later bounce rays", &s.gi.laterBounceRayStride, 1, kMaxLaterBounceRayStride,
                                s.gi.laterBounceRayStride <= 1 ? "every ray" : "1 in %d");
    tooltip("Every bounce after an update's first gathers only the change of the bounce before, over one\n"
            "in this many of the voxel rays (the first gathers the light whole): with 1 in 4 (the default) a\n"
            "light edit's bounces cost about half as much, and the image moves about 0.5 % per pixel. Voxel rays and\n"
            "RGBA16F radiance only (docs/GI.md, \"Bounces\")");
    changed |= ImGui::Checkbox("Voxelize changes only", &s.gi.voxelizeChangesOnly);
    tooltip("A moved object (gizmo drag, node animation) voxelizes again only the voxels it covered and\n"
            "covers, and the voxel rays that miss them replay their recorded hits instead of marching.\n"
            "Off: every geometry edit voxelizes the whole volume and marches every ray (docs/GI.md,\n"
            "\"Incremental voxelization\")");
    changed |= ImGui::SliderFloat("Footprint / height", &s.gi.coneFootprintPerHeight, 0.0f, 2.0f, "%.2f");
    tooltip(
        "Largest voxel a cone leaving a surface samples, as a multiple of its height above that\n"
        "surface (ratio; 0 = unbounded). Smaller keeps cones out of their own surface's voxels\n"
        "(no self-illumination) at the cost of more steps (3-5x the cone-trace time per pixel).\n"
        "Accurate and cached modes only (the fast mode's cones are unbounded)");
    if (s.gi.voxelIrradiance()) {
        changed |= ImGui::DragFloat("Near level side", &s.gi.nearLevelSide, 1.0f, 0.0f, 4096.0f,
                                    s.gi.nearLevelSide <= 0.0f ? "off" : "%.0f m");
        tooltip("The finest near level's side (metres): a second volume of the same resolution around the camera,\n"
                "moved in eighths of its side; pixels inside it gather its finer voxels' light, and its voxels' rays\n"
                "continue in the volumes outside it. Each further level is twice as large. A level runs only in\n"
                "scenes at least twice its side across; 0 = off (docs/GI.md, \"Near levels\")");
        changed |= ImGui::SliderInt("Near levels", &s.gi.nearLevels, 0, kMaxNearLevels, s.gi.nearLevels == 0 ? "off" : "%d");
        tooltip("How many near levels (count, 0..3): the finest of Near level side, each next twice as large;\n"
                "each costs a volume's memory and update");
    }
    if (s.gi.voxelIrradiance()) {
        ImGui::DragInt("Update voxels / frame", &viewport.giUpdateVoxelsPerFrame, 256.0f, 0, 1 << 24,
                       viewport.giUpdateVoxelsPerFrame == 0 ? "all at once" : "%d voxels");
        tooltip("Occupied voxels traced per frame after an edit, for each bounce past the first and then\n"
                "the irradiance (count; 0 = all in the edit's frame); voxels not reached yet keep the old\n"
                "light. After a voxelization the first bounce marches the voxel rays (~5 us per voxel on\n"
                "llvmpipe) and records their hits; the passes after it replay them, 4x as many voxels a\n"
                "frame at about the same cost, so a light edit takes bounces x occupied / (4 x this)\n"
                "frames. The performance overlay shows the progress");
        ImGui::DragInt("Refine voxels / frame", &viewport.giRefineVoxelsPerFrame, 256.0f, 0, 1 << 24,
                       viewport.giRefineVoxelsPerFrame == 0 ? "off" : "%d voxels");
        tooltip("Once the light is traced, occupied voxels traced again per frame with the other cone sets\n"
                "(count; 0 = off) until each holds all 16: 15 more passes over the voxels, spread over frames.\n"
                "Removes the bands a few voxels wide that one set per voxel leaves");
        ImGui::DragFloat("GI ms / frame", &viewport.giMillisecondsPerFrame, 0.5f, 0.0f, 1000.0f,
                         viewport.giMillisecondsPerFrame == 0.0f ? "voxel counts only" : "%.1f ms");
        tooltip("GPU time the spread GI work may take per frame (ms; 0 = the voxel counts alone). The two\n"
                "counts above are then the most a frame traces: the GI measures what its voxels cost and\n"
                "traces what fits. While only the GI works, the 3D image is rendered again when an update\n"
                "completes and otherwise in at most a quarter of the time, so the UI stays responsive");
        ImGui::DragFloat("GI ms / idle frame", &viewport.giIdleMillisecondsPerFrame, 0.5f, 0.0f, 1000.0f,
                         viewport.giIdleMillisecondsPerFrame == 0.0f ? "as above" : "%.1f ms");
        tooltip("The same while the update after an edit runs and nothing is touched (no input, no motion,\n"
                "the interactive scale's grace over): the edit's light is final sooner, and the UI still\n"
                "answers within about this plus its own frame. The voxel counts grow with it; the refinement\n"
                "keeps GI ms / frame. Below GI ms / frame, or 0: as GI ms / frame");
    }
    changed |= comboInt("Indirect scale", s.indirect.scale, std::array{1, 2, 4});
    tooltip("Trace indirect light for one pixel in N x N and upsample edge-aware (1 = every pixel)");
    changed |= ImGui::SliderFloat("Full-res specular below", &s.indirect.specularFullResRoughness, 0.0f, 1.0f,
                                  "roughness %.2f");
    tooltip("Surfaces smoother than this trace indirect specular for every pixel (sharp reflections)");
    changed |= ImGui::Checkbox("Temporal accumulation", &s.indirect.temporalAccumulation);
    tooltip("Average indirect light over frames (reprojected; history dropped on disocclusion and edits)");
    changed |= ImGui::SliderInt("History frames", &s.indirect.temporalMaxFrames, 1, 64);
    tooltip("Frames averaged at most: more is smoother, slower to follow changes");
    changed |= ImGui::Checkbox("Cone subsets", &s.indirect.temporalConeSubsets);
    tooltip("With temporal accumulation: each traced pixel marches the normal cone and 2 of the 5 side\n"
            "cones per frame, a different pair each frame, and the accumulation averages them (half\n"
            "the cone-trace time; in the accurate mode, pairs of each pixel's stratified set)");
    ImGui::EndDisabled();
    if (s.debug.view == View::Voxels || s.debug.view == View::VoxelSlice) {
        ImGui::Separator();
        ImGui::TextDisabled(s.debug.view == View::Voxels ? "Voxel view (ray-marched)" : "Voxel slice");
        changed |= comboEnum("Channel", s.debug.voxelChannel, kVoxelChannels);
        if (s.gi.nearLevelCount() > 0) {
            // The scene's volume or a near level around the camera (those the scene runs).
            const int level = std::clamp(s.debug.voxelLevel, 0, s.gi.nearLevelCount());
            const std::string name =
                level == 0 ? std::string("scene volume")
                           : "near " + std::to_string(level) + " (" +
                                 std::to_string(static_cast<int>(std::ldexp(s.gi.nearLevelSide, level - 1))) + " m)";
            changed |= ImGui::SliderInt("Volume", &s.debug.voxelLevel, 0, s.gi.nearLevelCount(), name.c_str());
            tooltip(
                "The voxel volume shown: the one around the scene, or a near level around the camera\n"
                "(1 the finest; a scene smaller than twice a level's side runs without it)");
        }
        const int lastMip = std::max(static_cast<int>(std::log2(std::max(s.gi.voxelResolution, 1))), 0);
        changed |= ImGui::SliderInt("Mip", &s.debug.voxelMip, 0, lastMip);
        if (s.debug.view == View::VoxelSlice) {
            constexpr std::array kAxes = {"X", "Y", "Z"};
            changed |=
                ImGui::Combo("Slice axis", &s.debug.voxelSliceAxis, kAxes.data(), static_cast<int>(kAxes.size()));
            // Shown as a voxel index at the chosen mip; stored as a fraction so it survives
            // resolution changes.
            const int voxels = std::max(s.gi.voxelResolution >> std::clamp(s.debug.voxelMip, 0, lastMip), 1);
            int slice = std::clamp(static_cast<int>(s.debug.voxelSlice * static_cast<float>(voxels)), 0, voxels - 1);
            if (ImGui::SliderInt("Slice", &slice, 0, voxels - 1)) {
                s.debug.voxelSlice = (static_cast<float>(slice) + 0.5f) / static_cast<float>(voxels);
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
        changed |= drawGlobalIllumination(settings, viewport);
        ImGui::BeginDisabled(!settings.gi.enabled);
        requests.revoxelize = ImGui::Button("Re-voxelize");
        tooltip("Rebuild the voxel volume and re-inject light now (edits do this by themselves)");
        ImGui::EndDisabled();
    }
    changed |= ImGui::Checkbox("Frustum culling", &settings.output.frustumCulling);
    tooltip("Camera and shadow views draw only what their frustum may see (a BVH over the draw items)");
    ImGui::Separator();
    if (ImGui::Button("Reset to defaults")) {
        // Keep the output size: it belongs to the window, not to the user's choices.
        RenderSettings defaults;
        defaults.output.width = settings.output.width;
        defaults.output.height = settings.output.height;
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
