#pragma once
// --frame-log FILE: one row per frame of the editor's loop (when it began, the render scale and
// size, whether the camera moved, the voxels the GI refined, whether the 3D image was rendered or
// the last one shown again, the camera path's playhead, where the camera was, the active node,
// whether the frame worked on the GI alone and how far the GI update is),
// written as CSV
// when the editor ends. The editor_interactive, editor_camera_path and editor_real_input tests and
// the frame-rate
// measurements (docs/PERFORMANCE.md, "Editor") read it. Window-free (lit_editor_core).

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace lit::editor {

struct FrameLogRow {
    double start = 0.0;  // s, on the editor's steady clock, when the frame began
    float renderScale = 1.0f;
    glm::ivec2 renderSize{0};  // pixels
    bool cameraMoved = false;
    std::uint32_t refinedVoxels = 0;  // FrameStats::refinedVoxels of the frame
    bool rendered = false;            // the 3D image was rendered (redraw on demand: ViewportRedraw.h)
    double playhead = 0.0;            // s, the camera path's playhead (PathPlayback::time)
    bool playing = false;             // the camera path plays
    glm::vec3 camera{0.0f};           // m, the fly camera's position the frame renders from
    int selectedNode = -1;            // the active node (Document::selectedNode), -1: none
    bool giOnly = false;              // the frame advanced the GI without rendering (Renderer::advanceGi)
    float giUpdateDone = 1.0f;        // FrameStats::giUpdateDone after the frame: share of the GI update done
};

class FrameLog {
public:
    void add(const FrameLogRow& row) { rows_.push_back(row); }
    // The row of the frame being rendered (after add).
    FrameLogRow& last() { return rows_.back(); }

    // frame,start_s,duration_ms,render_width,render_height,render_scale,camera_moved,refined_voxels,
    // rendered,playhead_s,playing,camera_x,camera_y,camera_z,selected_node,gi_only,gi_update_done: a frame lasts until the next one begins (the loop's own frame time: update, render,
    // present), the last one until `endSeconds`; start_s counts from the first frame.
    std::string csv(double endSeconds) const;
    // Writes csv() atomically; throws when it cannot.
    void write(const std::filesystem::path& file, double endSeconds) const;

private:
    std::vector<FrameLogRow> rows_;
};

}  // namespace lit::editor
