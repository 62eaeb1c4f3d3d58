#include "FrameLog.h"

#include <cstdio>
#include <sstream>

#include "io/AtomicFile.h"

namespace lit::editor {

std::string FrameLog::csv(double endSeconds) const {
    std::ostringstream out;
    out << "frame,start_s,duration_ms,render_width,render_height,render_scale,camera_moved,refined_voxels,rendered,"
           "playhead_s,playing,camera_x,camera_y,camera_z,selected_node,gi_only,gi_update_done\n";
    char line[256];
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        const FrameLogRow& row = rows_[i];
        const double next = i + 1 < rows_.size() ? rows_[i + 1].start : endSeconds;
        std::snprintf(line, sizeof line, "%zu,%.4f,%.2f,%d,%d,%.2f,%d,%u,%d,%.4f,%d,%.4f,%.4f,%.4f,%d,%d,%.3f\n", i,
                      row.start - rows_.front().start, (next - row.start) * 1000.0, row.renderSize.x, row.renderSize.y,
                      row.renderScale, row.cameraMoved ? 1 : 0, static_cast<unsigned>(row.refinedVoxels),
                      row.rendered ? 1 : 0, row.playhead, row.playing ? 1 : 0, static_cast<double>(row.camera.x),
                      static_cast<double>(row.camera.y), static_cast<double>(row.camera.z), row.selectedNode, row.giOnly ? 1 : 0,
                      static_cast<double>(row.giUpdateDone));
        out << line;
    }
    return out.str();
}

void FrameLog::write(const std::filesystem::path& file, double endSeconds) const {
    writeFileAtomically(file, csv(endSeconds));
}

}  // namespace lit::editor
