#pragma once
// Times the radiance volume's mip chains like for like, in one run with the runs interleaved so
// that all see the same machine load: the isotropic compute chain against glGenerateTextureMipmap
// (a plain average: a different, cheaper reduction, kept as a yardstick) over the whole grid; the
// isotropic chain over the occupied parents; and, with anisotropic voxels, the six directional
// chains on their own (whole grid and occupied parents). lit-render --bench prints them.

#include <vector>

namespace lit {

class MipmapPass;
class VoxelVolume;

struct MipmapTimings {
    int resolution = 0;   // voxels per side of level 0
    bool rgba8 = false;   // radiance format: RGBA8 (true) or RGBA16F
    int repetitions = 0;  // timed runs of each
    // The isotropic chain over the whole grid (MipmapPass::execute) and glGenerateTextureMipmap,
    // GPU time (ms). Process CPU time (ms, all threads), median: on llvmpipe the "GPU" is the CPU,
    // so this is the work done, which stays meaningful when other processes compete for the cores
    // and wall-clock times do not; on a GPU it is only the driver's submission cost.
    double computeMinMs = 0.0, computeMedianMs = 0.0, computeCpuMedianMs = 0.0;
    double generateMinMs = 0.0, generateMedianMs = 0.0, generateCpuMedianMs = 0.0;
    // The isotropic chain over the occupied parents, when the volume's parent lists were valid
    // (0 otherwise).
    double occupiedMinMs = 0.0, occupiedMedianMs = 0.0, occupiedCpuMedianMs = 0.0;
    // The six directional chains alone (MipmapPass::executeDirectional), timed when `anisotropic`.
    bool anisotropic = false;
    double directionalMinMs = 0.0, directionalMedianMs = 0.0;
    double directionalOccupiedMinMs = 0.0, directionalOccupiedMedianMs = 0.0;
    // GPU ms of each timed run, in order (run i of each ran back to back: one interleaved round).
    std::vector<double> computeRunsMs, occupiedRunsMs, directionalRunsMs, directionalOccupiedRunsMs;

    // computeMinMs / occupiedMinMs: > 1 means building over the occupied parents is faster.
    double occupiedSpeedup() const { return occupiedMinMs > 0.0 ? computeMinMs / occupiedMinMs : 0.0; }
    // generateMinMs / computeMinMs: > 1 means the compute chain is faster than
    // glGenerateTextureMipmap at building the same one chain. Minimums, because on a shared machine
    // the medians swing by 2× with the load while the minimums stay put.
    double speedup() const { return computeMinMs > 0.0 ? generateMinMs / computeMinMs : 0.0; }
};

// Runs each method once untimed (shader compilation, first-use allocation), then `repetitions`
// (clamped to 1..100) timed runs of each, alternating. GPU time comes from GL_TIMESTAMP query
// pairs around each run, with glFinish between runs (llvmpipe reports 0 for GL_TIME_ELAPSED around
// compute dispatches). glGenerateTextureMipmap overwrites the levels with plain averages; the
// chains (with the directional ones when `anisotropic`) are rebuilt at the end, so the volume
// ends as MipmapPass::execute leaves it. Level 0 is not changed.
MipmapTimings benchmarkMipmaps(MipmapPass& pass, VoxelVolume& volume, int repetitions, bool anisotropic = false);

}  // namespace lit
