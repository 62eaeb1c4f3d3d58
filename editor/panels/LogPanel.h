#pragma once
// The renderer's log (Log::recent()), coloured by level, with a level and text filter.

#include <imgui.h>

#include "Log.h"
#include "panels/Layout.h"

namespace lit::editor {

class LogPanel {
public:
    // Messages are drawn in `monoFont`.
    void draw(const Log& log, ImFont* monoFont, const Placement& placement, bool* open);

private:
    bool showInfo_ = true;
    bool showWarnings_ = true;
    bool showErrors_ = true;
    bool autoScroll_ = true;
    ImGuiTextFilter filter_;
};

}  // namespace lit::editor
