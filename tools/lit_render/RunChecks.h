#pragma once
// Checks made before anything is rendered, so a run that cannot finish fails at once with exit 2
// (UsageError) instead of after minutes of work: the output folders can be written, and the size
// fits this GL and this machine's memory.

#include <filesystem>

#include "Options.h"
#include "scene/Scene.h"
#include "scene/SceneMemory.h"

namespace lit::cli {

// Sizes checked against this GL's limits, and what `scene` and the render need in all
// (estimateSceneMemory, the loader's accounting) against renderMemoryLimit() and this machine's
// available memory (needs a current GL context).
void checkRenderLimits(const RenderSettings& settings, const Scene& scene);

// The folder of `file` is created, and a file created and removed in it; `what` names the file
// in the message ("the output").
void checkWritableFolder(const std::filesystem::path& file, const char* what);

// checkWritableFolder for every file and folder the options write.
void checkOutputFolders(const Options& options);

}  // namespace lit::cli
