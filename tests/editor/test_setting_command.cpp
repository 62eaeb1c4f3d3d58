#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "EditorState.h"
#include "SettingCommand.h"

namespace {

using lit::RenderSettings;
using lit::View;
using lit::editor::applySetting;

TEST(EditorSettingCommand, SetsNumbersBooleansAndViewNames) {
    RenderSettings settings;
    EXPECT_EQ(applySetting(settings, "voxelResolution", "64"), "");
    EXPECT_EQ(settings.gi.voxelResolution, 64);
    EXPECT_EQ(applySetting(settings, "gi", "false"), "");
    EXPECT_FALSE(settings.gi.enabled);
    EXPECT_EQ(applySetting(settings, "exposure", "2.5"), "");
    EXPECT_FLOAT_EQ(settings.output.exposureEv, std::log2(2.5f));  // the linear key of older scripts
    EXPECT_EQ(applySetting(settings, "exposureEv", "-3.5"), "");
    EXPECT_FLOAT_EQ(settings.output.exposureEv, -3.5f);
    EXPECT_EQ(applySetting(settings, "skyZenith", "[0.5, 0.25, 1]"), "");
    EXPECT_EQ(settings.sky.zenith, (std::array<float, 3>{0.5f, 0.25f, 1.0f}));
    EXPECT_EQ(applySetting(settings, "view", "albedo"), "");
    EXPECT_EQ(settings.debug.view, View::Albedo);
}

TEST(EditorSettingCommand, RejectsUnknownKeysBadValuesAndTheWindowSize) {
    RenderSettings settings;
    const RenderSettings before = settings;
    EXPECT_NE(applySetting(settings, "voxelRes", "64").find("unknown render setting 'voxelRes'"), std::string::npos);
    EXPECT_NE(applySetting(settings, "gi", "maybe").find("'gi' has the wrong type"), std::string::npos);
    EXPECT_NE(applySetting(settings, "voxelResolution", "1.5").find("voxelResolution"), std::string::npos);
    EXPECT_NE(applySetting(settings, "voxelResolution", "100").find("power of two"), std::string::npos);
    EXPECT_NE(applySetting(settings, "view", "nonsense").find("view"), std::string::npos);
    EXPECT_NE(applySetting(settings, "width", "640").find("--size"), std::string::npos);
    EXPECT_EQ(settings, before);  // nothing changed by any of them
}

// "setting gi.mode fast|accurate|cached" (the panel's GI mode combo) sets the mode, which implies
// the cone features; the footprint parameter applies to the accurate and cached modes only.
TEST(EditorSettingCommand, GiModeIsOneField) {
    RenderSettings settings;
    EXPECT_EQ(settings.gi.mode, lit::GiMode::Cached);  // the default
    EXPECT_EQ(applySetting(settings, "gi.mode", "accurate"), "");
    EXPECT_TRUE(settings.gi.anisotropicVoxels());
    EXPECT_EQ(settings.gi.footprintPerHeight(), lit::kAccurateGiFootprint);
    EXPECT_FALSE(settings.gi.voxelIrradiance());
    EXPECT_EQ(settings.gi.mode, lit::GiMode::Accurate);
    EXPECT_EQ(applySetting(settings, "gi.coneFootprintPerHeight", "0.5"), "");
    EXPECT_EQ(settings.gi.mode, lit::GiMode::Accurate);
    EXPECT_EQ(settings.gi.footprintPerHeight(), 0.5f);
    EXPECT_EQ(applySetting(settings, "gi.mode", "fast"), "");
    EXPECT_FALSE(settings.gi.anisotropicVoxels());
    EXPECT_EQ(settings.gi.footprintPerHeight(), 0.0f);
    EXPECT_FALSE(settings.gi.voxelIrradiance());
    EXPECT_EQ(applySetting(settings, "gi.coneFootprintPerHeight", "0.25"), "");
    EXPECT_EQ(applySetting(settings, "giMode", "cached"), "");  // the older script key
    EXPECT_EQ(settings, RenderSettings{});
    EXPECT_EQ(applySetting(settings, "gi.mode", "custom"),
              "render settings: 'gi.mode' is not a known name (got 'custom')");
    EXPECT_EQ(settings, RenderSettings{});
}

// The grouped keys, and an older flat key that still works with a deprecation message.
TEST(EditorSettingCommand, GroupedKeysAndDeprecatedFlatKeys) {
    RenderSettings settings;
    std::vector<std::string> warnings;
    EXPECT_EQ(applySetting(settings, "gi.voxelResolution", "64", &warnings), "");
    EXPECT_EQ(settings.gi.voxelResolution, 64);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(applySetting(settings, "indirect.scale", "4", &warnings), "");
    EXPECT_EQ(settings.indirect.scale, 4);
    EXPECT_EQ(applySetting(settings, "bounces", "3", &warnings), "");
    EXPECT_EQ(settings.gi.bounces, 3);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "render settings: 'bounces' is deprecated; read as gi.bounces");
    EXPECT_NE(applySetting(settings, "output.width", "640").find("--size"), std::string::npos);
}

