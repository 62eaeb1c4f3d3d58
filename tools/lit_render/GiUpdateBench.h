#pragma once
// --bench-gi-updates: a light edit (re-inject + mipmaps; the voxels stay) against a full
// re-voxelization (voxelize + inject + mipmaps), interleaved, GPU times from the profiler; both
// with the bounce passes and the cached GI mode's voxel irradiance pass and filter that follow
// every edit (the whole list in the edit's frame unless --gi-update-per-frame; else only
// that frame's share). Both also re-render the shadow maps (the light or geometry changed); that
// is printed separately.

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

}  // namespace lit::cli
