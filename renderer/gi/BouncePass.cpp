#include "gi/BouncePass.h"

#include <shared.h>

#include <array>

#include "gi/VoxelVolume.h"

namespace lit {

std::string radianceFormatDefine(bool rgba8) {
    return rgba8 ? "#define LIT_BOUNCE_RGBA8 1\n" : "#define LIT_BOUNCE_RGBA8 0\n";
}

const gl::Program& radianceFormatProgram(const std::filesystem::path& shaderRoot, gl::Program& rgba8Program,
                                         gl::Program& rgba16fProgram, bool rgba8, const std::string& label,
                                         const char* file) {
    gl::Program& program = rgba8 ? rgba8Program : rgba16fProgram;
    if (!program)
        program = gl::Program(shaderRoot, label + (rgba8 ? " rgba8" : " rgba16f"), {{GL_COMPUTE_SHADER, file}},
                              radianceFormatDefine(rgba8));
    return program;
}

std::vector<gl::Program*> BouncePass::programs() {
    std::vector<gl::Program*> programs;
    trace8_.appendBuilt(programs);
    trace16f_.appendBuilt(programs);
    for (gl::Program* built : {&copy8_, &copy16f_, &warm8_, &warm16f_})
        if (*built) programs.push_back(built);
    return programs;
}

void BouncePass::trace(const VoxelVolume& volume, const RayHitCache& cache, const BounceTrace& bounce) {
    if (volume.resolution() <= 0 || !volume.direct()) return;
    const bool rgba8 = volume.radianceRgba8();
    ConeProgram& programs = rgba8 ? trace8_ : trace16f_;
    if (programs.empty())
        programs = ConeProgram(shaderRoot_, rgba8 ? "bounce rgba8" : "bounce rgba16f",
                               {{GL_COMPUTE_SHADER, "bounce.comp.glsl"}}, radianceFormatDefine(rgba8), bounce.features);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    const gl::Program& program = programs.get(bounce.features);
    useWithVoxelSurfaces(program, volume, bounce.features);
    const GLenum format = volume.radianceFormat();
    glBindImageTexture(LIT_IMG_VOXEL_DIRECT, volume.direct().id(), 0, GL_TRUE, 0, GL_READ_ONLY, format);
    glBindImageTexture(LIT_IMG_VOXEL_BOUNCE, volume.bounce().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format);
    // The light the rays take: the direct light for the second bounce, the bounce before (level 0) after it.
    if (bounce.features.voxelRays > 0)
        glBindImageTexture(LIT_IMG_VOXEL_RAY_SOURCE,
                           bounce.secondBounce ? volume.direct().id() : volume.radiance().id(), 0, GL_TRUE, 0,
                           GL_READ_ONLY, format);
    // A change is gathered from the voxel rays' recorded hits, never while recording them (the
    // subset would leave the other rays' hits unrecorded).
    const bool change = bounce.changeSubset >= 0 && bounce.features.voxelRays > 0 && volume.change() &&
                        bounce.rayHits != RayHits::Record && !bounce.secondBounce;
    if (bounce.features.voxelRays > 0) {
        glProgramUniform1i(program.id(), program.location("uChangeSubset"), change ? bounce.changeSubset : -1);
        glProgramUniform1i(program.id(), program.location("uChangeStride"), bounce.changeStride);
        if (change)
            glBindImageTexture(LIT_IMG_VOXEL_CHANGE, volume.change().id(), 0, GL_TRUE, 0, GL_READ_ONLY, format);
    }
    cache.bind(program, bounce.features, bounce.overList ? bounce.rayHits : RayHits::Off);
    const bool measure = bounce.measureChange && changeBins_;
    glProgramUniform1i(program.id(), program.location("uMeasureChange"), measure ? 1 : 0);
    if (measure) changeBins_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_BOUNCE_CHANGE);
    dispatchListRange(volume, program, bounce.overList, bounce.range);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void BouncePass::resetChange() {
    constexpr std::size_t kBytes = 2 * LIT_BOUNCE_CHANGE_BINS * sizeof(GLuint);
    if (!changeBins_) changeBins_ = gl::Buffer("bounce change", kBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    const GLuint zero = 0;
    glClearNamedBufferData(changeBins_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

BounceChange BouncePass::readChange() const {
    if (!changeBins_) return {};
    std::array<GLuint, 2 * LIT_BOUNCE_CHANGE_BINS> bins{};
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(changeBins_.id(), 0, sizeof bins, bins.data());
    BounceChange change;
    for (int i = 0; i < LIT_BOUNCE_CHANGE_BINS; ++i) {
        change.luminance += bins[static_cast<std::size_t>(i)];
        change.change += bins[static_cast<std::size_t>(LIT_BOUNCE_CHANGE_BINS + i)];
    }
    change.luminance /= LIT_BOUNCE_CHANGE_SCALE;
    change.change /= LIT_BOUNCE_CHANGE_SCALE;
    return change;
}

void BouncePass::finish(const VoxelVolume& volume, const BounceFinish& how) {
    const int n = volume.resolution();
    changeKept_ = false;
    if (n <= 0 || !volume.direct()) return;
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    if (how.overList && volume.occupiedList()) {
        // Only the listed voxels: the bounce wrote those, and level 0 of the others is 0.
        const gl::Program& program = radianceFormatProgram(shaderRoot_, copy8_, copy16f_, volume.radianceRgba8(),
                                                           "bounce copy", "bounce_copy.comp.glsl");
        program.use();
        glBindImageTexture(LIT_IMG_VOXEL_BOUNCE, volume.bounce().id(), 0, GL_TRUE, 0, GL_READ_ONLY,
                           volume.radianceFormat());
        // Read too: the bounce before, whose change from it the tail extrapolates.
        glBindImageTexture(LIT_IMG_VOXEL_RADIANCE, volume.radiance().id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                           volume.radianceFormat());
        glBindImageTexture(LIT_IMG_VOXEL_ALBEDO, volume.albedo().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
        glProgramUniform1f(program.id(), program.location("uTail"), how.tail);
        changeKept_ = how.keepChange && volume.change();
        glProgramUniform1i(program.id(), program.location("uWriteChange"), changeKept_ ? 1 : 0);
        glProgramUniform1i(program.id(), program.location("uChangeFromDirect"), how.fromDirect ? 1 : 0);
        if (changeKept_)
            glBindImageTexture(LIT_IMG_VOXEL_CHANGE, volume.change().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                               volume.radianceFormat());
        glBindImageTexture(LIT_IMG_VOXEL_DIRECT, volume.direct().id(), 0, GL_TRUE, 0, GL_READ_ONLY,
                           volume.radianceFormat());
        dispatchOverVoxels(volume, program, true);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        return;
    }
    // The whole grid (the list overflowed: the bounce traced every voxel).
    glCopyImageSubData(volume.bounce().id(), GL_TEXTURE_3D, 0, 0, 0, 0, volume.radiance().id(), GL_TEXTURE_3D, 0, 0, 0,
                       0, n, n, n);
}

void BouncePass::keepIndirect(const VoxelVolume& volume) {
    if (volume.resolution() <= 0 || !volume.direct() || !volume.occupiedList()) return;
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // voxels new to the geometry keep nothing
    glClearTexImage(volume.bounce().id(), 0, GL_RGBA, GL_FLOAT, zero);
    warmStart(volume, 0);
}

void BouncePass::addKeptIndirect(const VoxelVolume& volume) {
    if (volume.resolution() <= 0 || !volume.direct() || !volume.occupiedList()) return;
    warmStart(volume, 1);
}

void BouncePass::warmStart(const VoxelVolume& volume, int mode) {
    const gl::Program& program = radianceFormatProgram(shaderRoot_, warm8_, warm16f_, volume.radianceRgba8(),
                                                       "bounce warm start", "bounce_warm_start.comp.glsl");
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    program.use();
    glProgramUniform1i(program.id(), program.location("uMode"), mode);
    const GLenum format = volume.radianceFormat();
    glBindImageTexture(LIT_IMG_VOXEL_RADIANCE, volume.radiance().id(), 0, GL_TRUE, 0, GL_READ_WRITE, format);
    glBindImageTexture(LIT_IMG_VOXEL_DIRECT, volume.direct().id(), 0, GL_TRUE, 0, GL_READ_ONLY, format);
    glBindImageTexture(LIT_IMG_VOXEL_BOUNCE, volume.bounce().id(), 0, GL_TRUE, 0, GL_READ_WRITE, format);
    dispatchOverVoxels(volume, program, true);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace lit
