#include "gi/VoxelIrradiancePass.h"

#include <shared.h>

#include <algorithm>

#include "gi/BouncePass.h"
#include "gi/VoxelIrradianceCache.h"
#include "gi/VoxelVolume.h"

namespace lit {

std::vector<gl::Program*> VoxelIrradiancePass::programs() {
    std::vector<gl::Program*> programs;
    programs8_.appendBuilt(programs);
    programs16f_.appendBuilt(programs);
    return programs;
}

void VoxelIrradiancePass::trace(const VoxelVolume& volume, const VoxelIrradianceCache& cache,
                                const RayHitCache& rayHits, const IrradianceTrace& trace) {
    if (!cache.matches(volume)) return;
    const bool rgba8 = volume.radianceRgba8();
    ConeProgram& programs = rgba8 ? programs8_ : programs16f_;
    if (programs.empty())
        programs = ConeProgram(shaderRoot_, rgba8 ? "voxel irradiance rgba8" : "voxel irradiance rgba16f",
                               {{GL_COMPUTE_SHADER, "bounce.comp.glsl"}},
                               radianceFormatDefine(rgba8) + "#define LIT_BOUNCE_IRRADIANCE 1\n", trace.features);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    const gl::Program& program = programs.get(trace.features);
    useWithVoxelSurfaces(program, volume, trace.features);
    // Read and written: the refinement averages into what is there.
    glBindImageTexture(LIT_IMG_VOXEL_DIRECT, cache.traced().id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                       volume.radianceFormat());
    const int setOffset = std::max(trace.setOffset, 0);
    glProgramUniform1i(program.id(), program.location("uSetOffset"), setOffset);
    glProgramUniform1f(program.id(), program.location("uBlend"), 1.0f / static_cast<float>(setOffset + 1));
    rayHits.bind(program, trace.features, trace.overList && setOffset == 0 ? trace.rayHits : RayHits::Off);
    dispatchListRange(volume, program, trace.overList, trace.range);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace lit
