#include "passes/PostPass.h"

#include <shared.h>

#include <utility>

namespace lit {

bool isDataView(View view) {
    return view == View::Albedo || view == View::Normal || view == View::RoughnessMetalness ||
           view == View::ShadowMap || view == View::Voxels || view == View::VoxelSlice || view == View::VoxelLevels;
}

PostPass::PostPass(const std::filesystem::path& shaderRoot)
    : composite_(shaderRoot, "composite",
                 {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "composite.frag.glsl"}}),
      finalComposite_(shaderRoot, "composite (final view)",
                      {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "composite.frag.glsl"}},
                      "#define LIT_COMPOSITE_FINAL_ONLY 1\n"),
      tonemap_(shaderRoot, "tonemap",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "tonemap.frag.glsl"}}),
      plainSampler_("debug view, no comparison") {
    plainSampler_.set(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    plainSampler_.set(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    plainSampler_.set(GL_TEXTURE_COMPARE_MODE, GL_NONE);
}

void PostPass::resize(int width, int height) {
    if (targets_.select(width, height) != TargetsBySize<Targets>::Selected::Empty) return;
    Targets& t = targets_.current();
    // 32-bit float so the HDR image holds the exact sum of the 16-bit term images.
    t.hdr = gl::Texture("hdr", {GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, 1});
    t.hdr.setFilter(GL_NEAREST, GL_NEAREST);
    t.output = gl::Texture("output", {GL_TEXTURE_2D, GL_SRGB8_ALPHA8, width, height, 1, 1});
    t.hdrFramebuffer = gl::Framebuffer::withColours("hdr", {&t.hdr});
    t.outputFramebuffer = gl::Framebuffer::withColours("output", {&t.output});
}

void PostPass::bindHdrTarget() const {
    targets_->hdrFramebuffer.bind();
    glViewport(0, 0, targets_->width, targets_->height);
}

void PostPass::bindOutputTarget() const {
    targets_->outputFramebuffer.bind();
    glViewport(0, 0, targets_->width, targets_->height);
}

void PostPass::composite(const RenderSettings& settings, const gl::Texture& shadowMaps, int shadowLayer) {
    bindHdrTarget();
    glDisable(GL_DEPTH_TEST);
    const gl::Program& program = settings.debug.view == View::Final ? finalComposite_ : composite_;
    program.use();
    glProgramUniform4i(program.id(), program.location("uTerms"), settings.terms.directDiffuse,
                       settings.gi.enabled && settings.terms.indirectDiffuse, settings.terms.directSpecular,
                       settings.gi.enabled && settings.terms.indirectSpecular);
    if (&program == &composite_) composite_.set("uShadowLayer", shadowLayer);
    shadowMaps.bind(LIT_TEX_DEBUG_INPUT);
    plainSampler_.bind(LIT_TEX_DEBUG_INPUT);
    triangle_.draw();
    glBindSampler(LIT_TEX_DEBUG_INPUT, 0);
}

void PostPass::tonemap(const RenderSettings& settings) {
    bindOutputTarget();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_FRAMEBUFFER_SRGB);
    tonemap_.use();
    tonemap_.set("uDataView", isDataView(settings.debug.view) ? 1 : 0);
    // The exposure buffer is bound by the Renderer (AutoExposurePass) when auto exposure is on.
    tonemap_.set("uAutoExposure", settings.output.autoExposure && !isDataView(settings.debug.view) ? 1 : 0);
    targets_->hdr.bind(LIT_TEX_HDR_INPUT);
    triangle_.draw();
    glDisable(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace lit
