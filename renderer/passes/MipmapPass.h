#pragma once
// Mipmap pass: builds the mip chain of the radiance volume with a compute shader
// (shaders/mipmap.comp.glsl). The volume holds premultiplied radiance (rgb = radiance × opacity,
// a = opacity; docs/GI.md), and a parent STACKS its 2×2×2 children along the axis where they are
// most opaque (directional opacity, stored isotropically):
//   per axis, each of the 4 child pairs along it (front c1,a1, back c2,a2) is composited
//     a = 1 − (1 − a1)(1 − a2),   rgb = ((c1 + (1 − a1)·c2) + (c2 + (1 − a2)·c1)) / 2,
//   the 4 pairs are averaged; the parent is the axis with the largest a (exactly tied axes:
//   their colours averaged).
// A one-voxel wall stays (C, 1) at every level instead of fading to 2^-k, so wide cones reading
// coarse levels no longer see through it; empty space stays 0, a uniform region (L, 1) stays
// (L, 1), and rgb/a stays a weighted mean of the children's colours (no dark edges).
// glGenerateTextureMipmap (a plain average) is only a speed reference now.
//
// Every level is rounded to the texture's format before the next is built from it: RGBA8 is
// reduced in exact integer arithmetic on the bytes, RGBA16F in fp32 in a fixed order; the CPU
// reference in tests/gl/test_mipmap.cpp repeats both bit for bit.
//
// How it is tuned (Mesa 22.3 llvmpipe, 2 cores, 256³; the measurements are in MipmapPass.cpp):
// one invocation reduces a whole 2³ (RGBA16F) or 8³ (RGBA8) block of the source level and stores
// every level on the way; no shared memory and no barrier(), which measured 1.3-3× slower there.

#include "passes/Pass.h"

#include <filesystem>
#include <vector>

namespace lit {

class VoxelVolume;

class MipmapPass : public Pass {
public:
    // Builds the RGBA8 and RGBA16F programs; throws gl::GlError if they do not compile.
    explicit MipmapPass(const std::filesystem::path& shaderRoot);

    // Lists the occupied parents of every mip level of `volume` (VoxelVolume::parentLayout,
    // shaders/mipmap_parents.comp.glsl) from its occupied-voxel list, one indirect dispatch per
    // level, and marks them valid. Call once per voxelization, after VoxelizePass and before
    // execute(); a light edit or a bounce reuses them. If the occupied list overflowed, the lists
    // miss voxels: the caller must then build over the whole grid (execute's overOccupiedParents
    // false). Binds LIT_SSBO_OCCUPIED_VOXELS and LIT_SSBO_MIP_PARENTS.
    void listOccupiedParents(VoxelVolume& volume);

    // Rebuilds levels 1..mipCount−1 of volume.radiance() from level 0.
    // Call after the pass that writes level 0 (radiance injection) and before anything samples
    // the volume. It issues the image barrier it needs before reading level 0 and, at the end,
    // glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT) so cone
    // tracing (texture fetches) and image loads see every level. Changes the current program and
    // image units LIT_IMG_MIP_SOURCE, LIT_IMG_MIP_DEST, LIT_IMG_MIP_DEST2, LIT_IMG_MIP_DEST3.
    // With `anisotropic`, also builds the six directional chains (executeDirectional): only then,
    // because they cost ~10× the isotropic chain on llvmpipe (docs/GI.md, "Cost").
    // `overOccupiedParents` (and the volume's parent lists valid): only the voxels of each level
    // with an occupied voxel below them are computed, one indirect dispatch per level over its
    // list; every other voxel is left as VoxelizePass cleared it, 0, which is also what the whole
    // grid computes for a parent of empty children, so the chain is the same to the bit
    // (MipmapOccupied tests). Otherwise every voxel of every level.
    void execute(VoxelVolume& volume, bool anisotropic = false, bool overOccupiedParents = true);
    // Builds every level of the six directional volumes (volume.directional(f)) from level 0 of
    // volume.radiance() and the normal volume (shaders/mipmap_directional.comp.glsl). Uses image
    // units LIT_IMG_MIP_SOURCE, LIT_IMG_MIP_DEST and LIT_IMG_VOXEL_NORMAL; ends with the same
    // barriers as execute(). Over the occupied parents as execute(); the first time after a
    // voxelization (VoxelVolume::directionalStale) it zeroes the directional volumes first.
    void executeDirectional(VoxelVolume& volume, bool overOccupiedParents = true);
    // The same for any cubic, power-of-two GL_TEXTURE_3D in GL_RGBA8 or GL_RGBA16F: levels
    // 1..desc().levels−1 are rebuilt. Throws gl::GlError naming the problem for anything else.
    void execute(const gl::Texture& volume);

