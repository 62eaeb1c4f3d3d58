#pragma once
// The voxel debug views, for one mip level and one channel (DebugViewSettings::voxelMip,
// voxelChannel):
//   View::VoxelSlice  one slice of the volume filling the viewport (aspect kept), each voxel a
//                     square (nearest filtering), with a thin grid once voxels are ≥ 4 px wide;
//   View::Voxels      the volume ray-marched voxel by voxel (a DDA over that mip's grid), each
//                     occupied voxel drawn as a cube with its faces shaded by their axis;
//   View::VoxelLevels every volume running ray-marched at level 0 (executeLevels), each voxel a
//                     cube in its level's colour (VoxelLevelColors.h) with its edges marked, the
//                     space a finer level holds left to it.
// Both write display values in [0,1] into the HDR target (see isDataView): albedo as is, normals
// as 0.5 + 0.5·n, opacity as grey, radiance and emission tone-mapped with the exposure.
//
// Radiance and opacity come from the radiance volume, which has a mip chain. Albedo, normal and
// emission live in single-level r32ui volumes; for those the pass decodes the channel into its
// own RGBA16F volume premultiplied by occupancy (so a mip averages only occupied voxels) and
// builds that volume's mip chain — only when the channel or the voxels changed.

#include <cstdint>
#include <span>

#include "RenderSettings.h"
#include "passes/Pass.h"

namespace lit {

class VoxelVolume;

bool isVoxelView(View view);  // Voxels, VoxelSlice or VoxelLevels

class VoxelDebugPass : public Pass {
public:
    explicit VoxelDebugPass(const std::filesystem::path& shaderRoot);

    // Draws settings.debug.view into the bound framebuffer (viewport set by the caller, the frame UBO
    // bound). `volume` is nullptr when there is none (GI off): the view is black.
    // `voxelGeneration` must change whenever the volume's material volumes were rewritten.
    void execute(const RenderSettings& settings, const VoxelVolume* volume, std::uint64_t voxelGeneration);

    // Draws View::VoxelLevels: `volumes` finest first, the scene's volume last (at most
    // LIT_MAX_NEAR_LEVELS + 1; empty when GI is off: the view is black).
    void executeLevels(std::span<const VoxelVolume* const> volumes);

    // Mip level and slice index (at that level) the views show for `settings` on `volume`.
    static int mipLevel(const RenderSettings& settings, const VoxelVolume& volume);
    static int sliceIndex(const RenderSettings& settings, const VoxelVolume& volume);

    std::vector<gl::Program*> programs() override { return {&view_, &decode_, &levels_}; }

private:
    // Rebuilds decoded_ for `channel` (albedo, normal or emission) when it is stale.
    void decode(const VoxelVolume& volume, VoxelChannel channel, std::uint64_t voxelGeneration);

    gl::Program view_, decode_, levels_;
    FullscreenTriangle triangle_;
    gl::Texture decoded_;  // RGBA16F N³ with mips: rgb channel value × occupancy, a occupancy
    // What decoded_ holds; generation 0 = nothing yet.
    VoxelChannel decodedChannel_ = VoxelChannel::Albedo;
    std::uint64_t decodedGeneration_ = 0;
    // ... of which volume (the scene's or a near level's count their generations apart).
    const VoxelVolume* decodedVolume_ = nullptr;
    int decodedResolution_ = 0;
};

}  // namespace lit
