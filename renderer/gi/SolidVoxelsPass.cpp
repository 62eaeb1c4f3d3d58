#include "gi/SolidVoxelsPass.h"

#include <shared.h>

#include "gi/VoxelVolume.h"

namespace lit {

namespace {
constexpr int kGroupSize = 64;  // solid_voxels.comp.glsl's local_size_x
constexpr int kColumnsPerInvocation = 32;
}  // namespace

SolidVoxelsPass::SolidVoxelsPass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "solid voxels", {{GL_COMPUTE_SHADER, "solid_voxels.comp.glsl"}}) {}

void SolidVoxelsPass::execute(const VoxelVolume& volume) {
    const int n = volume.resolution();
    if (n < kColumnsPerInvocation || !volume.solidVoxels()) return;
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    program_.use();
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    volume.solidVoxels().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_SOLID_VOXELS);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    const int invocations = n / kColumnsPerInvocation * n;
    glDispatchCompute(static_cast<GLuint>((invocations + kGroupSize - 1) / kGroupSize), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace lit
