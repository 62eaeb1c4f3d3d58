// lit-render's load progress lines (tools/lit_render/LoadProgressLines.h): progress (parse,
// textures, upload) on long loads only. Microseconds.
#include <gtest/gtest.h>

#include "LoadProgressLines.h"

#include <string>
#include <vector>

namespace {

using lit::LoadProgress;
using lit::cli::LoadProgressLines;

// Feeds (report, seconds) pairs and collects the printed lines.
std::vector<std::string> linesFor(const std::vector<std::pair<LoadProgress, double>>& reports) {
    LoadProgressLines lines;
    std::vector<std::string> out;
    for (const auto& [p, t] : reports)
        if (const auto line = lines(p, t)) out.push_back(*line);
    return out;
}

TEST(LoadProgressLines, AShortLoadPrintsNothing) {
    EXPECT_TRUE(linesFor({{{"parse", 0, 1}, 0.0},
                          {{"parse", 1, 1}, 0.1},
                          {{"images", 0, 3}, 0.2},
                          {{"images", 3, 3}, 0.5},
                          {{"upload", 0, 1}, 0.6},
                          {{"upload", 1, 1}, 0.9}})
                    .empty());
}

TEST(LoadProgressLines, ALongLoadNamesEachStageAndItsEndAtMostOnceASecondBetween) {
    const std::vector<std::string> lines = linesFor({{{"parse", 0, 1}, 0.0},
                                                     {{"parse", 1, 1}, 0.4},
                                                     {{"images", 0, 69}, 0.5},
                                                     {{"images", 5, 69}, 1.2},   // first line after the quiet second
                                                     {{"images", 6, 69}, 1.5},   // within the second: silent
                                                     {{"images", 12, 69}, 2.3},  // a second later
                                                     {{"images", 69, 69}, 2.4},  // the stage's end
                                                     {{"upload", 0, 1}, 2.5},    // a new stage
                                                     {{"upload", 1, 1}, 2.6}});
    EXPECT_EQ(lines, (std::vector<std::string>{"loading: images 5/69, 1.2 s", "loading: images 12/69, 2.3 s",
                                               "loading: images 69/69, 2.4 s", "loading: upload 0/1, 2.5 s",
                                               "loading: upload 1/1, 2.6 s"}));
}

}  // namespace
