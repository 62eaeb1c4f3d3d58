#pragma once
// The still: the chosen camera's view rendered until it has converged (or --frames, or --bench
// frames with their timings and --bench-gi-updates after them), then written as --out/--hdr and
// compared with --compare's reference.

#include "RunContext.h"

namespace lit {
struct Scene;
}

namespace lit::cli {

// Returns the exit status. `scene` is not const: --bench-gi-updates edits a light.
int runStill(const RunContext& run, Scene& scene, int cameraIndex, const GlRun& gl);

}  // namespace lit::cli
