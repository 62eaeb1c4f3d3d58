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
// (resetHistory) on scene edits and when what the terms mean changes. The targets and history are
// kept per size for two sizes (TargetsBySize): the editor's interactive render scale switches to a
// small size while the camera moves and back when it stops, and the still frame then finds its
// size's history (with the camera it was written with) and its targets instead of starting afresh
// and reallocating them (docs/PERFORMANCE.md, "Editor").

#include <cstdint>
#include <glm/glm.hpp>

#include "gl/ProgramVariants.h"
#include "passes/ConeTracePass.h"
#include "passes/MaterialLayersVariant.h"
#include "passes/Pass.h"
#include "passes/TargetsBySize.h"

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
    // settings.indirect.temporalAccumulation the history of the last temporal frame at this size is blended
    // in when it is valid (no reset since), reprojected with the view-projection of the frame that
    // wrote it; `viewProjection` is this frame's (world → clip), kept with the history it writes.
    // `materialLayers`: as ConeTracePass::execute.
    void execute(const LightingTerms& terms, ConeTracePass& cone, const VoxelVolume& volume,
                 const RenderSettings& settings, const ConeTracePass::Sampling& sampling,
                 const glm::mat4& viewProjection, bool materialLayers = true);

    // The next frame starts without history (scene edit, settings that change the terms), at
    // every size.
    void resetHistory() { ++generation_; }

    std::vector<gl::Program*> programs() override {
        std::vector<gl::Program*> out;
        program_.appendBuilt(out);
        plainProgram_.appendBuilt(out);
        return out;
    }

    // How far the history's clamp box (this frame's low-resolution neighbours) is widened, as a
    // fraction of its bounds: 10 %, or kSubsetClampMargin when the accurate mode traces cone
    // subsets (`sampling.coneSubset` ≥ 0 with footprint-bounded cones). There the strata filter
    // averages each texel with its neighbours, so the neighbours of a pixel all hold the same
    // frame's pairs of side cones, off the whole sets' value by up to ~2× in places (Cornell box,
    // 96², 64³), and a 10 % box held the history to the current frame's pairs (docs/GI.md, "Cone
    // subsets").
    static constexpr float kClampMargin = 0.1f;
    static constexpr float kSubsetClampMargin = 3.0f;
    static float clampMargin(const RenderSettings& settings, const ConeTracePass::Sampling& sampling);

    // For IndirectFallbackPass, after execute() of this frame: binds the framebuffer execute()
    // wrote (its depth attachment is the trace mask), the textures it read, and sets on `program`
    // the uniforms execute() used. Returns false when execute() wrote no terms this frame.
    bool bindForFallback(const gl::Program& program) const;

private:
    struct HistorySet {
        gl::Texture diffuse, specular, guide;
        gl::Framebuffer target;  // L_ID, L_IS of the terms, then these three; depth: the trace mask
    };
    // Everything of one size (TargetsBySize swaps it whole).
    struct Targets {
        int width = 0, height = 0;
        // Trace mask: 16-bit depth, only 0 (trace here) and 1 are written.
        gl::Texture traceMask;
        gl::Framebuffer plainTarget;  // without temporal accumulation: L_ID, L_IS and the trace mask
        HistorySet history[2];        // allocated by the first temporal frame at this size
        GLuint termIds[2] = {0, 0};   // term textures the framebuffers were built with
        int current = 0;              // set written last; the other one is read next
        bool historyWritten = false;  // a temporal frame wrote history[current] ...
        std::uint64_t generation = 0;  // ... while generation_ had this value ...
        glm::mat4 viewProjection{1.0f};  // ... with this camera
    };
    // What execute() drew with, for bindForFallback.
    struct Inputs {
        bool ran = false;
        const Targets* targets = nullptr;
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
        float clampMargin = kClampMargin;
        glm::mat4 previousViewProjection{1.0f};
    };
    // The targets of the terms' size, (re)built as needed; with `temporal` the history sets too.
    Targets& targetsFor(const LightingTerms& terms, bool temporal);
    static bool historyUsable(const Targets& t, std::uint64_t generation) {
        return t.historyWritten && t.generation == generation;
    }
    void bindInputs(const gl::Program& program) const;

    gl::ProgramVariants<MaterialLayersVariant::kVariants> program_;
    // Without temporal accumulation: no history code (LIT_RESOLVE_HISTORY 0).
    gl::ProgramVariants<MaterialLayersVariant::kVariants> plainProgram_;
    FullscreenTriangle triangle_;
    TargetsBySize<Targets> targets_;
    Inputs last_;
    std::uint64_t generation_ = 1;  // resetHistory counts up: history of an older one is stale
};

}  // namespace lit
