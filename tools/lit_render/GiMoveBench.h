#pragma once
// --bench-gi-moves: moving one object (the smallest mesh node) with the voxelization of its
// changed boxes (GiSettings::voxelizeChangesOnly) against the same move with the whole volume
// voxelized again, interleaved. Each move's update is let finish (over frames with
// --gi-update-per-frame) before the next: printed are the edit frame's GI passes and the GI passes
// of every frame up to the final light, GPU ms from the profiler.

#include "gi/GiBudget.h"

namespace lit {
class Renderer;
struct CameraView;
struct RenderSettings;
struct Scene;
}  // namespace lit

namespace lit::cli {

// Prints one line per round and the median ratios. The node moves by a tenth of its size along x
// and back in turn, so the scene ends as it began.
void benchGiMoves(int rounds, Scene& scene, const CameraView& camera, Renderer& renderer,
                  const RenderSettings& settings, const GiBudget& budget);

}  // namespace lit::cli
