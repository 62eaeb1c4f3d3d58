#include <gtest/gtest.h>

#include <set>

#include "SaveAsName.h"

namespace {

using namespace lit::editor;
namespace fs = std::filesystem;

FileExists taken(std::set<fs::path> names) {
    return [names = std::move(names)](const fs::path& path) { return names.count(path) > 0; };
}

TEST(SaveAsName, OffersACopyBesideTheFileNeverTheFileItself) {
    const fs::path scene = "/projects/sponza/scene.gltf";
    EXPECT_EQ(suggestSaveAsName(scene, "/opt/lit/assets", taken({scene})), "/projects/sponza/scene-copy.gltf");
    EXPECT_EQ(suggestSaveAsName(scene, "/opt/lit/assets",
                                taken({scene, "/projects/sponza/scene-copy.gltf", "/projects/sponza/scene-copy-2.gltf"})),
              "/projects/sponza/scene-copy-3.gltf");
    // A copy's copy counts on instead of growing "-copy-copy"; .glb stays .glb.
    EXPECT_EQ(suggestSaveAsName("/p/scene-copy.glb", "/opt/lit/assets", taken({"/p/scene-copy.glb"})),
              "/p/scene-copy-2.glb");
    EXPECT_EQ(suggestSaveAsName("/p/scene-copy-7.glb", "/opt/lit/assets",
                                taken({"/p/scene-copy-7.glb", "/p/scene-copy.glb"})),
              "/p/scene-copy-2.glb");
    // "-copyright" is part of the name.
    EXPECT_EQ(suggestSaveAsName("/p/a-copyright.gltf", "", taken({})), "/p/a-copyright-copy.gltf");
}

TEST(SaveAsName, TheBuiltInSceneIsCopiedToTheWorkingDirectory) {
    const fs::path assets = fs::temp_directory_path() / "lit_save_as_name_assets";
    const fs::path builtIn = assets / "cornell_box.gltf";
    const fs::path suggestion = suggestSaveAsName(builtIn, assets, taken({builtIn}));
    EXPECT_EQ(suggestion, "cornell_box-copy.gltf");
    EXPECT_NE(suggestion, builtIn);
    EXPECT_EQ(suggestSaveAsName(builtIn, assets, taken({"cornell_box-copy.gltf"})), "cornell_box-copy-2.gltf");
}

TEST(SaveAsName, ADocumentWithoutAFileIsUntitled) {
    EXPECT_EQ(suggestSaveAsName({}, "/opt/lit/assets", taken({})), "untitled.gltf");
    EXPECT_EQ(suggestSaveAsName({}, "/opt/lit/assets", taken({"untitled.gltf", "untitled-2.gltf"})), "untitled-3.gltf");
}

}  // namespace
