#pragma once
// Viewport overlay: what the editor draws into the image itself, after tone mapping, into the
// sRGB output texture (the HDR image stays clean for --hdr, tests and screenshots of terms):
//  1. the selection outline: pixels within 2 px outside the highlighted node's visible pixels
//     turn orange (a full-screen edge test on the G-buffer's node IDs);
//  2. depth-tested lines (markers, debug cones): tested against the G-buffer depth in the
//     fragment shader; the parts behind the scene are drawn faint instead of hidden;
//  3. lines on top (the gizmo): never hidden.
// Lines are 1 px GL_LINES (core profile guarantees no wider lines), alpha-blended.

#include "Overlay.h"
#include "passes/Pass.h"
#include "scene/Aabb.h"

#include <glm/glm.hpp>
#include <shared.h>

#include <cstddef>

namespace lit {

class GBufferPass;

class OverlayPass : public Pass {
public:
    explicit OverlayPass(const std::filesystem::path& shaderRoot);

    // Draws `overlay` into the bound framebuffer (the tone-mapped sRGB image, the G-buffer's size,
    // viewport set: PostPass::bindOutputTarget). Expects the frame UBO of the frame that filled
    // `gbuffer` bound. `highlightBounds` is the world box of overlay.highlightNode (empty: nothing
    // to outline) and `viewProjection` the frame's: the outline pass runs only over the box's
    // projection (it costs ~20 texel reads per pixel).
    void execute(const ViewportOverlay& overlay, const GBufferPass& gbuffer, const Aabb& highlightBounds,
                 const glm::mat4& viewProjection);

    // Pixels (x, y, width, height; GL bottom-up) that the projection of `box` covers, grown by
    // `margin` pixels and clipped to the image; the whole image when the box reaches behind the
    // eye, width 0 when it is empty or off screen.
    static glm::ivec4 screenRect(const Aabb& box, const glm::mat4& viewProjection, int width, int height, int margin);

    std::vector<gl::Program*> programs() override { return {&outline_, &lines_}; }

    // Selection outline colour: sRGB (255, 140, 0) as linear RGB (the target encodes it back).
    static constexpr float kOutlineColor[4] = {1.0f, 0.2623f, 0.0f, 1.0f};
    // Opacity multiplier of depth-tested lines where the scene hides them.
    static constexpr float kHiddenLineOpacity = static_cast<float>(LIT_HIDDEN_LINE_OPACITY);
    static constexpr int kOutlineRadius = LIT_OUTLINE_RADIUS;  // outline width (pixels)

private:
    struct LineVertex {
        float position[3];  // world (m)
        float color[4];     // linear RGBA
    };
    // Uploads both line lists (depth-tested first) into vertices_, growing it when needed.
    void uploadLines(const ViewportOverlay& overlay);
    void drawLines(GLint first, GLsizei vertexCount, bool depthTested);

    gl::Program outline_, lines_;
    FullscreenTriangle triangle_;
    gl::Buffer vertices_;
    std::size_t vertexCapacity_ = 0;
    gl::VertexArray vertexArray_;
    std::vector<LineVertex> staging_;
};

}  // namespace lit
