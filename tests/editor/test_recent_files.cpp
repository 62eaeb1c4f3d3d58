#include <gtest/gtest.h>

#include "RecentFiles.h"

namespace {

using lit::editor::RecentFiles;

TEST(EditorRecentFiles, MostRecentFirstWithoutDuplicates) {
    RecentFiles recent;
    recent.add("/scenes/a.gltf");
    recent.add("/scenes/b.gltf");
    recent.add("/scenes/x/../a.gltf");  // the same file as the first
    ASSERT_EQ(recent.paths().size(), 2u);
    EXPECT_EQ(recent.paths()[0], "/scenes/a.gltf");
    EXPECT_EQ(recent.paths()[1], "/scenes/b.gltf");
}

TEST(EditorRecentFiles, OldestDropsOffWhenFull) {
    RecentFiles recent(2);
    recent.add("/a.gltf");
    recent.add("/b.gltf");
    recent.add("/c.gltf");
    ASSERT_EQ(recent.paths().size(), 2u);
    EXPECT_EQ(recent.paths()[0], "/c.gltf");
    EXPECT_EQ(recent.paths()[1], "/b.gltf");
}

TEST(EditorRecentFiles, RelativePathsAreStoredAbsolute) {
    RecentFiles recent;
    recent.add("relative.gltf");
    ASSERT_EQ(recent.paths().size(), 1u);
    EXPECT_TRUE(recent.paths()[0].is_absolute());
    recent.remove("relative.gltf");
    EXPECT_TRUE(recent.empty());
}

}  // namespace
