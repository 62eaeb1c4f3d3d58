#pragma once
// The still: the chosen camera's view rendered until it has converged (or --frames, or --bench
// frames with their timings and --bench-gi-updates after them), then written as --out/--hdr and
// compared with --compare's reference.

#include "RunContext.h"

namespace lit {
struct Scene;
struct CameraView;
}

namespace lit::cli {

// Returns the exit status. `scene` is not const: --bench-gi-updates edits a light. `camera`: the
// chosen scene camera's view, or the camera path's at --time.
int runStill(const RunContext& run, Scene& scene, const CameraView& camera, const GlRun& gl);

}  // namespace lit::cli
