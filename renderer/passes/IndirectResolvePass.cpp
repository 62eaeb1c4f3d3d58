#include "passes/IndirectResolvePass.h"

#include <shared.h>

#include <algorithm>

#include "RenderSettings.h"
#include "passes/LightingTerms.h"
#include "passes/VoxelVolume.h"

namespace lit {

IndirectResolvePass::IndirectResolvePass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "indirect resolve",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "indirect_resolve.frag.glsl"}}) {}

void IndirectResolvePass::ensureTargets(const LightingTerms& terms) {
    const GLuint diffuseId = terms.texture(Term::IndirectDiffuse).id();
    const GLuint specularId = terms.texture(Term::IndirectSpecular).id();
    if (traceMask_ && terms.width() == traceMask_.desc().width && terms.height() == traceMask_.desc().height &&
        diffuseId == plainTermIds_[0] && specularId == plainTermIds_[1])
        return;
    plainTermIds_[0] = diffuseId;
    plainTermIds_[1] = specularId;
    // Only 0 and 1 are written: 16 bits is the smallest depth format.
    traceMask_ =
        gl::Texture("indirect trace mask", {GL_TEXTURE_2D, GL_DEPTH_COMPONENT16, terms.width(), terms.height(), 1, 1});
    plainTarget_ = gl::Framebuffer("indirect resolve");
    plainTarget_.attach(GL_COLOR_ATTACHMENT0, terms.texture(Term::IndirectDiffuse));
    plainTarget_.attach(GL_COLOR_ATTACHMENT1, terms.texture(Term::IndirectSpecular));
    plainTarget_.attach(GL_DEPTH_ATTACHMENT, traceMask_);
    plainTarget_.setDrawBuffers(2);  // outputs 2..4 (history) have no buffer and are dropped
    plainTarget_.checkComplete("indirect resolve");
    width_ = 0;  // the history targets hold the old mask: rebuild them too
}

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
        set.target.attach(GL_DEPTH_ATTACHMENT, traceMask_);
        set.target.setDrawBuffers(5);
        set.target.checkComplete("indirect resolve");
    }
    historyValid_ = false;  // a new size has no history
}

void IndirectResolvePass::bindInputs(const gl::Program& program) const {
    last_.target->bind();
    glViewport(0, 0, traceMask_.desc().width, traceMask_.desc().height);
    if (last_.history >= 0) {
        const HistorySet& read = history_[last_.history];
        read.diffuse.bind(LIT_TEX_HISTORY_DIFFUSE);
        read.specular.bind(LIT_TEX_HISTORY_SPECULAR);
        read.guide.bind(LIT_TEX_HISTORY_GUIDE);
    }
    last_.volume->radiance().bind(LIT_TEX_VOXEL_RADIANCE);
    last_.volume->bindDirectional();
    last_.cone->bindAlbedoTable();
    last_.cone->lowPacked().bind(LIT_TEX_INDIRECT_LOW_PACKED);
    last_.cone->lowGuide().bind(LIT_TEX_INDIRECT_LOW_GUIDE);
    const GLuint id = program.id();
    glProgramUniform2i(id, program.location("uTraceTerms"), last_.traceTerms.x, last_.traceTerms.y);
    glProgramUniform1f(id, program.location("uSmoothRoughness"), last_.smoothRoughness);
    glProgramUniform1i(id, program.location("uScale"), last_.scale);
    glProgramUniform2i(id, program.location("uJitter"), last_.sampling.jitter.x, last_.sampling.jitter.y);
    glProgramUniform1f(id, program.location("uRotation"), last_.sampling.rotation);
    glProgramUniform1i(id, program.location("uHistoryValid"), last_.historyValid ? 1 : 0);
    glProgramUniform1i(id, program.location("uMaxFrames"), last_.maxFrames);
    glProgramUniformMatrix4fv(id, program.location("uPrevViewProjection"), 1, GL_FALSE,
                              &last_.previousViewProjection[0][0]);
}

bool IndirectResolvePass::bindForFallback(const gl::Program& program) const {
    if (!last_.ran) return false;
    bindInputs(program);
    return true;
}

void IndirectResolvePass::execute(const LightingTerms& terms, ConeTracePass& cone, const VoxelVolume& volume,
                                  const RenderSettings& settings, const ConeTracePass::Sampling& sampling,
                                  const glm::mat4& previousViewProjection) {
    last_.ran = false;
    const ConeTracePass::Work work = ConeTracePass::workFor(settings);
    if ((!work.diffuse && !work.specular) || !volume.radiance()) {
        terms.clearIndirect();
        historyValid_ = false;
        return;
    }
    ensureTargets(terms);
    const bool temporal = settings.temporalAccumulation;
    last_.history = -1;
    if (temporal) {
        ensureHistory(terms);
        current_ = 1 - current_;
        last_.history = 1 - current_;
        last_.target = &history_[current_].target;
    } else {
        last_.target = &plainTarget_;
    }
    last_.cone = &cone;
    last_.volume = &volume;
    last_.traceTerms = {work.diffuse ? 1 : 0, work.specular ? 1 : 0};
    last_.smoothRoughness = settings.specularFullResRoughness;
    last_.scale = ConeTracePass::indirectScale(settings);
    last_.sampling = sampling;
    last_.historyValid = temporal && historyValid_;
    last_.maxFrames = std::max(settings.temporalMaxFrames, 1);
    last_.previousViewProjection = previousViewProjection;
    bindInputs(program_);
    // Every pixel writes the trace mask (gl_FragDepth): the depth test must be on to write it.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    program_.use();
    triangle_.draw();
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    historyValid_ = temporal;
    last_.ran = true;
}

}  // namespace lit
