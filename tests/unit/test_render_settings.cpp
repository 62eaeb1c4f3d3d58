// RenderSettings as JSON: one object per group, every key read back, and the flat keys of older
// files read into their new places with a deprecation message each.

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "RenderSettings.h"

namespace {

using lit::GiMode;
using lit::RenderSettings;

bool mentions(const std::vector<std::string>& messages, const std::string& text) {
    return std::any_of(messages.begin(), messages.end(),
                       [&](const std::string& m) { return m.find(text) != std::string::npos; });
}

TEST(RenderSettingsJson, GroupsRoundTripWithoutWarnings) {
    RenderSettings s;
    s.output.width = 320;
    s.sky.mode = lit::SkyMode::Uniform;
    s.shadows.mapSize = 2048;
    s.gi.mode = GiMode::Fast;
    s.gi.voxelResolution = 256;
    s.indirect.scale = 4;
    s.terms.indirectSpecular = false;
    s.debug.view = lit::View::VoxelSlice;
    const std::string json = lit::toJson(s);
    EXPECT_NE(json.find("\"gi\": {"), std::string::npos) << json;
    EXPECT_NE(json.find("\"voxelResolution\": 256"), std::string::npos) << json;
    std::vector<std::string> warnings;
    EXPECT_EQ(lit::renderSettingsFromJson(json, {}, &warnings), s);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
}

// A sidecar written before the settings had groups: every key lands in its group, the GI mode is
// derived from the three fields it replaced, and each old key is named in a deprecation message.
TEST(RenderSettingsJson, OldFlatFileGivesTheNewSettingsAndDeprecationWarnings) {
    const char* old = R"({
        "width": 640, "height": 360, "exposureEv": -1.5, "skyMode": "uniform", "skyZenith": [1, 2, 3],
        "defaultSunIrradiance": 2.0, "shadows": false, "shadowMapSize": 512, "shadowDebugLight": 1,
        "gi": true, "voxelResolution": 64, "voxelRadianceRgba8": true, "bounces": 3, "voxelRays": 16,
        "anisotropicVoxels": true, "coneFootprintPerHeight": 0.25, "diffuseFromVoxelIrradiance": false,
        "indirectScale": 4, "temporalAccumulation": true, "specularSamples": 4, "directSpecular": false,
        "view": "indirect-diffuse", "voxelChannel": "albedo", "frustumCulling": false,
        "interactiveFpsTarget": 30, "voxelIrradianceVoxelsPerFrame": 16384, "voxelIrradianceRefineVoxelsPerFrame": 8192
    })";
    std::vector<std::string> warnings;
    const RenderSettings s = lit::renderSettingsFromJson(old, {}, &warnings);
    EXPECT_EQ(s.output.width, 640);
    EXPECT_EQ(s.output.height, 360);
    EXPECT_EQ(s.output.exposureEv, -1.5f);
    EXPECT_FALSE(s.output.frustumCulling);
    EXPECT_EQ(s.sky.mode, lit::SkyMode::Uniform);
    EXPECT_EQ(s.sky.zenith, (std::array<float, 3>{1.0f, 2.0f, 3.0f}));
    EXPECT_EQ(s.sky.sunIrradiance, 2.0f);
    EXPECT_FALSE(s.shadows.enabled);
    EXPECT_EQ(s.shadows.mapSize, 512);
    EXPECT_EQ(s.debug.shadowMapLight, 1);
    EXPECT_TRUE(s.gi.enabled);
    EXPECT_EQ(s.gi.voxelResolution, 64);
    EXPECT_TRUE(s.gi.radianceRgba8);
    EXPECT_EQ(s.gi.bounces, 3);
    EXPECT_EQ(s.gi.voxelRays, 16);
    EXPECT_EQ(s.gi.mode, GiMode::Accurate) << "directional voxels without the voxel irradiance";
    EXPECT_EQ(s.indirect.scale, 4);
    EXPECT_TRUE(s.indirect.temporalAccumulation);
    EXPECT_EQ(s.indirect.specularSamples, 4);
    EXPECT_FALSE(s.terms.directSpecular);
    EXPECT_EQ(s.debug.view, lit::View::IndirectDiffuse);
    EXPECT_EQ(s.debug.voxelChannel, lit::VoxelChannel::Albedo);

    EXPECT_TRUE(mentions(warnings, "'voxelResolution' is deprecated; read as gi.voxelResolution"));
    EXPECT_TRUE(mentions(warnings, "'shadows' is deprecated; read as shadows.enabled"));
    EXPECT_TRUE(mentions(warnings, "'view' is deprecated; read as debug.view"));
    EXPECT_TRUE(mentions(warnings, "read as gi.mode \"accurate\""));
    // What moved to the editor is named with where it went.
    EXPECT_TRUE(mentions(warnings, "'interactiveFpsTarget' is no longer a render setting"));
    EXPECT_TRUE(mentions(warnings, "editor.giUpdateVoxelsPerFrame"));
    // One message per old key (27), the two fields the mode replaced sharing one.
    EXPECT_EQ(warnings.size(), 26u);

    // The cached and fast modes from the old fields.
    EXPECT_EQ(lit::renderSettingsFromJson(R"({"diffuseFromVoxelIrradiance": true})").gi.mode, GiMode::Cached);
    EXPECT_EQ(
        lit::renderSettingsFromJson(R"({"anisotropicVoxels": false, "diffuseFromVoxelIrradiance": false})").gi.mode,
        GiMode::Fast);
    // A grouped key wins over an old flat one in the same file.
    EXPECT_EQ(
        lit::renderSettingsFromJson(R"({"voxelResolution": 64, "gi": {"voxelResolution": 256}})").gi.voxelResolution,
        256);
}

TEST(RenderSettingsJson, BadValuesNameTheKey) {
    try {
        lit::renderSettingsFromJson(R"({"gi": {"voxelResolution": "many"}})");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("'gi.voxelResolution'"), std::string::npos) << e.what();
    }
    try {
        lit::renderSettingsFromJson(R"({"bounces": true})");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("'bounces'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(lit::renderSettingsFromJson(R"({"gi": {"mode": "custom"}})"), std::runtime_error);
}

// Every key renderSettingKeys lists is one setRenderSetting takes, with the value toJson writes.
TEST(RenderSettingsJson, EveryKeyCanBeSetByName) {
    const std::vector<std::string> keys = lit::renderSettingKeys();
    EXPECT_EQ(keys.size(), 63u);
    EXPECT_EQ(keys.front(), "output.width");
    RenderSettings changed;
    changed.output.exposureEv = 2.0f;
    changed.sky.hdrPath = "sky.hdr";
    changed.gi.mode = GiMode::Fast;
    changed.debug.view = lit::View::Albedo;
    const nlohmann::json values = nlohmann::json::parse(lit::toJson(changed));
    RenderSettings s;
    for (const std::string& key : keys) {
        const std::size_t dot = key.find('.');
        EXPECT_NO_THROW(lit::setRenderSetting(s, key, values[key.substr(0, dot)][key.substr(dot + 1)].dump())) << key;
    }
    EXPECT_EQ(s, changed);
    EXPECT_THROW(lit::setRenderSetting(s, "gi.sparkles", "1"), std::runtime_error);
}

}  // namespace
