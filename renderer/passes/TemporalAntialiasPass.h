#pragma once
// Temporal anti-aliasing (docs/ARCHITECTURE.md, "Anti-aliasing"). The rasterizer samples each
// pixel at one point, so edges, shadow edges and highlights smaller than a pixel alias and crawl
// as the camera moves, while the reference averages each pixel's area. Each frame is drawn with a
// sub-pixel offset (jitter(): the projection moves by a point of the Halton (2, 3) sequence, the
// first frame after a reset by none) and the composite's HDR image is blended with the history of
// the frames before (taa_resolve.frag.glsl):
//
//   history_n = history_{n−1}(reprojected) + (current − history_{n−1}(reprojected)) / min(n, N)
//
// With the camera and the scene still, nothing is clamped: after N frames each pixel holds the
// mean of N samples spread over its area, and later frames keep it (they would repeat the cycle). When the camera
// or a node moves, each pixel reads the history where its surface point was in the last frame (bilinear): the point
// moved back by its node's motion (the G-buffer's motion target) and seen through the last frame's camera. It is
// clamped to the range of this frame's 3 × 3 neighbourhood, so what the last frame saw elsewhere (a disocclusion, a
// shadow that moved with its node) does not trail. With the camera and the nodes still, a change of what is drawn (an
// edit, other settings, the GI's light while an update or its refinement runs) starts the cycle and the history
// again: such a frame is drawn at the pixel centres and shown alone, as without anti-aliasing, so an edit shows at
// once instead of fading in and light that converges over frames is not blended with itself.

#include <cstdint>
#include <glm/glm.hpp>

#include "RenderSettings.h"
#include "passes/Pass.h"
#include "passes/TargetsBySize.h"

namespace lit {

class TemporalAntialiasPass : public Pass {
public:
    explicit TemporalAntialiasPass(const std::filesystem::path& shaderRoot);

    // The jitter offset of sample `index` of a cycle of `frames`, in pixels within [−½, ½]²:
    // (0, 0) for index 0, then the Halton (2, 3) points 1, 2, ... minus ½ (index taken mod frames).
    static glm::vec2 sampleOffset(std::uint32_t index, int frames);
    // `projection` moved by `offsetPixels` on a `width` × `height` image (clip x, y += 2·offset/size · w).
    static glm::mat4 jittered(const glm::mat4& projection, glm::vec2 offsetPixels, int width, int height);

    // Whether the settings draw this frame through the pass (on, and a lit view: the data, voxel
    // and flat views show values, not light to average).
    static bool applies(const RenderSettings& settings);
    // OutputSettings::antialiasingFrames within 1..kMaxFrames.
    static constexpr int kMaxFrames = 64;
    static int frames(const RenderSettings& settings);

    struct FrameStart {
        glm::mat4 viewProjection{1.0f};  // this frame's camera, without the jitter
        // What is drawn changed since the last frame (the scene's revisions, the render settings),
        // or the GI's light was still changing in it.
        bool changed = false;
        // Nodes moved since the last frame and nothing else changed in the scene (a node animation
        // playing, a gizmo drag): the history follows them through the G-buffer's motion target.
        bool nodesMoved = false;
    };
    // Before the frame is drawn: the offset it uses, in pixels ((0, 0) when the pass does not
    // apply, or when the camera is still and `frame.changed`: the cycle starts again).
    glm::vec2 begin(const RenderSettings& settings, const FrameStart& frame);
    // Blends `hdr` (the composite, RGBA32F, written back in place) with the history, reading
    // `depth` (the G-buffer's, window space) for each pixel's point and, when begin() was told the
    // nodes moved, `motion` (the G-buffer's) for how far it moved. `giChanged`: the GI's light
    // changed during this frame. Needs the frame UBO bound; after begin() for the same frame.
    void execute(const RenderSettings& settings, const gl::Texture& hdr, const gl::Texture& depth,
                 const gl::Texture& motion, bool giChanged);
    // The next frame starts without history and at the cycle's first sample (a new scene, a view
    // the pass does not apply to).
    void reset();

    // Frames in the history after the last execute (1 after a reset; at most antialiasingFrames).
    int historyFrames() const { return historyFrames_; }

    std::vector<gl::Program*> programs() override { return {&still_, &moving_}; }

private:
    gl::Program still_, moving_;  // taa_resolve.frag.glsl, LIT_TAA_MOVING 0 and 1
    FullscreenTriangle triangle_;
    gl::Sampler linearSampler_;
    struct Targets {
        // RGBA32F, the resolved images of the last frame and this one (they swap each frame): the
        // composite's format, so the result is copied back into it whole.
        gl::Texture history[2];
        gl::Framebuffer framebuffer[2];
        gl::Texture depth;               // the G-buffer's depth of the frame written last (DEPTH_COMPONENT32F)
        int current = 0;                 // the one written last
        glm::mat4 viewProjection{1.0f};  // the unjittered camera it was written with
        std::uint64_t generation = 0;    // 0: never written
        int width = 0, height = 0;
    };
    TargetsBySize<Targets> targets_;
    std::uint64_t generation_ = 1;  // reset() counts up: older history is stale
    std::uint32_t sample_ = 0;      // the frame's place in the cycle
    int historyFrames_ = 0;
    // begin()'s decisions for execute().
    glm::mat4 viewProjection_{1.0f};
    bool moved_ = false, restart_ = true;
    bool nodesMoved_ = false;
    bool movedLast_ = false;  // the last frame's camera had moved
};

}  // namespace lit
