#pragma once
// The performance overlay: FPS, a frame-time graph of the last few seconds, GPU time per pass as
// a stacked bar and a table, CPU frame time, draw calls, triangles, culling and voxel memory.
// Drawn semi-transparent in the viewport's corner so it reads over any scene.

#include <glm/glm.hpp>
#include <string>

#include "FrameTimer.h"
#include "Profiler.h"
#include "Renderer.h"
#include "gi/VoxelVolume.h"
#include "panels/Layout.h"

namespace lit::editor {

// `voxels`: the renderer's voxel volume (null before GI has run), whose per-texture memory
// report is the tooltip of the voxel memory line. `renderScale`: the viewport's render scale this
// frame (lowered while the camera moves, ViewportSettings::interactiveFpsTarget).
void drawStatsOverlay(const FrameTimer& timer, const Profiler& profiler, const FrameStats& stats, glm::ivec2 renderSize,
                      ImFont* monoFont, const Placement& placement, bool* open, const VoxelVolume* voxels = nullptr,
                      float renderScale = 1.0f);

// The colour a pass has in the stacked bar and the table: fixed per pass name, so a pass keeps
// its colour when others appear or vanish.
ImU32 passColor(const std::string& passName);

}  // namespace lit::editor
