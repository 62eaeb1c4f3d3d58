#pragma once
// The stages of opening a scene as the editor's progress window shows them: the loader's own
// (GltfLoader.h LoadProgress: "file", "meshes", "images", "scene") and the editor's GPU upload
// ("upload", Renderer::setScene on the main thread). Window-free (lit_editor_core).
//
// The overall bar weighs each stage by a typical share of the load time (measured on Sponza:
// decoding images and building meshes dominate, the upload is a few tenths) and stays below
// kLoadBarCap until the document is in, so it never shows 100 % while work remains.

#include <array>
#include <string_view>

#include "scene/GltfLoader.h"

namespace lit::editor {

struct LoadStage {
    const char* name;   // as LoadProgress::stage says it
    const char* label;  // as the window shows it
    float weight;       // share of the overall bar
};
inline constexpr std::array<LoadStage, 5> kLoadStages{{
    {"file", "Parse file", 0.10f},
    {"meshes", "Meshes", 0.30f},
    {"images", "Textures", 0.40f},
    {"scene", "Scene", 0.05f},
    {"upload", "Upload to GPU", 0.15f},
}};
inline constexpr float kLoadBarCap = 0.99f;

// The index of `stage` in kLoadStages, or -1 (before the first report).
int loadStageIndex(std::string_view stage);
// How far each stage is (0..1): stages before the current one 1, after it 0.
std::array<float, kLoadStages.size()> loadStageFractions(const LoadProgress& progress);
// The overall fraction, 0..kLoadBarCap, never decreasing as the loader moves on.
float overallLoadFraction(const LoadProgress& progress);

}  // namespace lit::editor
