#pragma once
// lit-render's load progress on stderr, so a long load (a large scene's parse, textures and upload)
// does not look like a hang, as a pure function of the loader's reports and the seconds since the
// load began, so tests/unit/test_load_progress_lines.cpp can check it without a slow load: silent
// for the first second (a short load prints nothing), then "loading: STAGE DONE/TOTAL, T s" when
// the stage changes, a stage ends, or a second has passed since the last line.

#include "scene/GltfLoader.h"

#include <cstdio>
#include <optional>
#include <string>

namespace lit::cli {

class LoadProgressLines {
public:
    static constexpr double kQuietSeconds = 1.0;  // loads shorter than this print nothing
    static constexpr double kEverySeconds = 1.0;  // at most one line a second within a stage

    // The line to print for this report, if any.
    std::optional<std::string> operator()(const LoadProgress& p, double elapsedSeconds) {
        const bool newStage = p.stage != stage_;
        stage_ = p.stage;
        const bool stageEnds = p.done >= p.total;
        if (elapsedSeconds < kQuietSeconds || (!newStage && !stageEnds && elapsedSeconds - lastLine_ < kEverySeconds))
            return std::nullopt;
        lastLine_ = elapsedSeconds;
        char line[256];
        std::snprintf(line, sizeof line, "loading: %s %d/%d, %.1f s", p.stage.c_str(), p.done, p.total, elapsedSeconds);
        return std::string(line);
    }

private:
    std::string stage_;
    double lastLine_ = -1.0;
};

}  // namespace lit::cli