    std::vector<gl::Program*> programs() override {
        return {&rgba8_,         &rgba16f_,        &directionalFromIso8_,    &directionalFromIso16f_,
                &directional8_,  &directional16f_, &listRgba8_,              &listRgba16f_,
                &listFromIso8_,  &listFromIso16f_, &listDirectional8_,       &listDirectional16f_,
                &listParents_};
    }

private:
    void executeOverParents(const VoxelVolume& volume);
    void executeDirectionalOverParents(const VoxelVolume& volume);
    static int useDirectionalLevel(const gl::Program& program, const VoxelVolume& volume, int face, int level);

    bool rgba8Packed_ = false;  // RGBA8 levels are bound as r32ui images (see MipmapPass.cpp)
    gl::Program rgba8_, rgba16f_;
    // Directional chains: level 1 from the isotropic level 0, levels k+1 from level k (RGBA8, RGBA16F).
    gl::Program directionalFromIso8_, directionalFromIso16f_, directional8_, directional16f_;
    // The same over the occupied parents (one level per dispatch), and the program that lists them.
    gl::Program listRgba8_, listRgba16f_, listFromIso8_, listFromIso16f_, listDirectional8_, listDirectional16f_;
    gl::Program listParents_;
};

// Times the compute chain against glGenerateTextureMipmap (a plain average: a different, cheaper
// reduction, kept as a yardstick) on the same texture in the same run.
struct MipmapTimings {
    int resolution = 0;                                  // voxels per side of level 0
    bool rgba8 = false;                                  // radiance format: RGBA8 (true) or RGBA16F
    int repetitions = 0;                                 // timed runs of each
    double computeMinMs = 0.0, computeMedianMs = 0.0;    // MipmapPass::execute, GPU time (ms)
    double generateMinMs = 0.0, generateMedianMs = 0.0;  // glGenerateTextureMipmap, GPU time (ms)
    // Process CPU time (ms, all threads) of each, median. On llvmpipe the "GPU" is the CPU: this
    // is the work done, which stays meaningful when other processes compete for the cores and
    // GPU (wall-clock) times do not. On a real GPU it is only the driver's submission cost.
    double computeCpuMedianMs = 0.0, generateCpuMedianMs = 0.0;
    // The chain over the occupied parents (execute's default), GPU and process CPU time, when the
    // volume's parent lists were valid (0 otherwise). `anisotropic`: both runs of the chain also
    // built the six directional chains.
    double occupiedMinMs = 0.0, occupiedMedianMs = 0.0, occupiedCpuMedianMs = 0.0;
    bool anisotropic = false;
    // GPU ms of each timed run, in order (run i of each ran back to back: one interleaved round).
    std::vector<double> computeRunsMs, occupiedRunsMs;
    // computeMinMs / occupiedMinMs: > 1 means building over the occupied parents is faster.
    double occupiedSpeedup() const { return occupiedMinMs > 0.0 ? computeMinMs / occupiedMinMs : 0.0; }
    // generateMinMs / computeMinMs: > 1 means the compute chain is faster. Minimums, because on a
    // shared machine the medians swing by 2× with the load while the minimums stay put.
    double speedup() const { return computeMinMs > 0.0 ? generateMinMs / computeMinMs : 0.0; }
};

// Runs each method once untimed (shader compilation, first-use allocation), then `repetitions`
// timed runs of each, alternating so that all see the same machine load: the whole-grid chain,
// the chain over the occupied parents (if the volume's lists are valid) and glGenerateTextureMipmap.
// With `anisotropic` the two chains include the directional chains. GPU time comes from
// GL_TIMESTAMP query pairs around each run, with glFinish between runs (llvmpipe reports 0 for
// GL_TIME_ELAPSED around compute dispatches, so elapsed queries are not used). glGenerateTexture-
// Mipmap overwrites the levels with plain averages; the chain is rebuilt by `pass` at the end, so
// the volume ends as execute() leaves it. Level 0 is not changed.
// `repetitions` is clamped to [1, 100].
MipmapTimings benchmarkMipmaps(MipmapPass& pass, VoxelVolume& volume, int repetitions, bool anisotropic = false);

}  // namespace lit
