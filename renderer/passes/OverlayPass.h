#pragma once
// Viewport overlay: what the editor draws into the image itself, after tone mapping, into the
// sRGB output texture (the HDR image stays clean for --hdr, tests and screenshots of terms):
//  1. the selection outline: pixels within 2 px outside the outlined nodes' visible pixels turn
//     orange, light orange next to the active node (an edge test on the G-buffer's node IDs,
//     over the outlined nodes' screen rectangle only);
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
#include <cstdint>
#include <vector>

namespace lit {

class GBufferPass;

class OverlayPass : public Pass {
public:
    explicit OverlayPass(const std::filesystem::path& shaderRoot);

    // Draws `overlay` into the bound framebuffer (the tone-mapped sRGB image, the G-buffer's size,
    // viewport set: PostPass::bindOutputTarget). Expects the frame UBO of the frame that filled
    // `gbuffer` bound. `outlineBounds` is the world box of the outlined nodes (empty: nothing to
    // outline) and `viewProjection` the frame's: the outline pass runs only over the box's
    // projection (it costs ~20 texel reads per pixel).
    void execute(const ViewportOverlay& overlay, const GBufferPass& gbuffer, const Aabb& outlineBounds,
                 const glm::mat4& viewProjection);

    // Per node ID (index + 1): 0 not outlined, 1 selected, 2 active; as long as the largest
    // outlined ID + 1 (empty when nothing is outlined). What the outline shader reads.
    static std::vector<std::uint32_t> outlineClasses(const ViewportOverlay& overlay);

    // Pixels (x, y, width, height; GL bottom-up) that the projection of `box` covers, grown by
    // `margin` pixels and clipped to the image; the whole image when the box reaches behind the
    // eye, width 0 when it is empty or off screen.
    static glm::ivec4 screenRect(const Aabb& box, const glm::mat4& viewProjection, int width, int height, int margin);

    std::vector<gl::Program*> programs() override { return {&outline_, &lines_}; }

    // Outline colours as linear RGB (the target encodes them back): the active node sRGB
    // (255, 140, 0), the other selected nodes a darker sRGB (230, 80, 0), as Blender tells them apart.
    static constexpr float kOutlineColor[4] = {1.0f, 0.2623f, 0.0f, 1.0f};
    static constexpr float kSelectedOutlineColor[4] = {0.7913f, 0.0802f, 0.0f, 1.0f};
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
    gl::Buffer outlineClasses_;  // LIT_SSBO_OUTLINE_CLASSES, grown like vertices_
    std::size_t outlineCapacity_ = 0;
    gl::VertexArray vertexArray_;
    std::vector<LineVertex> staging_;
};

}  // namespace lit
