#include "passes/VoxelDebugPass.h"

#include <shared.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "gi/VoxelVolume.h"
#include "passes/VoxelLevelColors.h"

namespace lit {

namespace {
constexpr int kDecodeGroupSize = 8;  // voxel_debug_decode.comp.glsl: 8×8×8 voxels per work group

int toShaderChannel(VoxelChannel channel) {
    switch (channel) {
        case VoxelChannel::Radiance: return LIT_VOXEL_CHANNEL_RADIANCE;
        case VoxelChannel::Albedo: return LIT_VOXEL_CHANNEL_ALBEDO;
        case VoxelChannel::Normal: return LIT_VOXEL_CHANNEL_NORMAL;
        case VoxelChannel::Opacity: return LIT_VOXEL_CHANNEL_OPACITY;
        case VoxelChannel::Emission: return LIT_VOXEL_CHANNEL_EMISSION;
    }
    return LIT_VOXEL_CHANNEL_RADIANCE;
}

bool readsRadianceVolume(VoxelChannel channel) {
    return channel == VoxelChannel::Radiance || channel == VoxelChannel::Opacity;
}
// A voxel view with no volume (GI off) is black.
void clearToBlack() {
    const float black[4] = {0, 0, 0, 1};
    glClearBufferfv(GL_COLOR, 0, black);
}
}  // namespace

bool isVoxelView(View view) { return view == View::Voxels || view == View::VoxelSlice || view == View::VoxelLevels; }

VoxelDebugPass::VoxelDebugPass(const std::filesystem::path& shaderRoot)
    : view_(shaderRoot, "voxel debug",
            {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "voxel_debug.frag.glsl"}}),
      decode_(shaderRoot, "voxel debug decode", {{GL_COMPUTE_SHADER, "voxel_debug_decode.comp.glsl"}}),
      levels_(shaderRoot, "voxel levels",
              {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "voxel_levels.frag.glsl"}}) {}

int VoxelDebugPass::mipLevel(const RenderSettings& settings, const VoxelVolume& volume) {
    return std::clamp(settings.debug.voxelMip, 0, std::max(volume.mipCount() - 1, 0));
}

int VoxelDebugPass::sliceIndex(const RenderSettings& settings, const VoxelVolume& volume) {
    const int side = std::max(volume.resolution() >> mipLevel(settings, volume), 1);
    const float position = std::clamp(settings.debug.voxelSlice, 0.0f, 1.0f);
    return std::clamp(static_cast<int>(std::floor(position * static_cast<float>(side))), 0, side - 1);
}

void VoxelDebugPass::decode(const VoxelVolume& volume, VoxelChannel channel, std::uint64_t voxelGeneration) {
    const int n = volume.resolution();
    if (decoded_ && decodedResolution_ == n && decodedChannel_ == channel && decodedGeneration_ == voxelGeneration &&
        decodedVolume_ == &volume)
        return;
    if (!decoded_ || decodedResolution_ != n) {
        decoded_ = gl::Texture("voxel debug channel",
                               {GL_TEXTURE_3D, GL_RGBA16F, n, n, n, gl::Texture::mipCount(n, n, n)});
        decodedResolution_ = n;
    }
    decode_.use();
    decode_.set("uChannel", toShaderChannel(channel));
    glBindImageTexture(LIT_IMG_VOXEL_ALBEDO, volume.albedo().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_EMISSION, volume.emission().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    glBindImageTexture(LIT_IMG_MIP_DEST, decoded_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const auto groups = static_cast<GLuint>((n + kDecodeGroupSize - 1) / kDecodeGroupSize);
    glDispatchCompute(groups, groups, groups);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    // A box filter is the right mip here: the values are premultiplied by occupancy.
    glGenerateTextureMipmap(decoded_.id());
    decodedChannel_ = channel;
    decodedGeneration_ = voxelGeneration;
    decodedVolume_ = &volume;
}

void VoxelDebugPass::execute(const RenderSettings& settings, const VoxelVolume* volume,
                             std::uint64_t voxelGeneration) {
    glDisable(GL_DEPTH_TEST);
    if (!volume || volume->resolution() <= 0) {
        clearToBlack();
        return;
    }
    const VoxelChannel channel = settings.debug.voxelChannel;
    if (!readsRadianceVolume(channel)) decode(*volume, channel, voxelGeneration);
    const gl::Texture& source = readsRadianceVolume(channel) ? volume->radiance() : decoded_;

    view_.use();
    volume->uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    source.bind(LIT_TEX_DEBUG_INPUT);
    view_.set("uSlice", settings.debug.view == View::VoxelSlice ? 1 : 0);
    view_.set("uChannel", toShaderChannel(channel));
    view_.set("uMip", mipLevel(settings, *volume));
    view_.set("uAxis", std::clamp(settings.debug.voxelSliceAxis, 0, 2));
    view_.set("uSliceIndex", sliceIndex(settings, *volume));
    triangle_.draw();
}

void VoxelDebugPass::executeLevels(std::span<const VoxelVolume* const> volumes) {
    glDisable(GL_DEPTH_TEST);
    const std::size_t count = std::min<std::size_t>(volumes.size(), LIT_MAX_NEAR_LEVELS + 1);
    if (count == 0) {
        clearToBlack();
        return;
    }
    levels_.use();
    const GLuint program = levels_.id();
    const auto at = [&](const char* name, std::size_t k) {
        return levels_.location((std::string(name) + "[" + std::to_string(k) + "]").c_str());
    };
    for (std::size_t k = 0; k < count; ++k) {
        const VoxelVolume& volume = *volumes[k];
        volume.radiance().bind(static_cast<GLuint>(LIT_TEX_DEBUG_LEVELS_FIRST + k));
        const glm::vec3 corner = volume.minCorner();
        glProgramUniform4f(program, at("uVolume", k), corner.x, corner.y, corner.z, volume.voxelSize());
        glProgramUniform1i(program, at("uResolution", k), volume.resolution());
        // The last is the scene's volume; the others near levels 1, 2, ... from the finest.
        const glm::vec3 color = voxelLevelColor(k + 1 == count ? 0 : static_cast<int>(k) + 1);
        glProgramUniform3f(program, at("uColor", k), color.r, color.g, color.b);
    }
    // Every unit the shader's array declares is bound to a 3D texture (the unused ones never read).
    for (std::size_t k = count; k < LIT_MAX_NEAR_LEVELS + 1; ++k)
        volumes[0]->radiance().bind(static_cast<GLuint>(LIT_TEX_DEBUG_LEVELS_FIRST + k));
    levels_.set("uVolumeCount", static_cast<int>(count));
    triangle_.draw();
}

}  // namespace lit
