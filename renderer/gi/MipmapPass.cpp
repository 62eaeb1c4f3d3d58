#include "gi/MipmapPass.h"

#include <shared.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

#include "gi/VoxelVolume.h"
#include "gl/GlError.h"

namespace lit {

namespace {

// How each format is reduced: levels per dispatch and group size, chosen by timing each layout
// against the others with benchmarkMipmaps on llvmpipe (docs/PERFORMANCE.md, "Mipmaps"). llvmpipe's
// RGBA8 image loads cost about twice its RGBA16F ones per texel, so RGBA8 gains from reading each
// level once (three levels per dispatch, r32ui packed loads) while RGBA16F loses when one
// invocation walks a whole block; shared-memory reductions with barriers were slower for both.
// Not measured on a GPU, where the usual shared-memory reduction may win: time it before changing.
struct Reduction {
    int levelsPerDispatch;         // 1..3
    std::array<int, 3> groupSize;  // local_size_x/y/z
};
constexpr Reduction kRgba16f{1, {8, 8, 8}};
constexpr Reduction kRgba8{3, {8, 8, 1}};

// Over the occupied parents: one level per dispatch, one invocation per list entry, in groups of
// the list's dispatch command.
constexpr Reduction kFromList{1, {LIT_INJECT_LIST_GROUP_SIZE, 1, 1}};

std::string definesFor(bool rgba8, bool packed, const Reduction& r, bool fromList = false) {
    const std::pair<const char*, int> values[] = {
        {"LIT_MIP_RGBA8", rgba8 ? 1 : 0},        {"LIT_MIP_PACKED", packed ? 1 : 0},
        {"LIT_MIP_LEVELS", r.levelsPerDispatch}, {"LIT_MIP_GROUP_X", r.groupSize[0]},
        {"LIT_MIP_GROUP_Y", r.groupSize[1]},     {"LIT_MIP_GROUP_Z", r.groupSize[2]},
        {"LIT_MIP_FROM_LIST", fromList ? 1 : 0},
    };
    std::string defines;
    for (const auto& [name, value] : values)
        defines += "#define " + std::string(name) + " " + std::to_string(value) + "\n";
    return defines;
}

// RGBA8 textures may be bound as r32ui images when the driver matches image formats by texel
// size (every desktop GL 4.5 driver we know does; the spec lets it match by class instead).
bool rgba8BindsAsR32ui() {
    GLint compatibility = GL_NONE;
    glGetInternalformativ(GL_TEXTURE_3D, GL_RGBA8, GL_IMAGE_FORMAT_COMPATIBILITY_TYPE, 1, &compatibility);
    return compatibility == GL_IMAGE_FORMAT_COMPATIBILITY_BY_SIZE;
}

int ceilDiv(int a, int b) { return (a + b - 1) / b; }

std::string directionalDefines(bool rgba8, bool fromIso, bool fromList) {
    return std::string("#define LIT_MIP_RGBA8 ") + (rgba8 ? "1" : "0") + "\n#define LIT_DIRECTIONAL_FROM_ISO " +
           (fromIso ? "1" : "0") + "\n#define LIT_MIP_FROM_LIST " + (fromList ? "1" : "0") + "\n";
}

// Byte offset of level k's DispatchIndirectCommand in the parent lists (after its count).
GLintptr parentDispatchOffset(int level) { return static_cast<GLintptr>(16 * level + 4); }

std::string hexFormat(GLenum format) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", format);
    return text;
}

}  // namespace

