#pragma once
// --compare REF.hdr [--difference FILE.png [--max-error X]]: the rendered image's figures against a
// reference image of the same size (typically `--reference --hdr`), and the editor's Difference
// view as a PNG.

#include <vector>

#include "Options.h"
#include "image/ImageIO.h"

namespace lit::cli {

// The reference image --compare names, read before a render that may take minutes so a wrong
// name or size fails at once. Throws UsageError when it cannot be read or its size is not the
// render's.
HdrImage readCompareReference(const Options& options, const RenderSettings& settings);

// Prints mean luminances, their ratio and the relative RMSE; writes --difference when given.
// `rgb`: the render's linear image, the size of `truth`.
void compareWithReference(const Options& options, const HdrImage& truth, const std::vector<float>& rgb);

}  // namespace lit::cli
