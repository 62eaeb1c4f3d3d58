#include "Compare.h"

#include <cstdio>
#include <exception>
#include <string>

#include "reference/DifferenceImage.h"

namespace lit::cli {

HdrImage readCompareReference(const Options& options, const RenderSettings& settings) {
    HdrImage truth;
    try {
        truth = readHdr(options.compare);
    } catch (const std::exception& e) {
        throw UsageError(std::string("--compare: ") + e.what());
    }
    if (truth.width != settings.output.width || truth.height != settings.output.height)
        throw UsageError(options.compare.string() + " is " + std::to_string(truth.width) + "x" +
                         std::to_string(truth.height) + ", the image will be " + std::to_string(settings.output.width) +
                         "x" + std::to_string(settings.output.height) + ": render both at one --size");
    return truth;
}

void compareWithReference(const Options& options, const HdrImage& truth, const std::vector<float>& rgb) {
    const lit::reference::ImageComparison figures = lit::reference::compareImages(rgb, truth.rgb);
    std::printf(
        "compare with %s: mean luminance %.5g against %.5g (ratio %.3f), RMSE %.1f %% of the reference's mean\n",
        options.compare.string().c_str(), figures.testMean, figures.referenceMean, figures.meanRatio(),
        100.0 * figures.relativeRmse);
    if (options.difference.empty()) return;
    const float maxError = options.maxError.value_or(kDefaultMaxError);
    // The ramp is display colour: encoded as sRGB, as the editor's blit does.
    lit::writePng(
        options.difference, truth.width, truth.height,
        lit::reference::displayColoursToRgba8(lit::reference::relativeErrorColours(rgb, truth.rgb, maxError)));
    std::printf("wrote %s (relative error, ramp ends at ±%.0f %%)\n", options.difference.string().c_str(),
                100.0 * maxError);
}

}  // namespace lit::cli
