#include "gi/InjectPass.h"

#include <shared.h>

#include <algorithm>
#include <array>
#include <glm/gtc/packing.hpp>

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
    glBindImageTexture(LIT_IMG_VOXEL_SIDES, volume.sides().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG32UI);
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

std::vector<VoxelSides> readVoxelSides(const VoxelVolume& volume, float rgba8Range) {
    const int n = volume.resolution();
    if (n <= 0) return {};
    std::vector<glm::uvec2> texels(static_cast<std::size_t>(n) * n * n);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(volume.sides().id(), 0, GL_RG_INTEGER, GL_UNSIGNED_INT,
                      static_cast<GLsizei>(texels.size() * sizeof(glm::uvec2)), texels.data());
    const float scale = volume.radianceRgba8() ? rgba8Range : 1.0f;
    std::vector<VoxelSides> sides(texels.size());
    for (std::size_t i = 0; i < texels.size(); ++i) {
        const glm::uvec2 t = texels[i];
        if ((t.y & 0x80000000u) == 0) continue;
        VoxelSides& s = sides[i];
        s.split = true;
        s.delta = scale * glm::vec3(glm::unpackHalf2x16(t.x), glm::unpackHalf2x16(t.y).x);
        // Octahedral, 7 bits per coordinate in bits 16–22 and 23–29 (voxel.glsl, unpackSidesAxis).
        const glm::vec2 e = glm::vec2(float((t.y >> 16) & 127u), float((t.y >> 23) & 127u)) / 127.0f * 2.0f - 1.0f;
        glm::vec3 a(e, 1.0f - std::abs(e.x) - std::abs(e.y));
        const float fold = std::max(-a.z, 0.0f);
        a.x += a.x >= 0.0f ? -fold : fold;
        a.y += a.y >= 0.0f ? -fold : fold;
        s.axis = glm::normalize(a);
    }
    return sides;
}

}  // namespace lit
