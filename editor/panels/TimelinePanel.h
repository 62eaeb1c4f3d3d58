#pragma once
// The camera path's timeline: keys as markers on a time ruler, a playhead to scrub, play/pause,
// loop and speed, and the selected key's values. The scene's node animations play on the same
// clock: the ruler covers the longer of the path and the animations, and the playhead poses the
// animated nodes (the App applies them each frame). Every change to the path is one undo step on
// the Document (a key drag too); scrubbing and playing only move the playhead and, when
// "look through" is on, the fly camera.

#include <optional>
#include <string>

#include "Document.h"
#include "PathEditing.h"
#include "panels/Layout.h"
#include "scene/CameraView.h"

namespace lit::editor {

class TimelinePanel {
public:
    void draw(Document& doc, PathPlayback& playback, FlyCamera& camera, const Placement& placement, bool* open);

    // The seconds shown across the ruler.
    struct TimeRange {
        double start = 0.0, end = 1.0;
        float toX(double t, float x0, float width) const {
            return x0 + static_cast<float>((t - start) / (end - start)) * width;
        }
        double toTime(float x, float x0, float width) const { return start + (x - x0) / width * (end - start); }
    };

private:
    void drawRuler(Document& doc, PathPlayback& playback, FlyCamera& camera);

    int draggedKey_ = -1;  // key being dragged on the ruler, -1 when none
    std::optional<TimeRange> heldRange_;  // the ruler's scale while the mouse holds it
    std::string chooseError_;  // why the last animation switch failed, shown under the combo
};

}  // namespace lit::editor
