#include "gi/IrradianceFilterPass.h"

#include <shared.h>

#include "gi/VoxelIrradianceCache.h"
#include "gi/VoxelVolume.h"

namespace lit {

void IrradianceFilterPass::execute(const VoxelVolume& volume, const VoxelIrradianceCache& cache, bool overList,
                                   VoxelRange range) {
    if (!cache.matches(volume)) return;
    // It reads the traced volume through a sampler and writes the gather texels, whose format
    // does not follow the radiance volume's.
    if (!program_)
        program_ = gl::Program(shaderRoot_, "voxel irradiance filter",
                               {{GL_COMPUTE_SHADER, "voxel_irradiance_filter.comp.glsl"}});
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    program_.use();
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    glBindSampler(LIT_TEX_VOXEL_IRRADIANCE, 0);
    cache.traced().bind(LIT_TEX_VOXEL_IRRADIANCE);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_DIRECT, cache.gatherTexels().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32UI);
    dispatchListRange(volume, program_, overList, range);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void IrradianceFilterPass::pruneShown(const VoxelVolume& volume, const VoxelIrradianceCache& cache) {
    if (!cache.matches(volume) || !cache.showingPrevious()) return;
    prune(volume, cache.shownTexels());
}

void IrradianceFilterPass::pruneBoth(const VoxelVolume& volume, const VoxelIrradianceCache& cache) {
    if (!cache.matches(volume)) return;
    prune(volume, cache.shownTexels());
    if (cache.showingPrevious()) prune(volume, cache.gatherTexels());
}

void IrradianceFilterPass::prune(const VoxelVolume& volume, const gl::Texture& texels) {
    if (!prune_)
        prune_ = gl::Program(shaderRoot_, "voxel irradiance prune", {{GL_COMPUTE_SHADER, "voxel_irradiance_prune.comp.glsl"}});
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    prune_.use();
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_DIRECT, texels.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32UI);
    const auto groups = static_cast<GLuint>((volume.resolution() + LIT_INJECT_GROUP_SIZE - 1) / LIT_INJECT_GROUP_SIZE);
    glDispatchCompute(groups, groups, groups);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace lit
