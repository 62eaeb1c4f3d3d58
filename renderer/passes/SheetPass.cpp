#include "passes/SheetPass.h"

#include "RenderSettings.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"

#include <shared.h>

#include <algorithm>

namespace lit {

SheetPass::SheetPass(const std::filesystem::path& shaderRoot)
    : programs_(shaderRoot, "sheets",
                {{GL_VERTEX_SHADER, "gbuffer.vert.glsl"}, {GL_FRAGMENT_SHADER, "sheet.frag.glsl"}},
                "#define LIT_MATERIAL_LAYERS 1\n"),
      idProgram_(shaderRoot, "sheet ids",
                 {{GL_VERTEX_SHADER, "gbuffer.vert.glsl"}, {GL_FRAGMENT_SHADER, "sheet_id.frag.glsl"}}) {
    programs_.get(ShadowKinds{});  // a broken shader fails at start-up
}

bool SheetPass::drawsView(const RenderSettings& settings) {
    switch (settings.debug.view) {
        case View::Final:
        case View::DirectDiffuse:
        case View::DirectSpecular:
        case View::IndirectDiffuse:
        case View::IndirectSpecular:
            return true;
        default:
            return false;
    }
}

void SheetPass::execute(const Scene& scene, const GpuScene& gpuScene, const Targets& targets,
                        const RenderSettings& settings, const Frame& frame, DrawCounters& counters) {
    if (!drawsView(settings) || !gpuScene.hasSheets()) return;
    const std::vector<DrawItem>& items = gpuScene.items();
    gpuScene.sheetItems(frame.visibleItems, order_);
    if (order_.empty()) return;
    // Farthest first by the distance to each item's box centre: the blend composes sheet over sheet.
    byDistance_.clear();
    for (const std::uint32_t index : order_) {
        const DrawItem& item = items[index];
        const glm::mat4& world = scene.nodes[static_cast<std::size_t>(item.node)].world;
        const glm::vec3 d = glm::vec3(world * glm::vec4(item.localBounds.center(), 1.0f)) - frame.cameraPosition;
        byDistance_.emplace_back(glm::dot(d, d), index);
    }
    std::stable_sort(byDistance_.begin(), byDistance_.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = byDistance_[i].second;

    if (targets.hdr.id() != hdrId_ || targets.depth.id() != depthId_ || targets.nodeId.id() != nodeIdId_ ||
        !framebuffer_.id()) {
        framebuffer_ = gl::Framebuffer("sheets");
        framebuffer_.attach(GL_COLOR_ATTACHMENT0, targets.hdr);
        framebuffer_.attach(GL_DEPTH_ATTACHMENT, targets.depth);
        framebuffer_.setDrawBuffers(1);
        framebuffer_.checkComplete("sheets");
        idFramebuffer_ = gl::Framebuffer("sheet ids");
        idFramebuffer_.attach(GL_COLOR_ATTACHMENT0, targets.nodeId);
        idFramebuffer_.attach(GL_DEPTH_ATTACHMENT, targets.depth);
        idFramebuffer_.setDrawBuffers(1);
        idFramebuffer_.checkComplete("sheet ids");
        hdrId_ = targets.hdr.id();
        depthId_ = targets.depth.id();
        nodeIdId_ = targets.nodeId.id();
    }
    if (gpuScene.hasRefractingSheets()) {
        // Copies, not the targets themselves: the sheets draw into the image and test against the
        // depth, which they must not also sample.
        const auto copy = [](const gl::Texture& from, gl::Texture& to, const char* label) {
            const gl::TextureDesc& desc = from.desc();
            if (!to.id() || to.desc().width != desc.width || to.desc().height != desc.height ||
                to.desc().format != desc.format)
                to = gl::Texture(label, {GL_TEXTURE_2D, desc.format, desc.width, desc.height, 1, 1});
            glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, 0, 0, 0, to.id(), GL_TEXTURE_2D, 0, 0, 0, 0, desc.width,
                               desc.height, 1);
        };
        copy(targets.hdr, behind_, "sheets: the image behind");
        copy(targets.depth, behindDepth_, "sheets: the depth behind");
        behind_.bind(LIT_TEX_SHEET_BEHIND);
        behindDepth_.bind(LIT_TEX_SHEET_BEHIND_DEPTH);
    }
    framebuffer_.bind();
    glViewport(0, 0, targets.hdr.desc().width, targets.hdr.desc().height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);  // the G-buffer's depth stays the opaque surfaces' (picking, history)
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_SRC1_COLOR);  // own + T · image
    const gl::Program& program = programs_.get(frame.shadows);
    program.use();
    const bool final = settings.debug.view == View::Final;
    const View view = settings.debug.view;
    glProgramUniform4i(program.id(), program.location("uTerms"),
                       final ? settings.terms.directDiffuse : view == View::DirectDiffuse,
                       final ? settings.terms.indirectDiffuse : view == View::IndirectDiffuse,
                       final ? settings.terms.directSpecular : view == View::DirectSpecular,
                       final ? settings.terms.indirectSpecular : view == View::IndirectSpecular);
    glProgramUniform1i(program.id(), program.location("uIndirect"), frame.indirect ? 1 : 0);
    glProgramUniform1f(program.id(), program.location("uShadowNormalOffset"), settings.shadows.normalOffset);
    gpuScene.drawList(scene, program, GpuScene::Bind::Everything, counters, order_);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);

    // The IDs, farthest first as above: the nearest sheet over a pixel is the one picked.
    idFramebuffer_.bind();
    idProgram_.use();
    gpuScene.bindGeometry();
    for (const std::uint32_t index : order_) {
        const DrawItem& item = items[index];
        glProgramUniform1ui(idProgram_.id(), LIT_LOC_NODE_ID, static_cast<GLuint>(item.node + 1));
        glProgramUniform1ui(idProgram_.id(), LIT_LOC_PRIMITIVE, static_cast<GLuint>(item.primitive));
        gpuScene.drawItem(scene, item, idProgram_, GpuScene::Bind::AlphaOnly, counters);
    }
    GpuScene::unbindMaterialSamplers();
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace lit
