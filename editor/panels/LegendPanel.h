#pragma once
// The debug view's legend: a box in the bottom-left corner of the free viewport area (the
// viewport bar holds the other corner) that says what the view shows (DebugViewLegend.h), with
// its colour ramps and swatches, and, for the voxel views, the controls of the mip, the channel
// and the slice next to the picture they change.

#include <glm/glm.hpp>

#include "DebugViewLegend.h"
#include "RenderSettings.h"

namespace lit::editor {

struct LegendBox {
    glm::vec4 rect{0.0f};  // where it was drawn (x, y, width, height; ImGui units), zero when not
    bool changed = false;  // a voxel control changed `debug`
};

// `area`: the free viewport area (ViewportArea.h); `mipCount`: the voxel volume's levels (0: none
// yet); `open`: cleared by the box's close button.
LegendBox drawLegend(const ViewLegend& legend, DebugViewSettings& debug, int mipCount, glm::vec4 area, bool* open);

}  // namespace lit::editor
