// Replays the fuzzing corpus through the ordinary loader (not libFuzzer): the seeds must load,
// and every input that ever crashed, hung or exhausted memory under tools/fuzz.sh
// (tests/fuzz/regressions) must give a SceneLoadError or a scene, each within seconds.

#include <gtest/gtest.h>

#include "GltfFuzzInput.h"
#include "TempDir.h"

#include <algorithm>
#include <ctime>
#include <iterator>
#include <vector>

namespace lit {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputsIn(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        if (entry.is_regular_file() && !entry.path().filename().string().starts_with(".")) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::uint8_t> bytesOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(GltfFuzzCorpus, SeedsLoad) {
    lit::testing::TempDir scratch("lit_fuzz_seeds");
    fuzz::prepareScratch(scratch.path(), LIT_SOURCE_DIR);
    const std::vector<fs::path> seeds = inputsIn(fs::path(LIT_SOURCE_DIR) / "tests/fuzz/seeds");
    ASSERT_GE(seeds.size(), 3u);
    for (const fs::path& seed : seeds) {
        const std::vector<std::uint8_t> bytes = bytesOf(seed);
        // The WebP seeds require EXT_texture_webp: a build without libwebp refuses them by name.
        const bool needsWebp = seed.filename().string().find("webp") != std::string::npos;
        if (needsWebp && LIT_HAS_WEBP == 0) {
            EXPECT_NO_THROW(fuzz::loadFuzzInput(bytes.data(), bytes.size(), scratch.path())) << seed;
            continue;
        }
        EXPECT_TRUE(fuzz::loadFuzzInput(bytes.data(), bytes.size(), scratch.path())) << seed;
    }
}

TEST(GltfFuzzCorpus, RegressionsGiveAnErrorOrASceneQuickly) {
    lit::testing::TempDir scratch("lit_fuzz_regressions");
    fuzz::prepareScratch(scratch.path(), LIT_SOURCE_DIR);
    for (const fs::path& input : inputsIn(fs::path(LIT_SOURCE_DIR) / "tests/fuzz/regressions")) {
        const std::vector<std::uint8_t> bytes = bytesOf(input);
        // Processor time (all threads), not wall time: a loaded CI machine must not fail this.
        const std::clock_t start = std::clock();
        EXPECT_NO_THROW(fuzz::loadFuzzInput(bytes.data(), bytes.size(), scratch.path())) << input;
        const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
        // libFuzzer's -timeout in tools/fuzz.sh is 10 s (of an ASan+UBSan build); a replay in the
        // suite's builds (the sanitizer build included) must be far quicker.
        EXPECT_LT(seconds, 10.0) << input << " (processor seconds)";
    }
}

}  // namespace
}  // namespace lit
