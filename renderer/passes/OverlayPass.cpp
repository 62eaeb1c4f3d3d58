#include "passes/OverlayPass.h"

#include "passes/GBufferPass.h"

#include <shared.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <limits>

namespace lit {

OverlayPass::OverlayPass(const std::filesystem::path& shaderRoot)
    : outline_(shaderRoot, "overlay outline",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "overlay_outline.frag.glsl"}}),
      lines_(shaderRoot, "overlay lines",
             {{GL_VERTEX_SHADER, "overlay.vert.glsl"}, {GL_FRAGMENT_SHADER, "overlay.frag.glsl"}}),
      vertexArray_("overlay lines") {
    const GLuint vao = vertexArray_.id();
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(LineVertex, position));
    glVertexArrayAttribBinding(vao, 0, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glVertexArrayAttribFormat(vao, 1, 4, GL_FLOAT, GL_FALSE, offsetof(LineVertex, color));
    glVertexArrayAttribBinding(vao, 1, 0);
}

void OverlayPass::uploadLines(const ViewportOverlay& overlay) {
    staging_.clear();
    for (const std::vector<OverlayLine>* list : {&overlay.lines, &overlay.linesOnTop})
        for (const OverlayLine& line : *list)
            for (const glm::vec3& p : {line.a, line.b})
                staging_.push_back({{p.x, p.y, p.z}, {line.color.r, line.color.g, line.color.b, line.color.a}});
    if (staging_.empty()) return;
    if (staging_.size() > vertexCapacity_) {
        // Grow geometrically so a gizmo being dragged does not reallocate every frame.
        vertexCapacity_ = std::max<std::size_t>(1024, std::bit_ceil(staging_.size()));
        vertices_ = gl::Buffer("overlay line vertices", vertexCapacity_ * sizeof(LineVertex), nullptr,
                               GL_DYNAMIC_STORAGE_BIT);
        glVertexArrayVertexBuffer(vertexArray_.id(), 0, vertices_.id(), 0, sizeof(LineVertex));
    }
    vertices_.update(0, staging_.size() * sizeof(LineVertex), staging_.data());
}

void OverlayPass::drawLines(GLint first, GLsizei vertexCount, bool depthTested) {
    if (vertexCount == 0) return;
    lines_.set("uDepthTested", depthTested ? 1 : 0);
    lines_.use();
    vertexArray_.bind();
    glDrawArrays(GL_LINES, first, vertexCount);
}

glm::ivec4 OverlayPass::screenRect(const Aabb& box, const glm::mat4& viewProjection, int width, int height,
                                   int margin) {
    if (box.empty()) return {0, 0, 0, 0};
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner = box.corner(i);
        const glm::vec4 clip = viewProjection * glm::vec4(corner, 1.0f);
        if (clip.w <= 1e-6f) return {0, 0, width, height};  // crosses the eye plane: no bounded projection
        const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(width, height);
        lo = glm::min(lo, pixel);
        hi = glm::max(hi, pixel);
    }
    const glm::ivec2 x0 = glm::max(glm::ivec2(glm::floor(lo)) - margin, glm::ivec2(0));
    const glm::ivec2 x1 = glm::min(glm::ivec2(glm::ceil(hi)) + margin, glm::ivec2(width, height));
    if (x1.x <= x0.x || x1.y <= x0.y) return {0, 0, 0, 0};
    return {x0.x, x0.y, x1.x - x0.x, x1.y - x0.y};
}

std::vector<std::uint32_t> OverlayPass::outlineClasses(const ViewportOverlay& overlay) {
    std::vector<std::uint32_t> classes;
    const auto mark = [&](int node, std::uint32_t value) {
        if (node < 0) return;
        const auto id = static_cast<std::size_t>(node) + 1;
        if (classes.size() <= id) classes.resize(id + 1, 0);
        classes[id] = std::max(classes[id], value);
    };
    for (int node : overlay.selectedOutline) mark(node, 1);
    for (int node : overlay.activeOutline) mark(node, 2);
    return classes;
}

void OverlayPass::execute(const ViewportOverlay& overlay, const GBufferPass& gbuffer, const Aabb& outlineBounds,
                          const glm::mat4& viewProjection) {
    const int width = gbuffer.depth().desc().width, height = gbuffer.depth().desc().height;
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_FRAMEBUFFER_SRGB);  // shaders write linear colour; blending happens in linear too
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gbuffer.nodeId().bind(LIT_TEX_GBUFFER_ID);
    gbuffer.depth().bind(LIT_TEX_GBUFFER_DEPTH);

    // The outline reaches kOutlineRadius (2) pixels past the silhouette; 1 more for rounding.
    const glm::ivec4 rect = screenRect(outlineBounds, viewProjection, width, height, kOutlineRadius + 1);
    const std::vector<std::uint32_t> classes = outlineClasses(overlay);
    if (!classes.empty() && rect.z > 0 && rect.w > 0) {
        if (classes.size() > outlineCapacity_) {
            outlineCapacity_ = std::max<std::size_t>(256, std::bit_ceil(classes.size()));
            outlineClasses_ = gl::Buffer("overlay outline classes", outlineCapacity_ * sizeof(std::uint32_t), nullptr,
                                         GL_DYNAMIC_STORAGE_BIT);
        }
        // The whole buffer is read (the shader takes its length): clear what this frame does not set.
        std::vector<std::uint32_t> upload(outlineCapacity_, 0);
        std::copy(classes.begin(), classes.end(), upload.begin());
        outlineClasses_.update(0, upload.size() * sizeof(std::uint32_t), upload.data());
        outlineClasses_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_OUTLINE_CLASSES);
        outline_.use();
        glProgramUniform4fv(outline_.id(), outline_.location("uActiveColor"), 1, kOutlineColor);
        glProgramUniform4fv(outline_.id(), outline_.location("uSelectedColor"), 1, kSelectedOutlineColor);
        const PickedPrimitive picked = overlay.activePrimitive.value_or(PickedPrimitive{});
        glProgramUniform1ui(outline_.id(), outline_.location("uPrimitiveNode"), static_cast<GLuint>(picked.node + 1));
        glProgramUniform1ui(outline_.id(), outline_.location("uPrimitive"), static_cast<GLuint>(picked.primitive));
        glEnable(GL_SCISSOR_TEST);
        glScissor(rect.x, rect.y, rect.z, rect.w);
        triangle_.draw();
        glDisable(GL_SCISSOR_TEST);
    }
    uploadLines(overlay);
    const auto tested = static_cast<GLsizei>(2 * overlay.lines.size());
    const auto onTop = static_cast<GLsizei>(2 * overlay.linesOnTop.size());
    drawLines(0, tested, true);
    drawLines(tested, onTop, false);

    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);  // GL's default, for whoever enables blending next
    glDisable(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace lit
