#pragma once
// Marks the empty voxels that lie inside a solid (solid_voxels.comp.glsl), after each
// voxelization, in VoxelVolume::solidVoxels: the voxel rays do not start in them; then gives the
// voxels where two solids touch, whose buried faces cancelled their normal, the direction of the
// space they face (buried_faces.comp.glsl). docs/GI.md, "Solid voxels".

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

    // Which columns a voxelization of changed boxes walks again.
    enum class Columns {
        ThroughBoxes,  // those through the boxes' footprints in x and z
        Every,         // every one (after a scroll: the solid bits do not move with the volume)
    };
    // Walks the columns along y of the volume's normal volume (N²/32 invocations of N steps each
    // way): every column, or with `boxes` those `columns` says. Then passes over the occupied
    // voxels (the list, else the grid) for the buried faces: every one, or with `boxes` those in
    // them or beside them.
    void execute(const VoxelVolume& volume, std::span<const VoxelBox> boxes = {},
                 Columns columns = Columns::ThroughBoxes);

    std::vector<gl::Program*> programs() override { return {&program_, &buriedFaces_}; }

private:
    void walk(const VoxelVolume& volume, glm::ivec2 lo, glm::ivec2 hi);
    void findJunctions(const VoxelVolume& volume, std::span<const VoxelBox> boxes);

    gl::Program program_;
    gl::Program buriedFaces_;
};

}  // namespace lit
