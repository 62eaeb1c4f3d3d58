#pragma once
// --bench-gi-updates: a light edit (re-inject + mipmaps; the voxels stay) against a full
// re-voxelization (voxelize + inject + mipmaps), interleaved, GPU times from the profiler; both
// with the bounce passes and the cached GI mode's voxel irradiance pass and filter that follow
// every edit (the whole list in the edit's frame unless --gi-update-per-frame; else only
// that frame's share). Both also re-render the shadow maps (the light or geometry changed); that
// is printed separately.
//
// --bench-gi-moves (GiMoveBench.cpp): moving one object (the scene's node animations a frame on,
// else the smallest mesh node) with only its changed boxes voxelized again
// (GiSettings::voxelizeChangesOnly) against the same move with the whole volume voxelized,
// interleaved. Each move's update is let finish (over frames with --gi-update-per-frame) before
// the next: printed are the edit frame's GI passes and those of every frame to the final light.
// Then playback: 30 moves in a row, one a frame, in each mode: how many frames' pixels gather the
// GI of their own poses, and the GI passes a frame.

#include "gi/GiBudget.h"

namespace lit {
class Renderer;
struct CameraView;
struct RenderSettings;
struct Scene;
}  // namespace lit

namespace lit::cli {

// Prints one line per round and the median ratio. Runs after the still's frames, from the GI
// state they left; `scene`'s first light is nudged and restored in turn.
void benchGiUpdates(int rounds, Scene& scene, const CameraView& camera, Renderer& renderer,
                    const RenderSettings& settings, const GiBudget& budget);
// One line per round, the median ratios and the two playbacks; a moved node moves by a tenth of
// its size along x and back in turn. The scene's nodes end as they began.
void benchGiMoves(int rounds, Scene& scene, const CameraView& camera, Renderer& renderer,
                  const RenderSettings& settings, const GiBudget& budget);

}  // namespace lit::cli