MipmapPass::MipmapPass(const std::filesystem::path& shaderRoot)
    : rgba8Packed_(rgba8BindsAsR32ui()),
      rgba8_(shaderRoot, "mipmap rgba8", {{GL_COMPUTE_SHADER, "mipmap.comp.glsl"}},
             definesFor(true, rgba8Packed_, kRgba8)),
      rgba16f_(shaderRoot, "mipmap rgba16f", {{GL_COMPUTE_SHADER, "mipmap.comp.glsl"}},
               definesFor(false, false, kRgba16f)),
      directionalFromIso8_(shaderRoot, "directional mipmap rgba8 from level 0",
                           {{GL_COMPUTE_SHADER, "mipmap_directional.comp.glsl"}},
                           directionalDefines(true, true, false)),
      directionalFromIso16f_(shaderRoot, "directional mipmap rgba16f from level 0",
                             {{GL_COMPUTE_SHADER, "mipmap_directional.comp.glsl"}},
                             directionalDefines(false, true, false)),
      directional8_(shaderRoot, "directional mipmap rgba8", {{GL_COMPUTE_SHADER, "mipmap_directional.comp.glsl"}},
                    directionalDefines(true, false, false)),
      directional16f_(shaderRoot, "directional mipmap rgba16f", {{GL_COMPUTE_SHADER, "mipmap_directional.comp.glsl"}},
                      directionalDefines(false, false, false)),
      listRgba8_(shaderRoot, "mipmap rgba8 over occupied parents", {{GL_COMPUTE_SHADER, "mipmap.comp.glsl"}},
                 definesFor(true, rgba8Packed_, kFromList, true)),
      listRgba16f_(shaderRoot, "mipmap rgba16f over occupied parents", {{GL_COMPUTE_SHADER, "mipmap.comp.glsl"}},
                   definesFor(false, false, kFromList, true)),
      listFromIso8_(shaderRoot, "directional mipmap rgba8 from level 0 over occupied parents",
                    {{GL_COMPUTE_SHADER, "mipmap_directional.comp.glsl"}}, directionalDefines(true, true, true)),
      listFromIso16f_(shaderRoot, "directional mipmap rgba16f from level 0 over occupied parents",
                      {{GL_COMPUTE_SHADER, "mipmap_directional.comp.glsl"}}, directionalDefines(false, true, true)),
      listDirectional8_(shaderRoot, "directional mipmap rgba8 over occupied parents",
                        {{GL_COMPUTE_SHADER, "mipmap_directional.comp.glsl"}}, directionalDefines(true, false, true)),
      listDirectional16f_(shaderRoot, "directional mipmap rgba16f over occupied parents",
                          {{GL_COMPUTE_SHADER, "mipmap_directional.comp.glsl"}},
                          directionalDefines(false, false, true)),
      listParents_(shaderRoot, "occupied parents", {{GL_COMPUTE_SHADER, "mipmap_parents.comp.glsl"}}) {}

void MipmapPass::listOccupiedParents(VoxelVolume& volume) {
    const int n = volume.resolution();
    if (n < 2 || !volume.occupiedList()) return;
    volume.ensureParentLists();
    const VoxelVolume::ParentLayout& layout = volume.parentLayout();
    const gl::Buffer& parents = volume.parentLists();
    // Every level: count 0, dispatch 0 × 1 × 1; every bitmask zero.
    std::array<std::uint32_t, 4 * LIT_MIP_LIST_LEVELS> header{};
    for (int level = 0; level < LIT_MIP_LIST_LEVELS; ++level) {
        header[static_cast<std::size_t>(4 * level + 2)] = 1u;
        header[static_cast<std::size_t>(4 * level + 3)] = 1u;
    }
    glNamedBufferSubData(parents.id(), 0, sizeof header, header.data());
    const GLuint zero = 0;
    glClearNamedBufferSubData(
        parents.id(), GL_R32UI,
        static_cast<GLintptr>(VoxelVolume::kParentHeaderBytes + std::size_t{4} * layout.maskBegin),
        static_cast<GLsizeiptr>(std::size_t{4} * layout.maskWords), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);

    const gl::Program& program = listParents_;
    program.use();
    volume.occupiedList().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_OCCUPIED_VOXELS);
    parents.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_MIP_PARENTS);
    glProgramUniform1ui(program.id(), program.location("uOccupiedCapacity"), volume.occupiedCapacity());
    const int levels = std::min(volume.mipCount(), LIT_MIP_LIST_LEVELS);
    for (int level = 1; level < levels; ++level) {
        const auto k = static_cast<std::size_t>(level);
        glProgramUniform1i(program.id(), program.location("uLevel"), level);
        glProgramUniform1ui(program.id(), program.location("uChildList"), level > 1 ? layout.listOffset[k - 1] : 0u);
        glProgramUniform1ui(program.id(), program.location("uList"), layout.listOffset[k]);
        glProgramUniform1ui(program.id(), program.location("uMask"), layout.maskOffset[k]);
        glProgramUniform1i(program.id(), program.location("uEdge"), std::max(n >> level, 1));
        // Level k's children: the voxelizer's list (its command follows the count) or level k−1's.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        const gl::Buffer& children = level == 1 ? volume.occupiedList() : parents;
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, children.id());
        glDispatchComputeIndirect(level == 1 ? 4 : parentDispatchOffset(level - 1));
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    volume.setParentListsValid(true);
}

void MipmapPass::execute(VoxelVolume& volume, bool anisotropic, bool overOccupiedParents) {
    if (overOccupiedParents && volume.parentListsValid())
        executeOverParents(volume);
    else
        execute(volume.radiance());
    if (anisotropic) executeDirectional(volume, overOccupiedParents);
}

