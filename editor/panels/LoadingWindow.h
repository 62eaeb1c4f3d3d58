#pragma once
// The progress of a scene loading in the background, centred over the window: each stage with
// its own bar (done, running, waiting), then the whole load weighted by stage (LoadStages.h).

#include <filesystem>

#include "scene/GltfLoader.h"

namespace lit::editor {

// `seconds`: how long the load has been running.
void drawLoadingWindow(const std::filesystem::path& file, const LoadProgress& progress, double seconds);

}  // namespace lit::editor
