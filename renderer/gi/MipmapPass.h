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
// coarse levels do not see through it; empty space stays 0, a uniform region (L, 1) stays
// (L, 1), and rgb/a stays a weighted mean of the children's colours (no dark edges).
// glGenerateTextureMipmap (a plain average) is only a speed reference (docs/PERFORMANCE.md, "Mipmaps").
//
// Every level is rounded to the texture's format before the next is built from it: RGBA8 is
// reduced in exact integer arithmetic on the bytes, RGBA16F in fp32 in a fixed order; the CPU
// reference in tests/gl/test_mipmap.cpp repeats both bit for bit.
//
// How it is tuned for llvmpipe (MipmapPass.cpp, docs/PERFORMANCE.md "Mipmaps"): no shared memory
// and no barrier(), which measured slower there.

#include <filesystem>
#include <vector>

#include "passes/Pass.h"

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
    // because they cost over ten times the isotropic chain on llvmpipe (lit-render --bench prints both:
    // docs/PERFORMANCE.md, "What each benchmark prints").
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
        return {&rgba8_,        &rgba16f_,        &directionalFromIso8_, &directionalFromIso16f_,
                &directional8_, &directional16f_, &listRgba8_,           &listRgba16f_,
                &listFromIso8_, &listFromIso16f_, &listDirectional8_,    &listDirectional16f_,
                &listParents_};
    }

private:
    void executeOverParents(const VoxelVolume& volume);
    void executeDirectionalOverParents(const VoxelVolume& volume);
    static int useDirectionalLevel(const gl::Program& program, const VoxelVolume& volume, int face, int level);
    static int useDirectionalLevel0(const gl::Program& program, const VoxelVolume& volume);

    bool rgba8Packed_ = false;  // RGBA8 levels are bound as r32ui images (see MipmapPass.cpp)
    gl::Program rgba8_, rgba16f_;
    // Directional chains: level 1 of all six faces from the isotropic level 0, levels k+1 of one face
    // from its level k (RGBA8, RGBA16F).
    gl::Program directionalFromIso8_, directionalFromIso16f_, directional8_, directional16f_;
    // The same over the occupied parents (one level per dispatch), and the program that lists them.
    gl::Program listRgba8_, listRgba16f_, listFromIso8_, listFromIso16f_, listDirectional8_, listDirectional16f_;
    gl::Program listParents_;
};

}  // namespace lit
