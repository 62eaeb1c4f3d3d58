#include "gi/VoxelScrollPass.h"

#include <shared.h>

#include <string>

#include "gi/BouncePass.h"
#include "gi/VoxelIrradianceCache.h"
#include "gi/VoxelVolume.h"

namespace lit {

std::vector<gl::Program*> VoxelScrollPass::programs() {
    std::vector<gl::Program*> built;
    for (auto& byWritten : programs_)
        for (auto& byFormat : byWritten)
            for (gl::Program& program : byFormat)
                if (program) built.push_back(&program);
    return built;
}

const gl::Program& VoxelScrollPass::program(bool written, bool rgba8, int phase) {
    gl::Program& program = programs_[written ? 1 : 0][rgba8 ? 1 : 0][phase];
    if (!program)
        program = gl::Program(shaderRoot_,
                              std::string("voxel scroll") + (written ? " written" : "") +
                                  (rgba8 ? " rgba8" : " rgba16f") + (phase == 0 ? " lift" : " place"),
                              {{GL_COMPUTE_SHADER, "voxel_scroll.comp.glsl"}},
                              radianceFormatDefine(rgba8) + "#define LIT_SCROLL_WRITTEN " + (written ? "1" : "0") +
                                  "\n#define LIT_SCROLL_PHASE " + std::to_string(phase) + "\n");
    return program;
}

void VoxelScrollPass::execute(const VoxelVolume& volume, const VoxelIrradianceCache& cache, glm::ivec3 shift,
                              std::uint32_t entries) {
    if (shift == glm::ivec3(0)) return;
    const std::size_t bytes = std::size_t{entries} * LIT_SCROLL_SAVED_TEXELS * 16;
    if (saved_.size() < bytes) saved_ = gl::Buffer("voxel scroll saved texels", bytes + bytes / 4, nullptr, 0);
    const bool rgba8 = volume.radianceRgba8();
    const GLuint groups = (entries + LIT_INJECT_LIST_GROUP_SIZE - 1) / LIT_INJECT_LIST_GROUP_SIZE;
    // The passes before wrote these as images and buffers.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    volume.occupiedList().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_OCCUPIED_VOXELS);
    volume.listedVoxels().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_LISTED_VOXELS);
    if (entries > 0) saved_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_VOXEL_SCROLL);
    // Lift, then place: a program each, since llvmpipe would run both phases' code in either.
    const auto run = [&](bool written, auto&& setUniforms) {
        for (int phase = 0; phase < 2; ++phase) {
            const gl::Program& p = program(written, rgba8, phase);
            glProgramUniform1ui(p.id(), p.location("uEntries"), entries);
            glProgramUniform3i(p.id(), p.location("uShift"), shift.x, shift.y, shift.z);
            setUniforms(p);
            p.use();
            glDispatchCompute(groups, 1, 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        }
    };
    const GLenum radianceFormat = volume.radianceFormat();
    if (entries > 0 && cache.matches(volume)) {
        // The traced irradiance and what an update under way writes: first, as it reads the list's
        // old coordinates.
        const bool writtenTexels = &cache.gatherTexels() != &cache.shownTexels();
        glBindImageTexture(LIT_IMG_SCROLL_TRACED, cache.traced().id(), 0, GL_TRUE, 0, GL_READ_WRITE, radianceFormat);
        // An unused image is bound to a volume of its format all the same (the shader skips it).
        glBindImageTexture(LIT_IMG_SCROLL_BOUNCE, volume.bounce() ? volume.bounce().id() : volume.radiance().id(), 0,
                           GL_TRUE, 0, GL_READ_WRITE, radianceFormat);
        glBindImageTexture(LIT_IMG_SCROLL_WRITTEN_TEXELS, cache.gatherTexels().id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                           GL_RGBA32UI);
        run(true, [&](const gl::Program& p) {
            glProgramUniform1i(p.id(), p.location("uHasBounce"), volume.bounce() ? 1 : 0);
            glProgramUniform1i(p.id(), p.location("uHasWrittenTexels"), writtenTexels ? 1 : 0);
        });
    }
    glClearNamedBufferData(volume.listedVoxels().id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    if (entries > 0) {
        glBindImageTexture(LIT_IMG_VOXEL_ALBEDO, volume.albedo().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
        glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
        glBindImageTexture(LIT_IMG_VOXEL_EMISSION, volume.emission().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
        glBindImageTexture(LIT_IMG_VOXEL_SURFACE, volume.surface().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
        glBindImageTexture(LIT_IMG_VOXEL_SIDES, volume.sides().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RG32UI);
        glBindImageTexture(LIT_IMG_VOXEL_RADIANCE, volume.radiance().id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                           radianceFormat);
        glBindImageTexture(LIT_IMG_SCROLL_SHOWN_TEXELS, cache.shownTexels().id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                           GL_RGBA32UI);
        run(false, [](const gl::Program&) {});
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                    GL_COMMAND_BARRIER_BIT);
}

}  // namespace lit
