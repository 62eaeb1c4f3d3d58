#pragma once
// Indirect resolve: turns ConeTracePass's low-resolution demodulated trace into the full-
// resolution indirect terms L_ID and L_IS (indirect_resolve.frag.glsl): joint bilateral
// (depth- and normal-aware) upsampling, a per-pixel trace where no neighbour stands for a pixel
// or the surface is too smooth for reduced resolution, and temporal accumulation of both terms.
// One full-screen pass does all three, so the upsampled image is never written and read again
// (docs/GI.md, "Reduced resolution and temporal accumulation").
//
// History: two sets (ping-pong) of full-resolution textures, demodulated diffuse and specular
// (a = frames accumulated) and a guide (normal, clip w) for the rejection test. It is dropped
// (resetHistory) on scene edits and when what the terms mean changes; a resize drops it too.

#include "passes/ConeTracePass.h"
#include "passes/Pass.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace lit {

class LightingTerms;
class VoxelVolume;
struct RenderSettings;

class IndirectResolvePass : public Pass {
public:
    explicit IndirectResolvePass(const std::filesystem::path& shaderRoot);

    // Writes terms.indirectFramebuffer()'s two attachments from cone.lowPacked()/lowGuide()
    // (ConeTracePass::executeReduced of this frame with the same settings and `sampling`).
    // Expects bound as for ConeTracePass: the G-buffer, the frame UBO (this frame's camera), the
    // voxel UBO; binds the radiance volume and albedo table itself. With
    // settings.temporalAccumulation the history of the last frame is blended in when it is valid
    // (same size, no reset since), reprojected with `previousViewProjection`.
    void execute(const LightingTerms& terms, ConeTracePass& cone, const VoxelVolume& volume,
                 const RenderSettings& settings, const ConeTracePass::Sampling& sampling,
                 const glm::mat4& previousViewProjection);

    // The next frame starts without history (scene edit, settings that change the terms).
    void resetHistory() { historyValid_ = false; }
    bool historyValid() const { return historyValid_; }

    std::vector<gl::Program*> programs() override { return {&program_}; }

private:
    void ensureHistory(const LightingTerms& terms);

    gl::Program program_;
    FullscreenTriangle triangle_;
    struct HistorySet {
        gl::Texture diffuse, specular, guide;
        gl::Framebuffer target;  // L_ID, L_IS of the terms, then these three
    };
    HistorySet history_[2];
    int current_ = 0;               // set written this frame; the other one is read
    int width_ = 0, height_ = 0;
    GLuint termIds_[2] = {0, 0};    // term textures the targets were built with
    bool historyValid_ = false;
};

}  // namespace lit
