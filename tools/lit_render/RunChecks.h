#pragma once
// Checks made before anything is rendered, so a run that cannot finish fails at once with exit 2
// (UsageError) instead of after minutes of work: the output folders can be written, and the size
// fits this GL and this machine's memory.

#include <filesystem>

#include "Options.h"

namespace lit::cli {

// Sizes checked against this GL's limits and memory (needs a current GL context).
// $LIT_MAX_RENDER_MB caps the memory further (a shared machine, a CI runner).
void checkRenderLimits(const RenderSettings& settings);

// The folder of `file` is created, and a file created and removed in it; `what` names the file
// in the message ("the output").
void checkWritableFolder(const std::filesystem::path& file, const char* what);

// checkWritableFolder for every file and folder the options write.
void checkOutputFolders(const Options& options);

}  // namespace lit::cli
