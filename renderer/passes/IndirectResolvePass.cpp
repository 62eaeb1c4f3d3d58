#include "passes/IndirectResolvePass.h"

#include "RenderSettings.h"
#include "passes/LightingTerms.h"
#include "passes/VoxelVolume.h"

#include <shared.h>

#include <algorithm>

namespace lit {

IndirectResolvePass::IndirectResolvePass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "indirect resolve",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "indirect_resolve.frag.glsl"}}) {}

void IndirectResolvePass::ensureHistory(const LightingTerms& terms) {
    const GLuint diffuseId = terms.texture(Term::IndirectDiffuse).id();
    const GLuint specularId = terms.texture(Term::IndirectSpecular).id();
    if (terms.width() == width_ && terms.height() == height_ && diffuseId == termIds_[0] && specularId == termIds_[1])
        return;
    width_ = terms.width();
    height_ = terms.height();
    termIds_[0] = diffuseId;
    termIds_[1] = specularId;
    for (HistorySet& set : history_) {
        set.diffuse = gl::Texture("indirect history diffuse", {GL_TEXTURE_2D, GL_RGBA16F, width_, height_, 1, 1});
        set.specular = gl::Texture("indirect history specular", {GL_TEXTURE_2D, GL_RGBA16F, width_, height_, 1, 1});
        // Clip w is a distance in metres: 16F keeps 11 bits, 0.05 % of it, far below the 2 %
        // rejection tolerance.
        set.guide = gl::Texture("indirect history guide", {GL_TEXTURE_2D, GL_RGBA16F, width_, height_, 1, 1});
        for (const gl::Texture* t : {&set.diffuse, &set.specular, &set.guide}) t->setFilter(GL_NEAREST, GL_NEAREST);
        set.target = gl::Framebuffer("indirect resolve");
        set.target.attach(GL_COLOR_ATTACHMENT0, terms.texture(Term::IndirectDiffuse));
        set.target.attach(GL_COLOR_ATTACHMENT1, terms.texture(Term::IndirectSpecular));
        set.target.attach(GL_COLOR_ATTACHMENT2, set.diffuse);
        set.target.attach(GL_COLOR_ATTACHMENT3, set.specular);
        set.target.attach(GL_COLOR_ATTACHMENT4, set.guide);
        set.target.setDrawBuffers(5);
        set.target.checkComplete("indirect resolve");
    }
    historyValid_ = false;  // a new size has no history
}

void IndirectResolvePass::execute(const LightingTerms& terms, ConeTracePass& cone, const VoxelVolume& volume,
                                  const RenderSettings& settings, const ConeTracePass::Sampling& sampling,
                                  const glm::mat4& previousViewProjection) {
    const ConeTracePass::Work work = ConeTracePass::workFor(settings);
    if ((!work.diffuse && !work.specular) || !volume.radiance()) {
        terms.clearIndirect();
        historyValid_ = false;
        return;
    }
    const bool temporal = settings.temporalAccumulation;
    if (temporal) {
        ensureHistory(terms);
        current_ = 1 - current_;
        const HistorySet& read = history_[1 - current_];
        read.diffuse.bind(LIT_TEX_HISTORY_DIFFUSE);
        read.specular.bind(LIT_TEX_HISTORY_SPECULAR);
        read.guide.bind(LIT_TEX_HISTORY_GUIDE);
        history_[current_].target.bind();
    } else {
        terms.indirectFramebuffer().bind();  // outputs 2..4 (history) have no buffer and are dropped
    }
    glViewport(0, 0, terms.width(), terms.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    volume.radiance().bind(LIT_TEX_VOXEL_RADIANCE);
    cone.bindAlbedoTable();
    cone.lowPacked().bind(LIT_TEX_INDIRECT_LOW_PACKED);
    cone.lowGuide().bind(LIT_TEX_INDIRECT_LOW_GUIDE);
    program_.use();
    const GLuint id = program_.id();
    glProgramUniform2i(id, program_.location("uTraceTerms"), work.diffuse ? 1 : 0, work.specular ? 1 : 0);
    glProgramUniform1f(id, program_.location("uSmoothRoughness"), settings.specularFullResRoughness);
    glProgramUniform1i(id, program_.location("uScale"), ConeTracePass::indirectScale(settings));
    glProgramUniform2i(id, program_.location("uJitter"), sampling.jitter.x, sampling.jitter.y);
    glProgramUniform1f(id, program_.location("uRotation"), sampling.rotation);
    glProgramUniform1i(id, program_.location("uHistoryValid"), temporal && historyValid_ ? 1 : 0);
    glProgramUniform1i(id, program_.location("uMaxFrames"), std::max(settings.temporalMaxFrames, 1));
    glProgramUniformMatrix4fv(id, program_.location("uPrevViewProjection"), 1, GL_FALSE, &previousViewProjection[0][0]);
    triangle_.draw();
    historyValid_ = temporal;
}

}  // namespace lit
