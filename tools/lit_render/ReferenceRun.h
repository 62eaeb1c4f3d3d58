#pragma once
// --reference: the still path-traced on the CPU (renderer/reference/, Embree and TBB), written as
// the same --out/--hdr/--view images as the rasterizer writes, with progress and rays/s on stderr.
// Ctrl+C stops it after the tiles in flight and writes the image so far.

#include "RunContext.h"
#include "animation/CameraPath.h"

namespace lit {
struct Scene;
struct CameraView;
}

namespace lit::cli {

// Returns the exit status: 0, or 130 when Ctrl+C stopped the render (the image so far was written).
// `scene` as posed at --time (its world transforms are what the tracer builds from); `camera`
// the still's view, as the rasterized still's.
int runReference(const RunContext& run, const Scene& scene, const CameraView& camera);

// --reference --path --frames-out DIR: every frame of `path` (PathRun's pathFrameTimes), the
// scene's node animations posed at its time, path-traced with --spp samples and written as
// DIR/frame_NNNNN.png like the rasterized frames. Returns 0, or 130 when Ctrl+C stopped it (the
// frame in progress is written with its samples so far).
int runReferencePath(const RunContext& run, const CameraPath& path, Scene& scene);

}  // namespace lit::cli
