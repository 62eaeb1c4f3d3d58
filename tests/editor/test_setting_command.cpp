#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "EditorState.h"
#include "SettingCommand.h"

namespace {

using lit::RenderSettings;
using lit::View;
using lit::editor::applySetting;

TEST(EditorSettingCommand, SetsNumbersBooleansAndViewNames) {
    RenderSettings settings;
    EXPECT_EQ(applySetting(settings, "voxelResolution", "64"), "");
    EXPECT_EQ(settings.voxelResolution, 64);
    EXPECT_EQ(applySetting(settings, "gi", "false"), "");
    EXPECT_FALSE(settings.gi);
    EXPECT_EQ(applySetting(settings, "exposure", "2.5"), "");
    EXPECT_FLOAT_EQ(settings.exposureEv, std::log2(2.5f));  // the linear key of older scripts
    EXPECT_EQ(applySetting(settings, "exposureEv", "-3.5"), "");
    EXPECT_FLOAT_EQ(settings.exposureEv, -3.5f);
    EXPECT_EQ(applySetting(settings, "skyZenith", "[0.5, 0.25, 1]"), "");
    EXPECT_EQ(settings.skyZenith, (std::array<float, 3>{0.5f, 0.25f, 1.0f}));
    EXPECT_EQ(applySetting(settings, "view", "albedo"), "");
    EXPECT_EQ(settings.view, View::Albedo);
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

// "setting giMode fast|accurate|cached" sets the three fields the preset names (the panel's GI mode combo).
TEST(EditorSettingCommand, GiModeSetsTheThreeGiFields) {
    RenderSettings settings;
    EXPECT_EQ(lit::giModeOf(settings), lit::GiMode::Cached);  // the default
    EXPECT_EQ(applySetting(settings, "giMode", "accurate"), "");
    EXPECT_TRUE(settings.anisotropicVoxels);
    EXPECT_EQ(settings.coneFootprintPerHeight, lit::kAccurateGiFootprint);
    EXPECT_FALSE(settings.diffuseFromVoxelIrradiance);
    EXPECT_EQ(lit::giModeOf(settings), lit::GiMode::Accurate);
    EXPECT_EQ(applySetting(settings, "coneFootprintPerHeight", "0.5"), "");
    EXPECT_EQ(lit::giModeOf(settings), lit::GiMode::Custom);
    EXPECT_EQ(applySetting(settings, "giMode", "fast"), "");
    EXPECT_FALSE(settings.anisotropicVoxels);
    EXPECT_EQ(settings.coneFootprintPerHeight, 0.0f);
    EXPECT_FALSE(settings.diffuseFromVoxelIrradiance);
    EXPECT_EQ(lit::giModeOf(settings), lit::GiMode::Fast);
    EXPECT_EQ(applySetting(settings, "giMode", "cached"), "");
    EXPECT_EQ(settings, RenderSettings{});
    EXPECT_EQ(applySetting(settings, "giMode", "custom"),
              "setting giMode: expected fast, accurate or cached (got 'custom')");
    EXPECT_EQ(settings, RenderSettings{});
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
    EXPECT_EQ(lit::editor::panelFlag(visible, "Inspector"), nullptr);
    EXPECT_EQ(lit::editor::panelFlag(visible, "render"), nullptr);
}

}  // namespace