// The editor's own settings (not render settings) by key, and their older render-settings names.
TEST(EditorSettingCommand, EditorSettings) {
    lit::editor::ViewportSettings viewport;
    std::vector<std::string> warnings;
    EXPECT_EQ(lit::editor::applyEditorSetting(viewport, "editor.interactiveFpsTarget", "60", &warnings), "");
    EXPECT_EQ(viewport.interactiveFpsTarget, 60.0f);
    EXPECT_EQ(lit::editor::applyEditorSetting(viewport, "voxelIrradianceRefineVoxelsPerFrame", "100", &warnings), "");
    EXPECT_EQ(viewport.giRefineVoxelsPerFrame, 100);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("editor.giRefineVoxelsPerFrame"), std::string::npos);
    EXPECT_NE(lit::editor::applyEditorSetting(viewport, "editor.giUpdateVoxelsPerFrame", "-3")->find("voxel count"),
              std::string::npos);
    EXPECT_FALSE(lit::editor::applyEditorSetting(viewport, "gi.bounces", "2").has_value());
    EXPECT_EQ(lit::editor::applyEditorSetting(viewport, "editor.redrawOnDemand", "false"), "");
    EXPECT_FALSE(viewport.redrawOnDemand);
    EXPECT_NE(lit::editor::applyEditorSetting(viewport, "editor.redrawOnDemand", "0")->find("true or false"),
              std::string::npos);
}

// The script's "panel NAME on|off" and the View menu name the same flags.
TEST(EditorPanelFlag, NamesEveryPanelAndRejectsOthers) {
    lit::editor::PanelVisibility visible;
    EXPECT_EQ(lit::editor::panelFlag(visible, "hierarchy"), &visible.hierarchy);
    EXPECT_EQ(lit::editor::panelFlag(visible, "inspector"), &visible.inspector);
    EXPECT_EQ(lit::editor::panelFlag(visible, "settings"), &visible.renderSettings);
    EXPECT_EQ(lit::editor::panelFlag(visible, "stats"), &visible.stats);
    EXPECT_EQ(lit::editor::panelFlag(visible, "camera"), &visible.camera);
    EXPECT_EQ(lit::editor::panelFlag(visible, "log"), &visible.log);
    EXPECT_EQ(lit::editor::panelFlag(visible, "timeline"), &visible.timeline);
    EXPECT_EQ(lit::editor::panelFlag(visible, "legend"), &visible.legend);
    EXPECT_EQ(lit::editor::panelFlag(visible, "stats-details"), &visible.statsDetails);
    for (const char* name : lit::editor::kPanelNames) EXPECT_NE(lit::editor::panelFlag(visible, name), nullptr) << name;
    EXPECT_EQ(lit::editor::panelFlag(visible, "Inspector"), nullptr);
    EXPECT_EQ(lit::editor::panelFlag(visible, "render"), nullptr);
}

}  // namespace
