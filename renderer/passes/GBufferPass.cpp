#include "passes/GBufferPass.h"

#include "scene/GpuScene.h"

#include <shared.h>

#include <utility>

namespace lit {

GBufferPass::GBufferPass(const std::filesystem::path& shaderRoot)
    : programs_(shaderRoot, "gbuffer",
                {{GL_VERTEX_SHADER, "gbuffer.vert.glsl"}, {GL_FRAGMENT_SHADER, "gbuffer.frag.glsl"}}) {
    programs_.get(MaterialTextureKey{LIT_MATERIAL_TEXTURES_ALL});  // a broken shader fails at start-up
}

void GBufferPass::resize(int width, int height) {
    if (targets_.select(width, height) != TargetsBySize<Targets>::Selected::Empty) return;
    Targets& t = targets_.current();
    t.albedo = gl::Texture("gbuffer albedo", {GL_TEXTURE_2D, GL_SRGB8_ALPHA8, width, height, 1, 1});
    t.normal = gl::Texture("gbuffer normal", {GL_TEXTURE_2D, GL_RGBA16F, width, height, 1, 1});
    t.material = gl::Texture("gbuffer material", {GL_TEXTURE_2D, GL_RGBA8, width, height, 1, 1});
    t.emissive = gl::Texture("gbuffer emissive", {GL_TEXTURE_2D, GL_RGBA16F, width, height, 1, 1});
    t.nodeId = gl::Texture("gbuffer node id", {GL_TEXTURE_2D, GL_RGBA32UI, width, height, 1, 1});
    t.layers = gl::Texture("gbuffer layer texels", {GL_TEXTURE_2D, GL_RGBA32UI, width, height, 1, 1});
    t.motion = gl::Texture("gbuffer motion", {GL_TEXTURE_2D, GL_RGBA16F, width, height, 1, 1});
    t.depth = gl::Texture("gbuffer depth", {GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height, 1, 1});
    for (const gl::Texture* texture :
         {&t.albedo, &t.normal, &t.material, &t.emissive, &t.nodeId, &t.layers, &t.motion, &t.depth})
        texture->setFilter(GL_NEAREST, GL_NEAREST);
    t.framebuffer = gl::Framebuffer("gbuffer");
    t.framebuffer.attach(GL_COLOR_ATTACHMENT0, t.albedo);
    t.framebuffer.attach(GL_COLOR_ATTACHMENT1, t.normal);
    t.framebuffer.attach(GL_COLOR_ATTACHMENT2, t.material);
    t.framebuffer.attach(GL_COLOR_ATTACHMENT3, t.emissive);
    t.framebuffer.attach(GL_COLOR_ATTACHMENT4, t.nodeId);
    t.framebuffer.attach(GL_COLOR_ATTACHMENT5, t.layers);
    t.framebuffer.attach(GL_COLOR_ATTACHMENT6, t.motion);
    t.framebuffer.attach(GL_DEPTH_ATTACHMENT, t.depth);
    t.framebuffer.setDrawBuffers(7);
    t.framebuffer.checkComplete("gbuffer");
}

void GBufferPass::execute(const Scene& scene, const GpuScene& gpuScene, DrawCounters& counters,
                          const std::vector<std::uint32_t>* visibleItems, const std::vector<glm::mat4>* previousWorld) {
    // The layer texels are written only for scenes with layer textures, and read only at pixels
    // whose material has them (gbuffer.glsl readMaterialLayers), the motion only in frames whose
    // nodes moved (the anti-aliasing reads it then): otherwise those targets stay out.
    const bool motion = previousWorld != nullptr;
    targets_->framebuffer.setDrawBuffers({true, true, true, true, true, gpuScene.hasLayerTextures(), motion});
    targets_->framebuffer.bind();
    glViewport(0, 0, targets_->width, targets_->height);
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) glClearNamedFramebufferfv(targets_->framebuffer.id(), GL_COLOR, i, zero);
    const GLuint background[4] = {0, 0, 0, 0};
    glClearNamedFramebufferuiv(targets_->framebuffer.id(), GL_COLOR, 4, background);
    if (motion) glClearNamedFramebufferfv(targets_->framebuffer.id(), GL_COLOR, 6, zero);
    const float one = 1.0f;
    glClearNamedFramebufferfv(targets_->framebuffer.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // back faces are shaded with flipped normals (see gbuffer.frag.glsl)
    // Linear values written to the sRGB albedo target are encoded by the hardware.
    glEnable(GL_FRAMEBUFFER_SRGB);
    gpuScene.materials().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_MATERIALS);
    // Items are drawn one by one (as GpuScene::drawList does) to give each its node ID, each with
    // the program for its material's textures.
    const std::vector<DrawItem>& items = gpuScene.items();
    const gl::Program* bound = nullptr;
    const auto drawOne = [&](const DrawItem& item) {
        const gl::Program& itemProgram = programs_.get(MaterialTextureKey{gpuScene.materialTextureMask(item)});
        if (&itemProgram != bound) {
            itemProgram.use();
            bound = &itemProgram;
        }
        glProgramUniform1ui(itemProgram.id(), LIT_LOC_NODE_ID, static_cast<GLuint>(item.node + 1));
        glProgramUniform1ui(itemProgram.id(), LIT_LOC_PRIMITIVE, static_cast<GLuint>(item.primitive));
        if (motion) {
            const auto node = static_cast<std::size_t>(item.node);
            const glm::mat4& before = node < previousWorld->size() ? (*previousWorld)[node] : scene.nodes[node].world;
            glProgramUniformMatrix4fv(itemProgram.id(), LIT_LOC_PREVIOUS_MODEL, 1, GL_FALSE, &before[0][0]);
        }
        gpuScene.drawItem(scene, item, itemProgram, GpuScene::Bind::Everything, counters);
    };
    gpuScene.bindGeometry();
    if (visibleItems) {
        for (const std::uint32_t index : *visibleItems)
            if (index < items.size()) drawOne(items[index]);
    } else {
        for (const DrawItem& item : items) drawOne(item);
    }
    GpuScene::unbindMaterialSamplers();
    glDisable(GL_FRAMEBUFFER_SRGB);
}

void GBufferPass::bindTargets() const {
    targets_->albedo.bind(LIT_TEX_GBUFFER_ALBEDO);
    targets_->normal.bind(LIT_TEX_GBUFFER_NORMAL);
    targets_->material.bind(LIT_TEX_GBUFFER_MATERIAL);
    targets_->emissive.bind(LIT_TEX_GBUFFER_EMISSIVE);
    targets_->depth.bind(LIT_TEX_GBUFFER_DEPTH);
    targets_->nodeId.bind(LIT_TEX_GBUFFER_ID);
    targets_->layers.bind(LIT_TEX_GBUFFER_LAYERS);
}

}  // namespace lit
