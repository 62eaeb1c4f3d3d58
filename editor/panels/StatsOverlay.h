#pragma once
// The performance overlay, semi-transparent in the viewport's top-left corner. By default two
// lines: FPS, frame and GPU time, whether the 3D image was rendered or reused and how far the GI
// is. Its "+" button (or "panel stats-details on") adds a frame-time graph of the last few
// seconds, GPU time per pass as a stacked bar and a table, CPU frame time, draw calls, triangles,
// culling and voxel memory; the choice is kept with the layout (LayoutFile.h).

#include <glm/glm.hpp>
#include <string>
#include <string_view>

#include "FrameTimer.h"
#include "Profiler.h"
#include "Renderer.h"
#include "gi/VoxelVolume.h"
#include "panels/Layout.h"

namespace lit::editor {

// The viewport's last frame as the overlay reports it: with redraw on demand (ViewportRedraw.h)
// most frames show the last rendered image again, and the stats and pass timings are that
// image's.
struct ViewportFrameInfo {
    float renderScale = 1.0f;    // lowered while the camera moves (ViewportSettings::interactiveFpsTarget)
    bool rendered = true;        // the 3D image was rendered, else the last one was shown again
    bool giOnly = false;         // not rendered, but the GI worked (Renderer::advanceGi)
    std::string_view reason;     // why it was rendered (redrawReasonName)
    int framesReused = 0;        // frames in a row that showed the last rendered image again
    double renderFrameMs = 0.0;  // how long the last frame that rendered took (update, render, present)
    double giBudgetMs = 0.0;     // the GI's time budget a frame (ViewportSettings::giMillisecondsPerFrame; 0: none)
};

// `details`: the long form (toggled by the overlay's button); `voxels`: the renderer's voxel
// volume (null before GI has run), whose per-texture memory report is the tooltip of the voxel
// memory line. Returns where the overlay was drawn (x, y, width, height; zero when not).
glm::vec4 drawStatsOverlay(const FrameTimer& timer, const Profiler& profiler, const FrameStats& stats,
                           glm::ivec2 renderSize, ImFont* monoFont, const Placement& placement, bool* open,
                           bool* details, const VoxelVolume* voxels, const ViewportFrameInfo& frame);

// The colour a pass has in the stacked bar and the table: fixed per pass name, so a pass keeps
// its colour when others appear or vanish.
ImU32 passColor(const std::string& passName);

}  // namespace lit::editor
