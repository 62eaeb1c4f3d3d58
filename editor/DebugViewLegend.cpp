#include "DebugViewLegend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "EditorViews.h"
#include "ViewportOverlay.h"
#include "passes/VoxelLevelColors.h"

namespace lit::editor {

namespace {

// `pattern` with one number in it, however long.
std::string format(const char* pattern, double a) {
    const int size = std::snprintf(nullptr, 0, pattern, a);
    if (size <= 0) return "";
    std::string text(static_cast<std::size_t>(size) + 1, '\0');
    std::snprintf(text.data(), text.size(), pattern, a);
    text.pop_back();
    return text;
}

std::array<float, 3> grey(float linear) {
    const float v = srgbEncode(std::clamp(linear, 0.0f, 1.0f));
    return {v, v, v};
}

std::array<float, 3> encoded(float r, float g, float b) { return {srgbEncode(r), srgbEncode(g), srgbEncode(b)}; }

std::string exposureText(const LegendInputs& in) {
    return format("%+.1f EV", static_cast<double>(in.exposureEv)) +
           (in.settings.output.autoExposure ? " (metered)" : "");
}

// An HDR term as the tone mapper shows it: radiance × 2^EV through the ACES curve. The stops are
// the radiances that land on middle grey's input (0.18), 1 and 4 after the exposure.
LegendRamp radianceRamp(const LegendInputs& in, const char* what) {
    const float scale = std::exp2(in.exposureEv);
    LegendRamp ramp{std::string(what) + ", W/(sr m^2) at " + exposureText(in), {}};
    constexpr std::array<float, 4> kExposed = {0.0f, 0.18f, 1.0f, 4.0f};
    for (std::size_t i = 0; i < kExposed.size(); ++i) {
        const float shown = acesFilmic(kExposed[i]);
        ramp.stops.push_back({static_cast<float>(i) / static_cast<float>(kExposed.size() - 1), grey(shown),
                              format("%.3g", static_cast<double>(kExposed[i] / scale))});
    }
    return ramp;
}

LegendRamp linearRamp(std::string label, std::array<float, 3> tint) {
    LegendRamp ramp{std::move(label), {}};
    for (const float v : {0.0f, 0.18f, 0.5f, 1.0f})
        ramp.stops.push_back(
            {v, encoded(tint[0] * v, tint[1] * v, tint[2] * v), format("%.2g", static_cast<double>(v))});
    return ramp;
}

void addNormalSwatches(ViewLegend& legend) {
    // 0.5 + 0.5·n, shown sRGB-encoded as the view does.
    const struct {
        float x, y, z;
        const char* name;
    } kAxes[] = {{1, 0, 0, "+X"},  {-1, 0, 0, "-X"}, {0, 1, 0, "+Y"},
                 {0, -1, 0, "-Y"}, {0, 0, 1, "+Z"},  {0, 0, -1, "-Z"}};
    for (const auto& a : kAxes) {
        const std::array<float, 3> c = encoded(0.5f + 0.5f * a.x, 0.5f + 0.5f * a.y, 0.5f + 0.5f * a.z);
        legend.swatches.push_back({{c[0], c[1], c[2], 1.0f}, a.name});
    }
}

// Specular terms in a scene of rough dielectrics: F0 = 0.04 spread over a wide lobe.
std::string specularNote(const LegendInputs& in) {
    const MaterialSpread spread = materialSpread(in.scene);
    if (spread.count == 0 || spread.textured) return "";
    constexpr float kRough = 0.5f, kDielectric = 0.5f;
    if (spread.minRoughness < kRough || spread.maxMetalness >= kDielectric) return "";
    return format("Near black here: every material is a rough dielectric (roughness >= %.2f, ",
                  static_cast<double>(spread.minRoughness)) +
           format(
               "metalness <= %.2f), which reflects about 4 %% (F0 0.04) of the light over a wide lobe. "
               "The light is in the diffuse terms.",
               static_cast<double>(spread.maxMetalness));
}

void describeTerm(const LegendInputs& in, ViewLegend& legend) {
    const View view = *parseView(in.view);
    const bool indirect = view == View::IndirectDiffuse || view == View::IndirectSpecular;
    const bool specular = view == View::DirectSpecular || view == View::IndirectSpecular;
    if (view == View::DirectDiffuse)
        legend.lines.push_back("Light from the lights reflected diffusely, with their shadows.");
    if (view == View::DirectSpecular)
        legend.lines.push_back("Light from the lights reflected by the GGX specular lobe.");
    if (view == View::IndirectDiffuse)
        legend.lines.push_back("Light from the voxels (" + std::string(toString(in.settings.gi.mode)) +
                               " mode) reflected diffusely.");
    if (view == View::IndirectSpecular)
        legend.lines.push_back("Light from the voxels along " + std::to_string(in.settings.indirect.specularSamples) +
                               " specular cone(s) per pixel.");
    legend.lines.push_back("Linear radiance x 2^EV, then the ACES filmic curve, as the final image.");
    legend.ramps.push_back(radianceRamp(in, "radiance"));
    if (indirect && !in.settings.gi.enabled)
        legend.note = "Black: GI is off (Render settings, GI).";
    else if (specular)
        legend.note = specularNote(in);
}

void describeChannel(const LegendInputs& in, ViewLegend& legend) {
    const VoxelChannel channel = in.settings.debug.voxelChannel;
    switch (channel) {
        case VoxelChannel::Radiance:
            legend.lines.push_back("Channel radiance: the light each voxel sends out (direct and bounced).");
            legend.ramps.push_back(radianceRamp(in, "radiance"));
            break;
        case VoxelChannel::Emission:
            legend.lines.push_back("Channel emission: the light the voxel's surfaces emit.");
            legend.ramps.push_back(radianceRamp(in, "emission"));
            break;
        case VoxelChannel::Albedo:
            legend.lines.push_back("Channel albedo: base colour as voxelized (linear).");
            legend.ramps.push_back(linearRamp("albedo", {1.0f, 1.0f, 1.0f}));
            break;
        case VoxelChannel::Normal:
            legend.lines.push_back("Channel normal: RGB = 0.5 + 0.5 n, averaged over the voxel.");
            addNormalSwatches(legend);
            break;
        case VoxelChannel::Opacity:
            legend.lines.push_back("Channel opacity: how much of the voxel is solid.");
            legend.ramps.push_back(linearRamp("opacity (0 empty, 1 solid)", {1.0f, 1.0f, 1.0f}));
            break;
    }
}

std::string levelText(const LegendInputs& in, int mip) {
    if (in.volume.resolution <= 0) return "Mip " + std::to_string(mip) + " (no voxels yet).";
    const int side = std::max(in.volume.resolution >> mip, 1);
    const double size = static_cast<double>(in.volume.voxelSize) * static_cast<double>(1 << mip);
    return "Mip " + std::to_string(mip) + " of " + std::to_string(in.volume.mipCount) + ": " + std::to_string(side) +
           "^3 voxels of " + format("%.1f cm", 100.0 * size) + ".";
}

void describeVoxels(const LegendInputs& in, ViewLegend& legend) {
    const DebugViewSettings& debug = in.settings.debug;
    const int mip = std::clamp(debug.voxelMip, 0, std::max(in.volume.mipCount - 1, 0));
    legend.voxelControls = true;
    if (*parseView(in.view) == View::Voxels) {
        legend.lines.push_back(
            "The first occupied voxel along each ray, as a cube; faces shaded by the axis they face.");
        legend.lines.push_back(levelText(in, mip));
    } else {
        legend.sliceControls = true;
        constexpr const char* kAxes[] = {"X", "Y", "Z"};
        // voxel_debug.frag.glsl, sliceView: each axis seen from its positive side.
        constexpr const char* kOrientation[] = {"-Z right, Y up", "X right, -Z up", "X right, Y up"};
        const int axis = std::clamp(debug.voxelSliceAxis, 0, 2);
        const int side = in.volume.resolution > 0 ? std::max(in.volume.resolution >> mip, 1) : 0;
        const int index = side > 0 ? std::clamp(static_cast<int>(std::floor(std::clamp(debug.voxelSlice, 0.0f, 1.0f) *
                                                                            static_cast<float>(side))),
                                                0, side - 1)
                                   : 0;
        legend.lines.push_back(std::string("Axis ") + kAxes[axis] + ", slice " + std::to_string(index) + " of " +
                               std::to_string(side) + format(" (%.2f)", static_cast<double>(debug.voxelSlice)) +
                               ", seen from +" + kAxes[axis] + ": " + kOrientation[axis] + ".");
        legend.lines.push_back(levelText(in, mip));
    }
    describeChannel(in, legend);
    if (!in.settings.gi.enabled) legend.note = "No voxels: GI is off (Render settings, GI).";
}

void describeVoxelLevels(const LegendInputs& in, ViewLegend& legend) {
    legend.lines.push_back(
        "Every volume's voxels as cubes in their level's colour, edges darkened; a finer level holds its own space.");
    const auto swatch = [](glm::vec3 c) {
        return std::array<float, 4>{srgbEncode(c.r), srgbEncode(c.g), srgbEncode(c.b), 1.0f};
    };
    const std::size_t count = in.levels.size();
    for (std::size_t k = 0; k < count; ++k) {
        const LegendVolume& v = in.levels[k];
        const bool scene = k + 1 == count;
        const std::string name = scene ? std::string("scene volume") : "near " + std::to_string(k + 1);
        legend.swatches.push_back({swatch(voxelLevelColor(scene ? 0 : static_cast<int>(k) + 1)),
                                   name + format(": %.4g m across, ", static_cast<double>(v.voxelSize) * v.resolution) +
                                       std::to_string(v.resolution) +
                                       format("^3, %.3g m voxels", static_cast<double>(v.voxelSize))});
    }
    if (!in.settings.gi.enabled)
        legend.note = "No voxels: GI is off (Render settings, GI).";
    else if (count == 1 && in.settings.gi.nearLevelCount() > 0)
        legend.note = "No near level runs: the scene is smaller than twice a level's side.";
}

void describeConeDirections(const LegendInputs& in, ViewLegend& legend) {
    const GiSettings& gi = in.settings.gi;
    if (!in.coneSurfacePicked) legend.lines.push_back("Click a surface to draw the cones traced from that pixel.");
    legend.lines.push_back("Mode " + std::string(toString(gi.mode)) +
                           "; cones drawn to a quarter of the volume's side.");
    const auto rgba = [](glm::vec4 c) { return std::array<float, 4>{c.r, c.g, c.b, c.a}; };
    legend.swatches.push_back({rgba(kDiffuseConeColor), gi.mode == GiMode::Fast ? "diffuse cones (six, 60 deg)"
                                                                                : "diffuse cones (stratified set)"});
    legend.swatches.push_back({rgba(kSpecularConeColor), in.settings.indirect.specularSamples <= 1
                                                             ? "specular cone (the lobe's core, mirror direction)"
                                                             : "specular cones (GGX samples)"});
    glm::vec4 faint = kSpecularConeColor;
    faint.a *= kUnmarchedConeAlpha;
    legend.swatches.push_back({rgba(faint), "faint: not marched, the rough surface reuses the diffuse cones' light"});
    if (gi.footprintPerHeight() > 0.0f) {
        legend.lines.push_back("Circles: the voxels each sample reads, as wide as they are.");
        if (gi.anisotropicVoxels()) {
            legend.swatches.push_back({{1.0f, 0.0f, 0.0f, 1.0f}, "circle red: X faces of directional voxels"});
            legend.swatches.push_back({{0.0f, 1.0f, 0.0f, 1.0f}, "circle green: Y faces"});
            legend.swatches.push_back(
                {{0.0f, 0.0f, 1.0f, 1.0f}, "circle blue: Z faces (mixed: the blend, by direction^2)"});
        }
    }
}

void describeShadowMap(const LegendInputs& in, ViewLegend& legend) {
    const auto& lights = in.scene.lights;
    const int index = in.shadowMapLight;
    std::string name =
        index >= 0 && index < static_cast<int>(lights.size()) ? lights[static_cast<std::size_t>(index)].name : "";
    legend.lines.push_back("Depth seen from light " + std::to_string(index) + (name.empty() ? "" : " (" + name + ")") +
                           "; select a light to show its map.");
    legend.lines.push_back("Shown as depth^32, so the far end, where depth crowds, spreads out.");
    LegendRamp ramp{"depth (0 at the light, 1 far)", {}};
    constexpr std::array<float, 5> kDepths = {0.9f, 0.95f, 0.98f, 0.99f, 1.0f};
    for (std::size_t i = 0; i < kDepths.size(); ++i)
        ramp.stops.push_back({static_cast<float>(i) / static_cast<float>(kDepths.size() - 1),
                              grey(std::pow(kDepths[i], 32.0f)), format("%.2f", static_cast<double>(kDepths[i]))});
    legend.ramps.push_back(std::move(ramp));
    if (lights.empty())
        legend.note = "Black: the scene has no lights (the default sun casts no shadow map).";
    else if (index < 0 || index >= static_cast<int>(lights.size()))
        legend.note = "Black: there is no light " + std::to_string(index) + ".";
    else if (lights[static_cast<std::size_t>(index)].type == LightType::Point)
        legend.note = "Black: a point light's cube map is not shown here; select a spot or directional light.";
    else if (!lights[static_cast<std::size_t>(index)].castsShadow)
        legend.note = "Black: this light casts no shadow.";
}

}  // namespace

float srgbEncode(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

float acesFilmic(float x) {
    constexpr float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

MaterialSpread materialSpread(const Scene& scene) {
    MaterialSpread spread;
    for (const Material& m : scene.materials) {
        ++spread.count;
        spread.minRoughness = std::min(spread.minRoughness, m.roughness);
        spread.maxRoughness = std::max(spread.maxRoughness, m.roughness);
        spread.maxMetalness = std::max(spread.maxMetalness, m.metallic);
        spread.textured |= m.metallicRoughnessTexture >= 0;
    }
    return spread;
}

ViewLegend describeDebugView(const LegendInputs& in) {
    ViewLegend legend;
    const EditorView* entry = findEditorView(in.view);
    if (entry == nullptr || in.view == "final") return legend;
    legend.title = std::string(entry->label) + " (" + std::string(entry->shortcut) + ")";
    if (in.view == kConeDirectionsView) {
        describeConeDirections(in, legend);
        return legend;
    }
    switch (*parseView(in.view)) {
        case View::Final:
            break;
        case View::DirectDiffuse:
        case View::DirectSpecular:
        case View::IndirectDiffuse:
        case View::IndirectSpecular:
            describeTerm(in, legend);
            break;
        case View::Albedo:
            legend.lines.push_back("Base colour x texture (linear, as the G-buffer holds it); background black.");
            legend.ramps.push_back(linearRamp("albedo", {1.0f, 1.0f, 1.0f}));
            break;
        case View::Normal:
            legend.lines.push_back("World-space normal as RGB = 0.5 + 0.5 n; background black.");
            addNormalSwatches(legend);
            break;
        case View::RoughnessMetalness: {
            legend.lines.push_back("R = roughness, G = metalness (factor x texture), B = 0; background black.");
            legend.ramps.push_back(linearRamp("R: roughness", {1.0f, 0.0f, 0.0f}));
            legend.ramps.push_back(linearRamp("G: metalness", {0.0f, 1.0f, 0.0f}));
            legend.swatches.push_back({{1.0f, 0.0f, 0.0f, 1.0f}, "rough dielectric"});
            legend.swatches.push_back({{1.0f, 1.0f, 0.0f, 1.0f}, "rough metal"});
            legend.swatches.push_back({{0.0f, 1.0f, 0.0f, 1.0f}, "smooth metal"});
            const MaterialSpread spread = materialSpread(in.scene);
            if (spread.count > 0)
                legend.lines.push_back(
                    format("Scene factors: roughness %.2f", static_cast<double>(spread.minRoughness)) +
                    format("..%.2f", static_cast<double>(spread.maxRoughness)) +
                    format(", metalness <= %.2f", static_cast<double>(spread.maxMetalness)) +
                    (spread.textured ? " (textures lower them)." : "."));
            break;
        }
        case View::ShadowMap:
            describeShadowMap(in, legend);
            break;
        case View::Voxels:
        case View::VoxelSlice:
            describeVoxels(in, legend);
            break;
        case View::VoxelLevels:
            describeVoxelLevels(in, legend);
            break;
    }
    return legend;
}

std::string legendText(const ViewLegend& legend) {
    std::string text = legend.title;
    for (const std::string& line : legend.lines) text += " | " + line;
    for (const LegendRamp& ramp : legend.ramps) {
        text += " | ramp " + ramp.label + ":";
        for (const LegendStop& stop : ramp.stops) text += " " + stop.label;
    }
    for (const LegendSwatch& swatch : legend.swatches) text += " | " + swatch.meaning;
    if (!legend.note.empty()) text += " | note: " + legend.note;
    return text;
}

}  // namespace lit::editor