void MipmapPass::executeOverParents(const VoxelVolume& volume) {
    const gl::Texture& radiance = volume.radiance();
    const bool rgba8 = volume.radianceRgba8();
    const gl::Program& program = rgba8 ? listRgba8_ : listRgba16f_;
    const GLenum imageFormat = rgba8 ? (rgba8Packed_ ? GL_R32UI : GL_RGBA8) : GL_RGBA16F;
    const GLint listLocation = program.location("uParentList");
    const int levels = std::min({radiance.desc().levels, volume.mipCount(), LIT_MIP_LIST_LEVELS});
    // Level 0 may just have been written with imageStore; the lists with a compute shader.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    program.use();
    volume.parentLists().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_MIP_PARENTS);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, volume.parentLists().id());
    for (int level = 1; level < levels; ++level) {
        glBindImageTexture(LIT_IMG_MIP_SOURCE, radiance.id(), level - 1, GL_TRUE, 0, GL_READ_ONLY, imageFormat);
        glBindImageTexture(LIT_IMG_MIP_DEST, radiance.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, imageFormat);
        glProgramUniform2i(program.id(), listLocation, level,
                           static_cast<GLint>(volume.parentLayout().listOffset[static_cast<std::size_t>(level)]));
        glDispatchComputeIndirect(parentDispatchOffset(level));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // the next level reads this one
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

// Uses `program` for level `level` ≥ 1 of face `face`'s directional volume: binds that level as
// the destination and level − 1 as its source, and sets the face's region. Returns the level's
// edge in texels.
int MipmapPass::useDirectionalLevel(const gl::Program& program, const VoxelVolume& volume, int face, int level) {
    const gl::Texture& target = volume.directional(face / 2);
    const GLenum format = volume.radianceFormat();
    program.use();
    glBindImageTexture(LIT_IMG_MIP_SOURCE, target.id(), level - 1, GL_TRUE, 0, GL_READ_ONLY, format);
    glBindImageTexture(LIT_IMG_MIP_DEST, target.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, format);
    // The face's region: edge³ texels at x offset 2·edge for the −axis face (VoxelVolume.h).
    const int edge = std::max(target.desc().height >> level, 1);
    const bool negative = face % 2 == 1;
    glProgramUniform3i(program.id(), program.location("uFace"), face / 2, face % 2, edge);
    glProgramUniform2i(program.id(), program.location("uOffsets"), negative ? 4 * edge : 0, negative ? 2 * edge : 0);
    return edge;
}

// Uses `program` for level 0 of all six faces (from the isotropic level 0 and the normals).
// Returns the level's edge in texels.
int MipmapPass::useDirectionalLevel0(const gl::Program& program, const VoxelVolume& volume) {
    const GLenum format = volume.radianceFormat();
    program.use();
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_MIP_SOURCE, volume.radiance().id(), 0, GL_TRUE, 0, GL_READ_ONLY, format);
    constexpr std::array<GLuint, LIT_VOXEL_AXIS_COUNT> kDestUnits{LIT_IMG_MIP_DEST, LIT_IMG_MIP_DEST2,
                                                                  LIT_IMG_MIP_DEST3};
    for (int axis = 0; axis < LIT_VOXEL_AXIS_COUNT; ++axis)
        glBindImageTexture(kDestUnits[static_cast<std::size_t>(axis)], volume.directional(axis).id(), 0, GL_TRUE, 0,
                           GL_WRITE_ONLY, format);
    const int edge = volume.directional(0).desc().height;
    glProgramUniform1i(program.id(), program.location("uEdge"), edge);
    return edge;
}

