#include "gi/VoxelDispatch.h"

#include <shared.h>

#include <algorithm>
#include <array>
#include <string>

#include "gi/VoxelVolume.h"

namespace lit {

void dispatchOverVoxels(const VoxelVolume& volume, const gl::Program& program, bool overList) {
    dispatchOverVoxels(volume, program, overList, volume.onlyBoxes());
}

void dispatchOverVoxels(const VoxelVolume& volume, const gl::Program& program, bool overList,
                        std::span<const VoxelBox> onlyBoxes) {
    overList = overList && volume.occupiedList();
    glProgramUniform1i(program.id(), program.location("uFromList"), overList ? 1 : 0);
    glProgramUniform1ui(program.id(), program.location("uOccupiedCapacity"), volume.occupiedCapacity());
    setBoxUniforms(program, "uOnlyBox", onlyBoxes);
    if (overList) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        volume.occupiedList().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_OCCUPIED_VOXELS);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, volume.occupiedList().id());
        glDispatchComputeIndirect(4);  // the DispatchIndirectCommand after the count
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    } else {
        const int n = volume.resolution();
        const auto groups = static_cast<GLuint>((n + LIT_INJECT_GROUP_SIZE - 1) / LIT_INJECT_GROUP_SIZE);
        glDispatchCompute(groups, groups, groups);
    }
}

void dispatchListRange(const VoxelVolume& volume, const gl::Program& program, bool overList, VoxelRange range) {
    const bool ranged = overList && range.count > 0 && volume.occupiedList();
    glProgramUniform1ui(program.id(), program.location("uListFirst"), ranged ? range.first : 0u);
    glProgramUniform1ui(program.id(), program.location("uListEnd"),
                        ranged ? range.first + range.count : volume.occupiedCapacity());
    if (!ranged) {
        dispatchOverVoxels(volume, program, overList);
        return;
    }
    glProgramUniform1i(program.id(), program.location("uFromList"), 1);
    glProgramUniform1ui(program.id(), program.location("uOccupiedCapacity"), volume.occupiedCapacity());
    setBoxUniforms(program, "uOnlyBox", volume.onlyBoxes());
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    volume.occupiedList().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_OCCUPIED_VOXELS);
    glDispatchCompute((range.count + LIT_INJECT_LIST_GROUP_SIZE - 1) / LIT_INJECT_LIST_GROUP_SIZE, 1, 1);
}

void setBoxUniforms(const gl::Program& program, const char* name, std::span<const VoxelBox> boxes,
                    std::span<const int> boxW) {
    std::array<glm::ivec4, LIT_CHANGED_BOXES> lo{}, hi{};
    const std::size_t count = std::min<std::size_t>(boxes.size(), LIT_CHANGED_BOXES);
    for (std::size_t i = 0; i < count; ++i) {
        lo[i] = glm::ivec4(boxes[i].min, i < boxW.size() ? boxW[i] : 0);
        hi[i] = glm::ivec4(boxes[i].max, 0);
    }
    const std::string prefix(name);
    glProgramUniform1i(program.id(), program.location((prefix + "Count").c_str()), static_cast<GLint>(count));
    glProgramUniform4iv(program.id(), program.location((prefix + "Min").c_str()), LIT_CHANGED_BOXES, &lo[0].x);
    glProgramUniform4iv(program.id(), program.location((prefix + "Max").c_str()), LIT_CHANGED_BOXES, &hi[0].x);
}

void useWithVoxelSurfaces(const gl::Program& program, const VoxelVolume& volume, ConeFeatures features) {
    program.use();
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    volume.radiance().bind(LIT_TEX_VOXEL_RADIANCE);
    if (features.anisotropic) volume.bindDirectional();
    if (features.voxelRays > 0) {
        glProgramUniform1i(program.id(), program.location("uVoxelRays"), features.voxelRays);
        glBindImageTexture(LIT_IMG_VOXEL_SURFACE, volume.surface().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
        volume.sides().bind(LIT_TEX_VOXEL_SIDES);
    }
    glBindImageTexture(LIT_IMG_VOXEL_ALBEDO, volume.albedo().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    if (volume.solidVoxels()) volume.solidVoxels().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_SOLID_VOXELS);
}

}  // namespace lit
