#include <gtest/gtest.h>

#include "LoadStages.h"

namespace {

using namespace lit::editor;
using lit::LoadProgress;

TEST(LoadStages, WeightsSumToOne) {
    float sum = 0.0f;
    for (const LoadStage& stage : kLoadStages) sum += stage.weight;
    EXPECT_NEAR(sum, 1.0f, 1e-6f);
}

TEST(LoadStages, OverallNeverDecreasesAndStaysBelowTheCapUntilTheEnd) {
    // Every report a load of 3 meshes and 4 images makes, in order, then the upload.
    std::vector<LoadProgress> reports{{"file", 0, 1}, {"file", 1, 1}};
    for (int i = 0; i <= 3; ++i) reports.push_back({"meshes", i, 3});
    for (int i = 0; i <= 4; ++i) reports.push_back({"images", i, 4});
    reports.push_back({"scene", 0, 1});
    reports.push_back({"scene", 1, 1});
    reports.push_back({"upload", 0, 1});
    reports.push_back({"upload", 1, 1});
    float previous = -1.0f;
    for (const LoadProgress& p : reports) {
        const float f = overallLoadFraction(p);
        EXPECT_GE(f, previous) << p.stage << " " << p.done;
        EXPECT_LE(f, kLoadBarCap) << p.stage << " " << p.done;
        previous = f;
    }
    // Before the upload the bar is well short of full: the upload's share is still to come.
    EXPECT_LT(overallLoadFraction({"scene", 1, 1}), 0.9f);
    EXPECT_EQ(overallLoadFraction({}), 0.0f);
}

TEST(LoadStages, StageFractions) {
    const auto f = loadStageFractions({"images", 1, 4});
    EXPECT_EQ(f[0], 1.0f);
    EXPECT_EQ(f[1], 1.0f);
    EXPECT_EQ(f[2], 0.25f);
    EXPECT_EQ(f[3], 0.0f);
    EXPECT_EQ(loadStageFractions({"meshes", 0, 0})[1], 1.0f);  // nothing to do: done
    EXPECT_EQ(loadStageIndex("upload"), 4);
    EXPECT_EQ(loadStageIndex("bogus"), -1);
}

}  // namespace
