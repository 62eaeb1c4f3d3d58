#pragma once
// Frame statistics in the top left corner of the viewport: frame time and FPS, per-pass GPU
// and CPU times from the Profiler, and what the renderer drew.

#include <glm/glm.hpp>

#include "FrameTimer.h"
#include "Profiler.h"
#include "Renderer.h"
#include "panels/Layout.h"

namespace lit::editor {

// `renderSize`: the renderer's output size in pixels; `monoFont` keeps the columns of numbers
// aligned. `open` is cleared by the close button.
void drawStatsOverlay(const FrameTimer& timer, const Profiler& profiler, const FrameStats& stats, glm::ivec2 renderSize,
                      ImFont* monoFont, const Placement& placement, bool* open);

}  // namespace lit::editor
