#include "gi/InjectPass.h"

#include <shared.h>

#include <algorithm>
#include <array>

#include "gi/VoxelDispatch.h"
#include "gi/VoxelVolume.h"

namespace lit {

InjectPass::InjectPass(const std::filesystem::path& shaderRoot)
    : programs_(shaderRoot, "inject", {{GL_COMPUTE_SHADER, "inject.comp.glsl"}}) {
    programs_.get(ShadowKinds{});  // a broken shader fails at start-up
}

void InjectPass::execute(const VoxelVolume& volume, const InjectOptions& options) {
    if (volume.resolution() <= 0) return;
    const gl::Program& program = programs_.get(options.shadows);
    program.use();
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    glBindImageTexture(LIT_IMG_VOXEL_ALBEDO, volume.albedo().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_EMISSION, volume.emission().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_SURFACE, volume.surface().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_RADIANCE, volume.radiance().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       volume.radianceFormat());
    // The bounces' copy of the direct light (inject.comp.glsl), written as level 0 is.
    const bool writeDirect = options.writeDirect && volume.direct();
    const bool writeLevel0 = options.writeLevel0 || !writeDirect;
    glProgramUniform1i(program.id(), program.location("uWriteDirect"), writeDirect ? 1 : 0);
    glProgramUniform1i(program.id(), program.location("uWriteLevel0"), writeLevel0 ? 1 : 0);
    setBoxUniforms(program, "uLevel0Box", writeLevel0 ? std::span<const VoxelBox>{} : std::span(options.level0Boxes));
    if (writeDirect)
        glBindImageTexture(LIT_IMG_VOXEL_DIRECT, volume.direct().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                           volume.radianceFormat());
    dispatchOverVoxels(volume, program, options.overList);
    // The mipmap pass reads level 0 as an image; cone tracing and debug views sample it.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

std::vector<glm::vec4> readRadianceVoxels(const VoxelVolume& volume, int level, float rgba8Range) {
    const int n = volume.resolution();
    if (n <= 0 || level < 0 || level >= volume.mipCount()) return {};
    const int side = std::max(n >> level, 1);
    std::vector<glm::vec4> texels(static_cast<std::size_t>(side) * side * side);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(volume.radiance().id(), level, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)), texels.data());
    if (volume.radianceRgba8())
        for (glm::vec4& t : texels) t = glm::vec4(glm::vec3(t) * rgba8Range, t.a);
    return texels;
}

}  // namespace lit
