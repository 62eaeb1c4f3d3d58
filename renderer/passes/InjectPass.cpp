#include "passes/InjectPass.h"

#include "passes/VoxelVolume.h"

#include <shared.h>

#include <algorithm>

namespace lit {

namespace {

// Makes `program` current with what the cone-tracing voxel passes (bounce, voxel irradiance) read:
// the voxel uniforms, the radiance volume and its directional chains, and the voxels' albedo and
// normal images.
void useWithVoxelSurfaces(const gl::Program& program, const VoxelVolume& volume, ConeFeatures features) {
    program.use();
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    volume.radiance().bind(LIT_TEX_VOXEL_RADIANCE);
    if (features.anisotropic) volume.bindDirectional();
    if (features.voxelRays > 0) {
        glProgramUniform1i(program.id(), program.location("uVoxelRays"), features.voxelRays);
        glBindImageTexture(LIT_IMG_VOXEL_SURFACE, volume.surface().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    }
    glBindImageTexture(LIT_IMG_VOXEL_ALBEDO, volume.albedo().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
}

// Runs a voxel program (inject.comp.glsl, bounce.comp.glsl) over the occupied-voxel list when
// there is one and fromList asks for it (indirect dispatch: the voxelization wrote the list and
// its dispatch size), otherwise over the whole N³ grid.
void dispatchOverVoxels(const VoxelVolume& volume, const gl::Program& program, bool fromList) {
    fromList = fromList && volume.occupiedList();
    glProgramUniform1i(program.id(), program.location("uFromList"), fromList ? 1 : 0);
    glProgramUniform1ui(program.id(), program.location("uOccupiedCapacity"), volume.occupiedCapacity());
    if (fromList) {
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

// The list entries [first, first + count) when `fromList` and count > 0 (a direct dispatch sized
// for them: the list's indirect command covers all of it), else the whole list or grid as
// dispatchOverVoxels; for programs with LIT_VOXEL_LIST_RANGE_READER.
void dispatchListRange(const VoxelVolume& volume, const gl::Program& program, bool fromList, std::uint32_t first,
                       std::uint32_t count) {
    const bool range = fromList && count > 0 && volume.occupiedList();
    glProgramUniform1ui(program.id(), program.location("uListFirst"), range ? first : 0u);
    glProgramUniform1ui(program.id(), program.location("uListEnd"), range ? first + count : volume.occupiedCapacity());
    if (!range) {
        dispatchOverVoxels(volume, program, fromList);
        return;
    }
    glProgramUniform1i(program.id(), program.location("uFromList"), 1);
    glProgramUniform1ui(program.id(), program.location("uOccupiedCapacity"), volume.occupiedCapacity());
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    volume.occupiedList().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_OCCUPIED_VOXELS);
    glDispatchCompute((count + LIT_INJECT_LIST_GROUP_SIZE - 1) / LIT_INJECT_LIST_GROUP_SIZE, 1, 1);
}

}  // namespace

InjectPass::InjectPass(const std::filesystem::path& shaderRoot)
    : injectPrograms_(shaderRoot, "inject", {{GL_COMPUTE_SHADER, "inject.comp.glsl"}}), shaderRoot_(shaderRoot) {
    injectPrograms_.get(ShadowKinds{});  // a broken shader fails at start-up
}

std::vector<gl::Program*> InjectPass::programs() {
    std::vector<gl::Program*> programs = injectPrograms_.built();
    bounce8_.appendBuilt(programs);
    bounce16f_.appendBuilt(programs);
    irradiance8_.appendBuilt(programs);
    irradiance16f_.appendBuilt(programs);
    for (gl::Program* built : {&filter_, &copy8_, &copy16f_})
        if (*built) programs.push_back(built);
    return programs;
}

void InjectPass::traceBounce(const VoxelVolume& volume, ConeFeatures features, bool secondBounce, bool fromList,
                             std::uint32_t first, std::uint32_t count, RayHits hits) {
    if (volume.resolution() <= 0 || !volume.direct()) return;
    const bool rgba8 = volume.radianceRgba8();
    ConeProgram& programs = rgba8 ? bounce8_ : bounce16f_;
    if (programs.empty())
        programs = ConeProgram(shaderRoot_, rgba8 ? "bounce rgba8" : "bounce rgba16f", {{GL_COMPUTE_SHADER, "bounce.comp.glsl"}},
                               rgba8 ? "#define LIT_BOUNCE_RGBA8 1\n" : "#define LIT_BOUNCE_RGBA8 0\n", features);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    const gl::Program& program = programs.get(features);
    useWithVoxelSurfaces(program, volume, features);
    glBindImageTexture(LIT_IMG_VOXEL_DIRECT, volume.direct().id(), 0, GL_TRUE, 0, GL_READ_ONLY, volume.radianceFormat());
    glBindImageTexture(LIT_IMG_VOXEL_BOUNCE, volume.bounce().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, volume.radianceFormat());
    // The light the rays take: the direct light for the second bounce, the bounce before (level 0) after it.
    if (features.voxelRays > 0)
        glBindImageTexture(LIT_IMG_VOXEL_RAY_SOURCE, secondBounce ? volume.direct().id() : volume.radiance().id(), 0,
                           GL_TRUE, 0, GL_READ_ONLY, volume.radianceFormat());
    bindRayHits(program, features, fromList ? hits : RayHits::Off);
    dispatchListRange(volume, program, fromList, first, count);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

const gl::Program& InjectPass::formatProgram(gl::Program& rgba8Program, gl::Program& rgba16fProgram, bool rgba8,
                                             const std::string& label, const char* file) {
    gl::Program& program = rgba8 ? rgba8Program : rgba16fProgram;
    if (!program)
        program = gl::Program(shaderRoot_, label + (rgba8 ? " rgba8" : " rgba16f"), {{GL_COMPUTE_SHADER, file}},
                              rgba8 ? "#define LIT_BOUNCE_RGBA8 1\n" : "#define LIT_BOUNCE_RGBA8 0\n");
    return program;
}

void InjectPass::endBounce(const VoxelVolume& volume, bool fromList) {
    const int n = volume.resolution();
    if (n <= 0 || !volume.direct()) return;
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    // The bounce replaces level 0; the caller rebuilds the mips from it.
    if (fromList && volume.occupiedList()) {
        // Only the listed voxels: the bounce wrote those, and level 0 of the others is 0.
        const gl::Program& program = formatProgram(copy8_, copy16f_, volume.radianceRgba8(), "bounce copy",
                                                   "bounce_copy.comp.glsl");
        program.use();
        glBindImageTexture(LIT_IMG_VOXEL_BOUNCE, volume.bounce().id(), 0, GL_TRUE, 0, GL_READ_ONLY,
                           volume.radianceFormat());
        glBindImageTexture(LIT_IMG_VOXEL_RADIANCE, volume.radiance().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                           volume.radianceFormat());
        dispatchOverVoxels(volume, program, true);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        return;
    }
    // The whole grid (the list overflowed: the bounce traced every voxel).
    glCopyImageSubData(volume.bounce().id(), GL_TEXTURE_3D, 0, 0, 0, 0, volume.radiance().id(), GL_TEXTURE_3D, 0, 0, 0,
                       0, n, n, n);
}

void InjectPass::executeBounce(const VoxelVolume& volume, ConeFeatures features, bool secondBounce, bool fromList,
                               RayHits hits) {
    traceBounce(volume, features, secondBounce, fromList, 0, 0, hits);
    endBounce(volume, fromList);
}

bool InjectPass::ensureRayHits(int rays, std::uint32_t entries) {
    if (rays <= 0 || entries == 0) return false;
    const std::size_t bytes = static_cast<std::size_t>(entries) * 2 * static_cast<std::size_t>(rays) * 4;
    if (bytes > kMaxRayHitBytes) {
        rayHits_ = {};
        return false;
    }
    // Kept while it fits and is not more than twice what is needed (a voxelization that changes
    // the count a little reallocates nothing).
    if (rayHits_.size() < bytes || rayHits_.size() > 2 * bytes) rayHits_ = gl::Buffer("voxel ray hits", bytes, nullptr, 0);
    return true;
}

void InjectPass::bindRayHits(const gl::Program& program, ConeFeatures features, RayHits hits) const {
    if (features.voxelRays <= 0) return;
    const bool cached = hits != RayHits::Off && static_cast<bool>(rayHits_);
    glProgramUniform1i(program.id(), program.location("uRayHits"), !cached ? 0 : (hits == RayHits::Record ? 1 : 2));
    if (cached) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        rayHits_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_VOXEL_RAY_HITS);
    }
}

void InjectPass::prepareIrradiance(const VoxelVolume& volume, bool clear) {
    const int n = volume.resolution();
    if (n <= 0) return;
    const bool rgba8 = volume.radianceRgba8();
    if (irradianceResolution_ != n || irradianceRgba8_ != rgba8) {
        const GLenum format = volume.radianceFormat();
        // Both sides stacked in z (otherSideTexel, voxel.glsl).
        raw_ = gl::Texture("voxel irradiance (traced)", {GL_TEXTURE_3D, format, n, n, 2 * n, 1});
        irradiance_ = gl::Texture("voxel irradiance (gather texels)", {GL_TEXTURE_3D, GL_RGBA32UI, n, n, n, 1});
        // Read with texelFetch only; nearest keeps the one-level volumes complete for any sampler
        // state (an integer texture with linear filtering would be incomplete).
        for (const gl::Texture* t : {&raw_, &irradiance_}) t->setFilter(GL_NEAREST, GL_NEAREST);
        irradianceResolution_ = n;
        irradianceRgba8_ = rgba8;
        clear = true;  // new storage holds anything
    }
    if (!clear) return;
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(raw_.id(), 0, GL_RGBA, GL_FLOAT, zero);
    const GLuint zeroBits[4] = {0, 0, 0, 0};  // an empty voxel to the gather
    glClearTexImage(irradiance_.id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, zeroBits);
}

void InjectPass::executeIrradiance(const VoxelVolume& volume, ConeFeatures features, bool fromList, std::uint32_t first,
                                   std::uint32_t count, int setOffset, RayHits hits) {
    // prepareIrradiance first (it also follows a change of the radiance format).
    if (volume.resolution() <= 0 || irradianceResolution_ != volume.resolution() ||
        irradianceRgba8_ != volume.radianceRgba8())
        return;
    const bool rgba8 = irradianceRgba8_;
    const GLenum format = volume.radianceFormat();
    ConeProgram& tracePrograms = rgba8 ? irradiance8_ : irradiance16f_;
    const std::string formatDefine = rgba8 ? "#define LIT_BOUNCE_RGBA8 1\n" : "#define LIT_BOUNCE_RGBA8 0\n";
    if (tracePrograms.empty())
        tracePrograms = ConeProgram(shaderRoot_, rgba8 ? "voxel irradiance rgba8" : "voxel irradiance rgba16f",
                                    {{GL_COMPUTE_SHADER, "bounce.comp.glsl"}},
                                    formatDefine + "#define LIT_BOUNCE_IRRADIANCE 1\n", features);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    const gl::Program& program = tracePrograms.get(features);
    useWithVoxelSurfaces(program, volume, features);
    // Read and written: the refinement averages into what is there.
    glBindImageTexture(LIT_IMG_VOXEL_DIRECT, raw_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, format);
    glProgramUniform1i(program.id(), program.location("uSetOffset"), std::max(setOffset, 0));
    glProgramUniform1f(program.id(), program.location("uBlend"), 1.0f / static_cast<float>(std::max(setOffset, 0) + 1));
    // Only the first set's rays are those the cache holds.
    bindRayHits(program, features, fromList && setOffset <= 0 ? hits : RayHits::Off);
    dispatchListRange(volume, program, fromList, first, count);

    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void InjectPass::filterIrradiance(const VoxelVolume& volume, bool fromList, std::uint32_t first, std::uint32_t count) {
    if (volume.resolution() <= 0 || irradianceResolution_ != volume.resolution() ||
        irradianceRgba8_ != volume.radianceRgba8())
        return;
    // One program for both radiance formats: it reads the traced volume through a sampler and
    // writes the gather texels, whose format does not follow the radiance volume's.
    if (!filter_)
        filter_ = gl::Program(shaderRoot_, "voxel irradiance filter",
                              {{GL_COMPUTE_SHADER, "voxel_irradiance_filter.comp.glsl"}});
    const gl::Program& filter = filter_;
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    filter.use();
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    glBindSampler(LIT_TEX_VOXEL_IRRADIANCE, 0);
    raw_.bind(LIT_TEX_VOXEL_IRRADIANCE);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_DIRECT, irradiance_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32UI);
    dispatchListRange(volume, filter, fromList, first, count);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void InjectPass::bindIrradiance() const {
    if (!irradiance_) return;
    // A one-level volume with nearest filtering (set where it is made); a sampler object left on
    // this unit by another pass would override that.
    glBindSampler(LIT_TEX_VOXEL_IRRADIANCE, 0);
    irradiance_.bind(LIT_TEX_VOXEL_IRRADIANCE);
}

void InjectPass::execute(const VoxelVolume& volume, bool fromList, bool writeLevel0, bool writeDirect,
                         ShadowKinds shadows) {
    const int n = volume.resolution();
    if (n <= 0) return;
    const gl::Program& program = injectPrograms_.get(shadows);
    program.use();
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    glBindImageTexture(LIT_IMG_VOXEL_ALBEDO, volume.albedo().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_EMISSION, volume.emission().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_RADIANCE, volume.radiance().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       volume.radianceFormat());
    // The bounces' copy of the direct light (inject.comp.glsl), written as level 0 is.
    writeDirect = writeDirect && volume.direct();
    writeLevel0 = writeLevel0 || !writeDirect;
    glProgramUniform1i(program.id(), program.location("uWriteDirect"), writeDirect ? 1 : 0);
    glProgramUniform1i(program.id(), program.location("uWriteLevel0"), writeLevel0 ? 1 : 0);
    if (writeDirect)
        glBindImageTexture(LIT_IMG_VOXEL_DIRECT, volume.direct().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                           volume.radianceFormat());
    dispatchOverVoxels(volume, program, fromList);
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