void MipmapPass::executeDirectionalOverParents(const VoxelVolume& volume) {
    const bool rgba8 = volume.radianceRgba8();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    volume.parentLists().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_MIP_PARENTS);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, volume.parentLists().id());
    // Directional level L mirrors radiance level L + 1: its voxels are that level's parents.
    const auto useParents = [&](const gl::Program& program, int level) {
        const int radianceLevel = level + 1;
        glProgramUniform2i(
            program.id(), program.location("uParentList"), radianceLevel,
            static_cast<GLint>(volume.parentLayout().listOffset[static_cast<std::size_t>(radianceLevel)]));
        glDispatchComputeIndirect(parentDispatchOffset(radianceLevel));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    };
    const gl::Program& fromIso = rgba8 ? listFromIso8_ : listFromIso16f_;
    useDirectionalLevel0(fromIso, volume);
    useParents(fromIso, 0);
    for (int face = 0; face < LIT_VOXEL_FACE_COUNT; ++face) {
        const gl::Texture& target = volume.directional(face / 2);
        const int levels = std::min(target.desc().levels, LIT_MIP_LIST_LEVELS - 1);
        for (int level = 1; level < levels; ++level) {
            const gl::Program& program = rgba8 ? listDirectional8_ : listDirectional16f_;
            useDirectionalLevel(program, volume, face, level);
            useParents(program, level);
        }
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void MipmapPass::executeDirectional(VoxelVolume& volume, bool overOccupiedParents) {
    const int n = volume.resolution();
    if (n < 2) return;
    volume.ensureDirectionalVolumes();
    if (overOccupiedParents && volume.parentListsValid()) {
        // Voxels off the lists keep what they hold: zero them once after a voxelization.
        if (volume.directionalStale()) volume.clearDirectional();
        volume.setDirectionalStale(false);
        executeDirectionalOverParents(volume);
        return;
    }
    volume.setDirectionalStale(false);  // every voxel is written below
    const bool rgba8 = volume.radianceRgba8();
    constexpr int kGroup = 4;  // mipmap_directional.comp.glsl: 4×4×4 work groups
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    {
        const gl::Program& fromIso = rgba8 ? directionalFromIso8_ : directionalFromIso16f_;
        const auto groups = static_cast<GLuint>(ceilDiv(useDirectionalLevel0(fromIso, volume), kGroup));
        glDispatchCompute(groups, groups, groups);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    for (int face = 0; face < LIT_VOXEL_FACE_COUNT; ++face) {
        const gl::Texture& target = volume.directional(face / 2);
        for (int level = 1; level < target.desc().levels; ++level) {
            const gl::Program& program = rgba8 ? directional8_ : directional16f_;
            const int edge = useDirectionalLevel(program, volume, face, level);
            const auto groups = static_cast<GLuint>(ceilDiv(edge, kGroup));
            glDispatchCompute(groups, groups, groups);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void MipmapPass::execute(const gl::Texture& volume) {
    const gl::TextureDesc& desc = volume.desc();
    if (!volume || desc.target != GL_TEXTURE_3D) throw gl::GlError("MipmapPass: the volume must be a GL_TEXTURE_3D");
    if (desc.format != GL_RGBA8 && desc.format != GL_RGBA16F)
        throw gl::GlError("MipmapPass: the volume must be GL_RGBA8 or GL_RGBA16F, not format " +
                          hexFormat(desc.format));
    const int n = desc.width;
    if (desc.height != n || desc.depth != n || n < 1 || !std::has_single_bit(static_cast<unsigned>(n)))
        throw gl::GlError("MipmapPass: the volume must be a cube with a power-of-two side, not " +
                          std::to_string(desc.width) + "×" + std::to_string(desc.height) + "×" +
                          std::to_string(desc.depth));
    const int levels = std::min(desc.levels, gl::Texture::mipCount(n, n, n));
    if (levels < 2) return;

    const bool rgba8 = desc.format == GL_RGBA8;
    const Reduction& reduction = rgba8 ? kRgba8 : kRgba16f;
    const gl::Program& program = rgba8 ? rgba8_ : rgba16f_;
    const GLenum imageFormat = rgba8 ? (rgba8Packed_ ? GL_R32UI : GL_RGBA8) : GL_RGBA16F;
    const GLint dispatchLocation = program.location("uDispatch");
    constexpr std::array<GLuint, 3> kDestUnits{LIT_IMG_MIP_DEST, LIT_IMG_MIP_DEST2, LIT_IMG_MIP_DEST3};

    // Level 0 may just have been written with imageStore (radiance injection).
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    program.use();
    for (int source = 0; source + 1 < levels;) {
        const int count = std::min(reduction.levelsPerDispatch, levels - 1 - source);
        glBindImageTexture(LIT_IMG_MIP_SOURCE, volume.id(), source, GL_TRUE, 0, GL_READ_ONLY, imageFormat);
        // Units past `count` are not written this time; they get the last level so every image
        // the shader declares is bound to something valid.
        for (int i = 0; i < static_cast<int>(kDestUnits.size()); ++i)
            glBindImageTexture(kDestUnits[i], volume.id(), source + 1 + std::min(i, count - 1), GL_TRUE, 0,
                               GL_WRITE_ONLY, imageFormat);
        // One invocation per voxel of the last level this dispatch writes.
        const int lastEdge = std::max(n >> (source + count), 1);
        glProgramUniform2i(program.id(), dispatchLocation, lastEdge, count);
        glDispatchCompute(static_cast<GLuint>(ceilDiv(lastEdge, reduction.groupSize[0])),
                          static_cast<GLuint>(ceilDiv(lastEdge, reduction.groupSize[1])),
                          static_cast<GLuint>(ceilDiv(lastEdge, reduction.groupSize[2])));
        // The next dispatch reads what this one wrote.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        source += count;
    }
    // Cone tracing samples the levels through a sampler.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace lit
