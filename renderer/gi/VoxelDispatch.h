#pragma once
// How the voxel passes (inject, bounce, voxel irradiance, its filter) run over the voxels: over
// the occupied-voxel list that the voxelization wrote (an indirect dispatch, or a range of it), or
// over the whole N³ grid when the list overflowed.

#include <cstdint>
#include <span>

#include "gi/ConeProgram.h"
#include "gi/VoxelRegions.h"
#include "gl/Shader.h"

namespace lit {

class VoxelVolume;

// Entries [first, first + count) of the occupied-voxel list; count 0 = all of it.
struct VoxelRange {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    bool operator==(const VoxelRange&) const = default;
};

// Runs `program` over the occupied-voxel list (indirect dispatch, its size written by the
// voxelization) when `overList` and the volume has one, else over the whole grid. Sets the
// program's uFromList and uOccupiedCapacity.
void dispatchOverVoxels(const VoxelVolume& volume, const gl::Program& program, bool overList);
// The same, limited to `onlyBoxes` (uOnlyBox*) instead of the volume's VoxelVolume::onlyBoxes
// (empty: every voxel).
void dispatchOverVoxels(const VoxelVolume& volume, const gl::Program& program, bool overList,
                        std::span<const VoxelBox> onlyBoxes);

// The list range `range` when `overList` and range.count > 0 (a direct dispatch sized for it),
// else the whole list or grid as dispatchOverVoxels; for programs with LIT_VOXEL_LIST_RANGE_READER.
void dispatchListRange(const VoxelVolume& volume, const gl::Program& program, bool overList, VoxelRange range);

// Sets `program`'s box list: <name>Count, <name>Min[LIT_CHANGED_BOXES] (xyz first voxel, w
// boxW[i] when given) and <name>Max (xyz one past the last). Boxes past LIT_CHANGED_BOXES are
// dropped (the tracker never makes more).
void setBoxUniforms(const gl::Program& program, const char* name, std::span<const VoxelBox> boxes,
                    std::span<const int> boxW = {});

// Makes `program` current with what the voxel passes that gather light read: the voxel
// uniforms, the radiance volume (and its directional chains with anisotropic features), the
// voxels' albedo, normal and (for voxel rays) surface images, uVoxelRays, and the solid voxels.
void useWithVoxelSurfaces(const gl::Program& program, const VoxelVolume& volume, ConeFeatures features);

}  // namespace lit
