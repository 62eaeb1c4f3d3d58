// The voxel debug view settings: the slice view's name and the channel enum in text and JSON.
#include "RenderSettings.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace lit {
namespace {

TEST(VoxelViewSettings, SliceViewHasATextName) {
    EXPECT_EQ(toString(View::VoxelSlice), "voxel-slice");
    EXPECT_EQ(parseView("voxel-slice"), View::VoxelSlice);
}

TEST(VoxelViewSettings, ChannelNamesRoundTrip) {
    for (VoxelChannel c : {VoxelChannel::Radiance, VoxelChannel::Albedo, VoxelChannel::Normal, VoxelChannel::Opacity,
                           VoxelChannel::Emission})
        EXPECT_EQ(parseVoxelChannel(toString(c)), c);
    EXPECT_EQ(toString(VoxelChannel::Opacity), "opacity");
    EXPECT_FALSE(parseVoxelChannel("Albedo"));
    EXPECT_FALSE(parseVoxelChannel(""));
}

TEST(VoxelViewSettings, ChannelIsSavedByNameAndLoaded) {
    RenderSettings s;
    s.debug.view = View::VoxelSlice;
    s.debug.voxelChannel = VoxelChannel::Normal;
    s.debug.voxelMip = 2;
    const std::string json = toJson(s);
    EXPECT_NE(json.find("\"voxelChannel\": \"normal\""), std::string::npos) << json;
    EXPECT_EQ(renderSettingsFromJson(json), s);
}

TEST(VoxelViewSettings, UnknownChannelNamesTheKey) {
    try {
        renderSettingsFromJson(R"({"voxelChannel": "colour"})");
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("voxelChannel"), std::string::npos) << e.what();
    }
    EXPECT_THROW(renderSettingsFromJson(R"({"voxelChannel": 1})"), std::runtime_error);
}

}  // namespace
}  // namespace lit
