#pragma once
// Indirect resolve: turns ConeTracePass's low-resolution demodulated trace into the full-
// resolution indirect terms L_ID and L_IS (indirect_resolve.frag.glsl): joint bilateral
// (depth- and normal-aware) upsampling and temporal accumulation of both terms in one full-screen
// pass, so the upsampled image is never written and read again (docs/GI.md, "Reduced resolution
// and temporal accumulation"). Pixels where no neighbour stands for the pixel, or whose surface
// is too smooth for reduced resolution, are marked in a trace mask (a depth buffer: 0 = trace
// here) for IndirectFallbackPass, which traces them per pixel with the same upsampling and
// accumulation; the resolve itself has no cone code (which cost llvmpipe about half its time).
//
// History: two sets (ping-pong) of full-resolution textures, demodulated diffuse and specular
// (a = frames accumulated) and a guide (normal, clip w) for the rejection test. It is dropped
// (resetHistory) on scene edits and when what the terms mean changes; a resize drops it too.

#include <cstdint>
#include <glm/glm.hpp>

#include "passes/ConeTracePass.h"
#include "passes/Pass.h"

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

    // For IndirectFallbackPass, after execute() of this frame: binds the framebuffer execute()
    // wrote (its depth attachment is the trace mask), the textures it read, and sets on `program`
    // the uniforms execute() used. Returns false when execute() wrote no terms this frame.
    bool bindForFallback(const gl::Program& program) const;

private:
    // What execute() drew with, for bindForFallback.
    struct Inputs {
        bool ran = false;
        const gl::Framebuffer* target = nullptr;
        ConeTracePass* cone = nullptr;
        const VoxelVolume* volume = nullptr;
        int history = -1;  // history set read, -1: none
        glm::ivec2 traceTerms{0};
        float smoothRoughness = 0.0f;
        int scale = 1;
        ConeTracePass::Sampling sampling;
        bool historyValid = false;
        int maxFrames = 1;
        glm::mat4 previousViewProjection{1.0f};
    };
    void ensureTargets(const LightingTerms& terms);
    void ensureHistory(const LightingTerms& terms);
    void bindInputs(const gl::Program& program) const;

    gl::Program program_;
    FullscreenTriangle triangle_;
    // Trace mask: 16-bit depth, only 0 (trace here) and 1 are written.
    gl::Texture traceMask_;
    gl::Framebuffer plainTarget_;  // without temporal accumulation: L_ID, L_IS and the trace mask
    Inputs last_;
    struct HistorySet {
        gl::Texture diffuse, specular, guide;
        gl::Framebuffer target;  // L_ID, L_IS of the terms, then these three; depth: the trace mask
    };
    HistorySet history_[2];
    int current_ = 0;  // set written this frame; the other one is read
    int width_ = 0, height_ = 0;
    GLuint termIds_[2] = {0, 0};       // term textures the history targets were built with
    GLuint plainTermIds_[2] = {0, 0};  // and the plain target
    bool historyValid_ = false;
};

}  // namespace lit
