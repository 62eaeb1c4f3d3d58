#include "passes/GBufferPass.h"

#include "scene/GpuScene.h"

#include <shared.h>

#include <utility>

namespace lit {

GBufferPass::GBufferPass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "gbuffer",
               {{GL_VERTEX_SHADER, "gbuffer.vert.glsl"}, {GL_FRAGMENT_SHADER, "gbuffer.frag.glsl"}}) {}

void GBufferPass::swapWithSpare() {
    std::swap(albedo_, spare_.albedo);
    std::swap(normal_, spare_.normal);
    std::swap(material_, spare_.material);
    std::swap(emissive_, spare_.emissive);
    std::swap(nodeId_, spare_.nodeId);
    std::swap(depth_, spare_.depth);
    std::swap(framebuffer_, spare_.framebuffer);
    std::swap(width_, spare_.width);
    std::swap(height_, spare_.height);
}

void GBufferPass::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    swapWithSpare();  // the current targets become the spare
    if (width == width_ && height == height_) return;  // the spare had this size
    width_ = width;
    height_ = height;
    albedo_ = gl::Texture("gbuffer albedo", {GL_TEXTURE_2D, GL_SRGB8_ALPHA8, width, height, 1, 1});
    normal_ = gl::Texture("gbuffer normal", {GL_TEXTURE_2D, GL_RGBA16F, width, height, 1, 1});
    material_ = gl::Texture("gbuffer material", {GL_TEXTURE_2D, GL_RGBA8, width, height, 1, 1});
    emissive_ = gl::Texture("gbuffer emissive", {GL_TEXTURE_2D, GL_RGBA16F, width, height, 1, 1});
    nodeId_ = gl::Texture("gbuffer node id", {GL_TEXTURE_2D, GL_R32UI, width, height, 1, 1});
    depth_ = gl::Texture("gbuffer depth", {GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height, 1, 1});
    for (const gl::Texture* t : {&albedo_, &normal_, &material_, &emissive_, &nodeId_, &depth_})
        t->setFilter(GL_NEAREST, GL_NEAREST);
    framebuffer_ = gl::Framebuffer("gbuffer");
    framebuffer_.attach(GL_COLOR_ATTACHMENT0, albedo_);
    framebuffer_.attach(GL_COLOR_ATTACHMENT1, normal_);
    framebuffer_.attach(GL_COLOR_ATTACHMENT2, material_);
    framebuffer_.attach(GL_COLOR_ATTACHMENT3, emissive_);
    framebuffer_.attach(GL_COLOR_ATTACHMENT4, nodeId_);
    framebuffer_.attach(GL_DEPTH_ATTACHMENT, depth_);
    framebuffer_.setDrawBuffers(5);
    framebuffer_.checkComplete("gbuffer");
}

void GBufferPass::execute(const Scene& scene, const GpuScene& gpuScene, DrawCounters& counters,
                          const std::vector<std::uint32_t>* visibleItems) {
    framebuffer_.bind();
    glViewport(0, 0, width_, height_);
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, i, zero);
    const GLuint background = 0;
    glClearNamedFramebufferuiv(framebuffer_.id(), GL_COLOR, 4, &background);
    const float one = 1.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // back faces are shaded with flipped normals (see gbuffer.frag.glsl)
    // Linear values written to the sRGB albedo target are encoded by the hardware.
    glEnable(GL_FRAMEBUFFER_SRGB);
    program_.use();
    gpuScene.materials().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_MATERIALS);
    // Items are drawn one by one (as GpuScene::drawList does) to give each its node ID.
    const std::vector<DrawItem>& items = gpuScene.items();
    const auto drawOne = [&](const DrawItem& item) {
        glProgramUniform1ui(program_.id(), LIT_LOC_NODE_ID, static_cast<GLuint>(item.node + 1));
        gpuScene.drawItem(scene, item, program_, GpuScene::Bind::Everything, counters);
    };
    gpuScene.bindGeometry();
    if (visibleItems) {
        for (const std::uint32_t index : *visibleItems)
            if (index < items.size()) drawOne(items[index]);
    } else {
        for (const DrawItem& item : items) drawOne(item);
    }
    glDisable(GL_FRAMEBUFFER_SRGB);
}

void GBufferPass::bindTargets() const {
    albedo_.bind(LIT_TEX_GBUFFER_ALBEDO);
    normal_.bind(LIT_TEX_GBUFFER_NORMAL);
    material_.bind(LIT_TEX_GBUFFER_MATERIAL);
    emissive_.bind(LIT_TEX_GBUFFER_EMISSIVE);
    depth_.bind(LIT_TEX_GBUFFER_DEPTH);
}

}  // namespace lit
