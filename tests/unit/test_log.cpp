// Log folding: a message repeated back to back (numbers aside) is one entry with a count, and
// the sink hears the run once at its start and once at its end.
#include <gtest/gtest.h>

#include "Log.h"

namespace {

using namespace lit;

TEST(Log, RepeatsDifferingOnlyInNumbersFoldIntoOneEntry) {
    Log log;
    std::vector<LogMessage> heard;
    log.setSink([&heard](const LogMessage& m) { heard.push_back(m); });
    log.info("opened scene");
    // A line repeated every frame with other numbers (as a gizmo drag re-voxelizes).
    for (int frame = 0; frame < 50; ++frame)
        log.info("re-voxelized 64³ (geometry changed): voxelize " + std::to_string(1.5 + frame) + " ms",
                 Fold::IgnoringNumbers);
    const std::vector<LogMessage> recent = log.recent();
    ASSERT_EQ(recent.size(), 2u);
    EXPECT_EQ(recent[1].repeats, 50);
    EXPECT_EQ(recent[1].text, "re-voxelized 64³ (geometry changed): voxelize 50.500000 ms");  // the newest
    EXPECT_EQ(heard.size(), 2u);  // the first of the run only, so far
    log.warning("something else");
    ASSERT_EQ(heard.size(), 4u);  // the end of the run (with its count), then the new message
    EXPECT_EQ(heard[2].repeats, 50);
    EXPECT_EQ(heard[3].text, "something else");
    EXPECT_EQ(log.countAtLeast(LogLevel::Info), 52u);  // every write counts
    EXPECT_EQ(log.countAtLeast(LogLevel::Warning), 1u);
}

TEST(Log, DifferentTextsOrLevelsDoNotFold) {
    Log log;
    log.setSink([](const LogMessage&) {});
    log.info("loading a.gltf");
    log.info("loading b.gltf");
    log.warning("loading b.gltf");
    log.info("voxelize 3 ms", Fold::IgnoringNumbers);
    log.info("voxelize 3 ms, inject 2 ms", Fold::IgnoringNumbers);
    // Numbers count unless the writer asked otherwise: a loader's per-image warnings stay apart.
    log.warning("image 4 does not decode");
    log.warning("image 9 does not decode");
    EXPECT_EQ(log.recent().size(), 7u);
    // The very same text folds whatever the writer asked.
    log.warning("image 9 does not decode");
    EXPECT_EQ(log.recent().size(), 7u);
    EXPECT_EQ(log.recent().back().repeats, 2);
    EXPECT_TRUE(sameButNumbers("a 1.5 b 20", "a 3 b 4.25"));
    EXPECT_FALSE(sameButNumbers("a 1 b", "a 1 c"));
    EXPECT_FALSE(sameButNumbers("a 1", "a 1 b"));
}

}  // namespace
