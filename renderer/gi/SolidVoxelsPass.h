#pragma once
// Marks the empty voxels that lie inside a solid (solid_voxels.comp.glsl), after each
// voxelization, in VoxelVolume::solidVoxels: the voxel rays do not start in them (docs/GI.md,
// "Solid voxels").

#include <filesystem>
#include <span>
#include <vector>

#include "gi/VoxelRegions.h"
#include "gl/Shader.h"
#include "passes/Pass.h"

namespace lit {

class VoxelVolume;

class SolidVoxelsPass : public Pass {
public:
    explicit SolidVoxelsPass(const std::filesystem::path& shaderRoot);

    // Walks the columns along y of the volume's normal volume (N²/32 invocations of N steps each
    // way): every column, or with `boxes` only those through their footprints in x and z.
    void execute(const VoxelVolume& volume, std::span<const VoxelBox> boxes = {});

    std::vector<gl::Program*> programs() override { return {&program_}; }

private:
    gl::Program program_;
};

}  // namespace lit
