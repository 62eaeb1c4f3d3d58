#include <gtest/gtest.h>

#include <map>
#include <string>

#include "LayoutFile.h"

namespace {

using namespace lit::editor;

EnvironmentLookup environment(std::map<std::string, std::string> values) {
    return [values = std::move(values)](const char* name) -> const char* {
        const auto found = values.find(name);
        return found == values.end() ? nullptr : found->second.c_str();
    };
}

// The user's config folder, as XDG says; tests and scripted runs name their own file or none.
TEST(LayoutFile, LivesInTheUsersConfigFolder) {
    EXPECT_EQ(layoutFilePath(false, environment({{"HOME", "/home/ann"}})), "/home/ann/.config/lit/imgui.ini");
    EXPECT_EQ(layoutFilePath(false, environment({{"HOME", "/home/ann"}, {"XDG_CONFIG_HOME", "/cfg"}})),
              "/cfg/lit/imgui.ini");
    // A relative XDG_CONFIG_HOME is invalid (XDG Base Directory) and ignored.
    EXPECT_EQ(layoutFilePath(false, environment({{"HOME", "/home/ann"}, {"XDG_CONFIG_HOME", "cfg"}})),
              "/home/ann/.config/lit/imgui.ini");
    EXPECT_EQ(layoutFilePath(false, environment({})), std::nullopt);
    EXPECT_EQ(layoutFilePath(true, environment({{"HOME", "/home/ann"}})), std::nullopt);
    EXPECT_EQ(layoutFilePath(true, environment({{"HOME", "/home/ann"}, {"LIT_EDITOR_LAYOUT", "/tmp/l.ini"}})),
              "/tmp/l.ini");
    EXPECT_EQ(layoutFilePath(false, environment({{"HOME", "/home/ann"}, {"LIT_EDITOR_LAYOUT", ""}})), std::nullopt);
}

TEST(LayoutFile, SectionRoundTrips) {
    PanelVisibility panels;
    panels.statsDetails = true;
    panels.legend = false;
    panels.log = false;
    const std::string text = layoutSectionText(panels, {1280.0f, 720.0f});
    PanelVisibility read;
    glm::vec2 display{0.0f};
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        EXPECT_TRUE(readLayoutLine(text.substr(start, end - start), read, display)) << text.substr(start, end - start);
        start = end + 1;
    }
    EXPECT_EQ(read, panels);
    EXPECT_EQ(display, glm::vec2(1280.0f, 720.0f));
    EXPECT_FALSE(readLayoutLine("panel.sidebar=1", read, display));
    EXPECT_FALSE(readLayoutLine("panel.log=yes", read, display));
    EXPECT_FALSE(readLayoutLine("display=wide", read, display));
}

}  // namespace
