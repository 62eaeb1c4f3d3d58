#pragma once
// --reference: the still path-traced on the CPU (renderer/reference/, Embree and TBB), written as
// the same --out/--hdr/--view images as the rasterizer writes, with progress and rays/s on stderr.
// Ctrl+C stops it after the tiles in flight and writes the image so far.

#include "RunContext.h"

namespace lit {
struct Scene;
}

namespace lit::cli {

// Returns the exit status: 0, or 130 when Ctrl+C stopped the render (the image so far was written).
int runReference(const RunContext& run, const Scene& scene, int cameraIndex);

}  // namespace lit::cli
