#pragma once
// The name the Save As dialog offers. Never the open file itself: Enter in the dialog would
// overwrite it without a second look (and the built-in Cornell box ships with the editor).
// Offered instead, as a file manager names a copy:
//   a document with a file:    "<stem>-copy<ext>" beside it, then "<stem>-copy-2<ext>", "-copy-3"
//                              ... while the name exists; a stem that already ends in "-copy" or
//                              "-copy-N" counts on from it rather than growing "-copy-copy";
//   the built-in scene:        the same name in the working directory, not in the install's
//                              assets folder;
//   a document without a file: "untitled.gltf", then "untitled-2.gltf" ... in the working directory.
// <ext> is the file's .gltf or .glb (anything else: .gltf). Window-free (lit_editor_core).

#include <filesystem>
#include <functional>

namespace lit::editor {

using FileExists = std::function<bool(const std::filesystem::path&)>;

// `current`: the document's file (empty: none); `builtInFolder`: where the built-in scenes live
// (lit::defaultAssetRoot()); `exists`: whether a name is taken.
std::filesystem::path suggestSaveAsName(const std::filesystem::path& current,
                                        const std::filesystem::path& builtInFolder, const FileExists& exists);

// The same on this machine: the renderer's asset folder and the file system.
std::filesystem::path suggestSaveAsName(const std::filesystem::path& current);

}  // namespace lit::editor
