#include <gtest/gtest.h>

#include <vector>

#include "ViewportArea.h"

namespace {

using namespace lit::editor;

// The editor's layout at 1280x720 under a 19-unit menu bar (panels/Layout.h): columns 282 and
// 345 wide, the log and the timeline along the bottom between them.
const glm::vec2 kDisplay(1280.0f, 720.0f);
const glm::vec4 kHierarchy(8, 27, 282, 270), kInspector(8, 305, 282, 407);
const glm::vec4 kSettings(927, 27, 345, 480), kCamera(927, 515, 345, 197);
const glm::vec4 kLog(298, 541, 278, 171), kTimeline(584, 541, 335, 171);

TEST(ViewportArea, TheDockedPanelsBoundTheVisibleViewport) {
    const std::vector<glm::vec4> all{kHierarchy, kInspector, kSettings, kCamera, kLog, kTimeline};
    const glm::vec4 area = visibleViewportArea(kDisplay, 19.0f, all);
    EXPECT_FLOAT_EQ(area.x, 8 + 282 + kViewportMargin);
    EXPECT_FLOAT_EQ(area.y, 19.0f);
    EXPECT_FLOAT_EQ(area.x + area.z, 927 - kViewportMargin);
    EXPECT_FLOAT_EQ(area.y + area.w, 541 - kViewportMargin);
    EXPECT_TRUE(insideArea(area, {600, 300}));
    EXPECT_FALSE(insideArea(area, {600, 600}));  // over the timeline
    EXPECT_FALSE(insideArea(area, {294, 300}));  // the gap beside the hierarchy
}

TEST(ViewportArea, HiddenOrMovedPanelsGiveTheirRoomBack) {
    // The right column hidden: the area reaches the window's right side.
    const std::vector<glm::vec4> noRight{kHierarchy, kInspector, kLog, kTimeline};
    EXPECT_FLOAT_EQ(visibleViewportArea(kDisplay, 19.0f, noRight).z, 1280.0f - (8 + 282 + kViewportMargin));
    // The timeline dragged up into the middle floats over the picture: the log still bounds it.
    const glm::vec4 floating(500, 200, 335, 171);
    const glm::vec4 area = visibleViewportArea(kDisplay, 19.0f, std::vector<glm::vec4>{kLog, floating});
    EXPECT_FLOAT_EQ(area.x, 0.0f);
    EXPECT_FLOAT_EQ(area.y + area.w, 541 - kViewportMargin);
    // No panels: the whole window below the menu.
    const glm::vec4 whole = visibleViewportArea(kDisplay, 19.0f, {});
    EXPECT_EQ(whole, glm::vec4(0, 19, 1280, 701));
}

}  // namespace
