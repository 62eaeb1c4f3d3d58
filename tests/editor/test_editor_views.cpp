#include <gtest/gtest.h>

#include <set>

#include "EditorViews.h"
#include "RenderSettings.h"
#include "Script.h"

namespace {

using namespace lit;
using namespace lit::editor;

TEST(EditorViews, EveryRendererViewIsInTheMenuOnceWithItsOwnKey) {
    // Every View the renderer has (the enum is contiguous from Final to VoxelLevels).
    for (int v = static_cast<int>(View::Final); v <= static_cast<int>(View::VoxelLevels); ++v) {
        const std::string_view name = toString(static_cast<View>(v));
        EXPECT_NE(findEditorView(name), nullptr) << name;
    }
    EXPECT_NE(findEditorView(kConeDirectionsView), nullptr);
    std::set<std::pair<int, bool>> keys;
    std::set<std::string_view> names;
    for (const EditorView& view : editorViews()) {
        EXPECT_TRUE(keys.insert({view.digit, view.shift}).second) << view.name;
        EXPECT_TRUE(names.insert(view.name).second) << view.name;
        EXPECT_EQ(editorViewForKey(view.digit, view.shift), &view);
        EXPECT_TRUE(parseView(view.name) || view.name == kConeDirectionsView) << view.name;
    }
    EXPECT_EQ(editorViewForKey(9, true), nullptr);
}

}  // namespace
