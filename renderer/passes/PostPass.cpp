#include "passes/PostPass.h"

#include <shared.h>

#include <utility>

namespace lit {

bool isDataView(View view) {
    return view == View::Albedo || view == View::Normal || view == View::RoughnessMetalness ||
           view == View::ShadowMap || view == View::Voxels || view == View::VoxelSlice;
}

PostPass::PostPass(const std::filesystem::path& shaderRoot)
    : composite_(shaderRoot, "composite",
                 {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "composite.frag.glsl"}}),
      tonemap_(shaderRoot, "tonemap",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "tonemap.frag.glsl"}}),
      plainSampler_("debug view, no comparison") {
    plainSampler_.set(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    plainSampler_.set(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    plainSampler_.set(GL_TEXTURE_COMPARE_MODE, GL_NONE);
}

void PostPass::swapWithSpare() {
    std::swap(hdr_, spare_.hdr);
    std::swap(output_, spare_.output);
    std::swap(hdrFramebuffer_, spare_.hdrFramebuffer);
    std::swap(outputFramebuffer_, spare_.outputFramebuffer);
    std::swap(width_, spare_.width);
    std::swap(height_, spare_.height);
}

void PostPass::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    swapWithSpare();  // the current targets become the spare
    if (width == width_ && height == height_) return;  // the spare had this size
    width_ = width;
    height_ = height;
    // 32-bit float so the HDR image holds the exact sum of the 16-bit term images.
    hdr_ = gl::Texture("hdr", {GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, 1});
    hdr_.setFilter(GL_NEAREST, GL_NEAREST);
    output_ = gl::Texture("output", {GL_TEXTURE_2D, GL_SRGB8_ALPHA8, width, height, 1, 1});
    hdrFramebuffer_ = gl::Framebuffer("hdr");
    hdrFramebuffer_.attach(GL_COLOR_ATTACHMENT0, hdr_);
    hdrFramebuffer_.setDrawBuffers(1);
    hdrFramebuffer_.checkComplete("hdr");
    outputFramebuffer_ = gl::Framebuffer("output");
    outputFramebuffer_.attach(GL_COLOR_ATTACHMENT0, output_);
    outputFramebuffer_.setDrawBuffers(1);
    outputFramebuffer_.checkComplete("output");
}

void PostPass::bindHdrTarget() const {
    hdrFramebuffer_.bind();
    glViewport(0, 0, width_, height_);
}

void PostPass::bindOutputTarget() const {
    outputFramebuffer_.bind();
    glViewport(0, 0, width_, height_);
}

void PostPass::composite(const RenderSettings& settings, const gl::Texture& shadowMaps, int shadowLayer) {
    bindHdrTarget();
    glDisable(GL_DEPTH_TEST);
    composite_.use();
    glProgramUniform4i(composite_.id(), composite_.location("uTerms"), settings.directDiffuse,
                       settings.gi && settings.indirectDiffuse, settings.directSpecular,
                       settings.gi && settings.indirectSpecular);
    composite_.set("uShadowLayer", shadowLayer);
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
    tonemap_.set("uDataView", isDataView(settings.view) ? 1 : 0);
    // The exposure buffer is bound by the Renderer (AutoExposurePass) when auto exposure is on.
    tonemap_.set("uAutoExposure", settings.autoExposure && !isDataView(settings.view) ? 1 : 0);
    hdr_.bind(LIT_TEX_HDR_INPUT);
    triangle_.draw();
    glDisable(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace lit
