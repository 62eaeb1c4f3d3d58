#include "LoadStages.h"

#include <algorithm>

namespace lit::editor {

int loadStageIndex(std::string_view stage) {
    for (std::size_t i = 0; i < kLoadStages.size(); ++i)
        if (stage == kLoadStages[i].name) return static_cast<int>(i);
    return -1;
}

std::array<float, kLoadStages.size()> loadStageFractions(const LoadProgress& progress) {
    std::array<float, kLoadStages.size()> fractions{};
    const int current = loadStageIndex(progress.stage);
    for (int i = 0; i < static_cast<int>(kLoadStages.size()); ++i) {
        if (i < current) fractions[static_cast<std::size_t>(i)] = 1.0f;
        else if (i == current)
            // A stage with nothing to do (total 0) is done once it is reported.
            fractions[static_cast<std::size_t>(i)] =
                progress.total > 0 ? std::clamp(static_cast<float>(progress.done) / static_cast<float>(progress.total), 0.0f, 1.0f)
                                   : 1.0f;
    }
    return fractions;
}

float overallLoadFraction(const LoadProgress& progress) {
    const auto fractions = loadStageFractions(progress);
    float sum = 0.0f;
    for (std::size_t i = 0; i < kLoadStages.size(); ++i) sum += kLoadStages[i].weight * fractions[i];
    return std::min(sum, kLoadBarCap);
}

}  // namespace lit::editor
