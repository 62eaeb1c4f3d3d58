#include <gtest/gtest.h>

#include <string>

#include "DebugViewLegend.h"
#include "EditorViews.h"
#include "scene/SceneBuilder.h"

namespace {

using namespace lit;
using namespace lit::editor;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

Scene sceneWithMaterial(float roughness, float metalness) {
    Scene scene;
    addMaterial(scene, glm::vec3(0.7f), roughness, metalness, "wall");
    Light spot;
    spot.type = LightType::Spot;
    spot.name = "lamp";
    scene.lights.push_back(spot);
    return scene;
}

ViewLegend legendOf(std::string_view view, const Scene& scene, const RenderSettings& settings = {},
                    LegendVolume volume = {128, 8, 0.05f}) {
    return describeDebugView({.view = view, .settings = settings, .scene = scene, .volume = volume});
}

// Every debug view but the final image explains itself; the final image needs no legend.
TEST(DebugViewLegend, EveryDebugViewHasOne) {
    const Scene scene = sceneWithMaterial(0.9f, 0.0f);
    for (const EditorView& view : editorViews()) {
        const ViewLegend legend = legendOf(view.name, scene);
        if (view.name == "final") {
            EXPECT_TRUE(legend.empty());
            continue;
        }
        EXPECT_FALSE(legend.empty()) << view.name;
        EXPECT_TRUE(contains(legend.title, std::string(view.label))) << view.name;
        EXPECT_FALSE(legend.lines.empty() && legend.ramps.empty() && legend.swatches.empty()) << view.name;
    }
}

// The roughness / metalness view names its channels and gives each a 0..1 ramp.
TEST(DebugViewLegend, RoughnessMetalnessNamesItsChannels) {
    const ViewLegend legend = legendOf("roughness-metalness", sceneWithMaterial(0.9f, 0.0f));
    ASSERT_EQ(legend.ramps.size(), 2u);
    EXPECT_TRUE(contains(legend.ramps[0].label, "roughness"));
    EXPECT_TRUE(contains(legend.ramps[1].label, "metalness"));
    EXPECT_EQ(legend.ramps[0].stops.front().label, "0");
    EXPECT_EQ(legend.ramps[0].stops.back().label, "1");
    EXPECT_GT(legend.ramps[0].stops.back().color[0], 0.99f);  // full roughness is pure red
    EXPECT_LT(legend.ramps[0].stops.back().color[1], 0.01f);
    EXPECT_TRUE(contains(legendText(legend), "roughness 0.90..0.90"));
}

// In a scene of rough dielectrics the specular terms say why they are near black; with a smooth
// metal they do not.
TEST(DebugViewLegend, SpecularTermsExplainARoughScene) {
    const Scene rough = sceneWithMaterial(0.9f, 0.0f);
    EXPECT_TRUE(contains(legendOf("direct-specular", rough).note, "rough dielectric"));
    EXPECT_TRUE(contains(legendOf("direct-specular", rough).note, "metalness <= 0.00), which reflects about 4 %"));
    EXPECT_TRUE(contains(legendOf("direct-specular", rough).note, "The light is in the diffuse terms."));
    EXPECT_TRUE(contains(legendOf("indirect-specular", rough).note, "rough dielectric"));
    EXPECT_TRUE(legendOf("direct-diffuse", rough).note.empty());
    EXPECT_TRUE(legendOf("direct-specular", sceneWithMaterial(0.2f, 1.0f)).note.empty());
    RenderSettings noGi;
    noGi.gi.enabled = false;
    EXPECT_TRUE(contains(legendOf("indirect-diffuse", rough, noGi).note, "GI is off"));
}

// HDR terms quote the exposure and the radiance each stop of the ramp stands for.
TEST(DebugViewLegend, RadianceRampFollowsTheExposure) {
    const Scene scene = sceneWithMaterial(0.9f, 0.0f);
    const ViewLegend plain =
        describeDebugView({.view = "direct-diffuse", .settings = {}, .scene = scene, .exposureEv = 0.0f});
    const ViewLegend brighter =
        describeDebugView({.view = "direct-diffuse", .settings = {}, .scene = scene, .exposureEv = 1.0f});
    ASSERT_EQ(plain.ramps.size(), 1u);
    EXPECT_TRUE(contains(plain.ramps[0].label, "+0.0 EV"));
    EXPECT_TRUE(contains(brighter.ramps[0].label, "+1.0 EV"));
    EXPECT_EQ(plain.ramps[0].stops[2].label, "1");
    EXPECT_EQ(brighter.ramps[0].stops[2].label, "0.5");  // half the radiance reaches the same grey
}

// The slice view says its axis, slice, mip and channel, and carries their controls.
TEST(DebugViewLegend, VoxelSliceSaysWhatItCuts) {
    RenderSettings settings;
    settings.debug.voxelSliceAxis = 1;
    settings.debug.voxelSlice = 0.5f;
    settings.debug.voxelMip = 1;
    settings.debug.voxelChannel = VoxelChannel::Albedo;
    const ViewLegend legend = legendOf("voxel-slice", sceneWithMaterial(0.9f, 0.0f), settings, {128, 8, 0.05f});
    const std::string text = legendText(legend);
    EXPECT_TRUE(contains(text, "Axis Y, slice 32 of 64")) << text;
    EXPECT_TRUE(contains(text, "X right, -Z up")) << text;
    EXPECT_TRUE(contains(text, "Mip 1 of 8: 64^3 voxels of 10.0 cm")) << text;
    EXPECT_TRUE(contains(text, "Channel albedo")) << text;
    EXPECT_TRUE(legend.voxelControls);
    EXPECT_TRUE(legend.sliceControls);
    EXPECT_FALSE(legendOf("voxels", Scene{}, settings).sliceControls);
}

// The voxel-levels view names each volume running in its colour, finest first, with its size and
// its voxels'.
TEST(DebugViewLegend, VoxelLevelsNameEachVolumeInItsColour) {
    const Scene scene = sceneWithMaterial(0.9f, 0.0f);
    const RenderSettings settings;
    const ViewLegend legend = describeDebugView(
        {.view = "voxel-levels", .settings = settings, .scene = scene, .levels = {{128, 8, 0.5f}, {128, 8, 5.0f}}});
    const std::string text = legendText(legend);
    ASSERT_EQ(legend.swatches.size(), 2u) << text;
    EXPECT_TRUE(contains(legend.swatches[0].meaning, "near 1: 64 m across, 128^3, 0.5 m voxels")) << text;
    EXPECT_TRUE(contains(legend.swatches[1].meaning, "scene volume: 640 m across, 128^3, 5 m voxels")) << text;
    EXPECT_NE(legend.swatches[0].color, legend.swatches[1].color);
    EXPECT_TRUE(legend.note.empty()) << text;
    // A scene too small for a near level: the scene's volume alone, and why.
    const ViewLegend alone =
        describeDebugView({.view = "voxel-levels", .settings = settings, .scene = scene, .levels = {{128, 8, 0.05f}}});
    ASSERT_EQ(alone.swatches.size(), 1u);
    EXPECT_TRUE(contains(alone.note, "smaller than twice")) << legendText(alone);
}

// The cone directions' colours are the overlay's own.
TEST(DebugViewLegend, ConeColoursMatchTheOverlay) {
    const ViewLegend legend = legendOf(kConeDirectionsView, Scene{});
    ASSERT_GE(legend.swatches.size(), 3u);
    EXPECT_TRUE(contains(legend.swatches[0].meaning, "diffuse"));
    EXPECT_FLOAT_EQ(legend.swatches[0].color[1], 1.0f);  // green
    EXPECT_TRUE(contains(legend.swatches[1].meaning, "specular"));
    EXPECT_TRUE(contains(legend.swatches[2].meaning, "not marched"));
    EXPECT_LT(legend.swatches[2].color[3], legend.swatches[1].color[3]);
    EXPECT_TRUE(contains(legendText(legend), "Click a surface"));
}

TEST(DebugViewLegend, ShadowMapOfAPointLightSaysWhyItIsBlack) {
    Scene scene = sceneWithMaterial(0.9f, 0.0f);
    EXPECT_TRUE(legendOf("shadow-map", scene).note.empty());
    scene.lights[0].type = LightType::Point;
    EXPECT_TRUE(contains(legendOf("shadow-map", scene).note, "point light"));
    EXPECT_TRUE(contains(legendOf("shadow-map", Scene{}).note, "no lights"));
}

}  // namespace
