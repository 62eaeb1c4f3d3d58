#include "gi/SolidVoxelsPass.h"

#include <shared.h>

#include <algorithm>

#include "gi/VoxelDispatch.h"
#include "gi/VoxelVolume.h"

namespace lit {

namespace {
constexpr int kColumnsPerInvocation = 32;  // one bit each of a word (solid_voxels.comp.glsl)
}  // namespace

SolidVoxelsPass::SolidVoxelsPass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "solid voxels", {{GL_COMPUTE_SHADER, "solid_voxels.comp.glsl"}}),
      buriedFaces_(shaderRoot, "buried faces", {{GL_COMPUTE_SHADER, "buried_faces.comp.glsl"}}) {}

void SolidVoxelsPass::execute(const VoxelVolume& volume, std::span<const VoxelBox> boxes, Columns columns) {
    const int n = volume.resolution();
    if (n < kColumnsPerInvocation || !volume.solidVoxels()) return;
    // The columns to walk: x in words of 32 columns, z in voxels, [min, end).
    glm::ivec2 lo(0), hi(n / kColumnsPerInvocation, n);
    if (!boxes.empty() && columns == Columns::ThroughBoxes) {
        lo = glm::ivec2(n);
        hi = glm::ivec2(0);
        for (const VoxelBox& box : boxes) {
            lo = glm::min(lo, glm::ivec2(std::max(box.min.x, 0) / kColumnsPerInvocation, std::max(box.min.z, 0)));
            hi = glm::max(hi, glm::ivec2((std::min(box.max.x, n) + kColumnsPerInvocation - 1) / kColumnsPerInvocation,
                                         std::min(box.max.z, n)));
        }
    }
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    if (hi.x > lo.x && hi.y > lo.y) walk(volume, lo, hi);
    findJunctions(volume, boxes);
}

void SolidVoxelsPass::walk(const VoxelVolume& volume, glm::ivec2 lo, glm::ivec2 hi) {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    program_.use();
    glProgramUniform2i(program_.id(), program_.location("uColumnMin"), lo.x, lo.y);
    glProgramUniform2i(program_.id(), program_.location("uColumnEnd"), hi.x, hi.y);
    volume.solidVoxels().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_SOLID_VOXELS);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    const int invocations = (hi.x - lo.x) * (hi.y - lo.y);
    glDispatchCompute(static_cast<GLuint>((invocations + LIT_SOLID_VOXELS_GROUP_SIZE - 1) / LIT_SOLID_VOXELS_GROUP_SIZE), 1,
                      1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void SolidVoxelsPass::findJunctions(const VoxelVolume& volume, std::span<const VoxelBox> boxes) {
    // The voxels a voxelization of changed boxes wrote again, and their neighbours, whose faces
    // may have changed; the others were made one-sided before or stay as they were.
    std::vector<VoxelBox> padded(boxes.begin(), boxes.end());
    const int n = volume.resolution();
    for (VoxelBox& box : padded) {
        box.min = glm::max(box.min - 1, glm::ivec3(0));
        box.max = glm::min(box.max + 1, glm::ivec3(n));
    }
    buriedFaces_.use();
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_SURFACE, volume.surface().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    dispatchOverVoxels(volume, buriedFaces_, true, padded);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace lit
