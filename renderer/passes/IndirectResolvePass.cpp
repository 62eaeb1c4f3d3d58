#include "passes/IndirectResolvePass.h"

#include <shared.h>

#include <algorithm>

#include "RenderSettings.h"
#include "gi/VoxelVolume.h"
#include "passes/LightingTerms.h"

namespace lit {

IndirectResolvePass::IndirectResolvePass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "indirect resolve",
               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "indirect_resolve.frag.glsl"}}),
      plainProgram_(shaderRoot, "indirect resolve (no history)",
                    {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "indirect_resolve.frag.glsl"}},
                    "#define LIT_RESOLVE_HISTORY 0\n") {
    program_.get(MaterialLayersVariant{});  // a broken shader fails at start-up
    plainProgram_.get(MaterialLayersVariant{});
}

IndirectResolvePass::Targets& IndirectResolvePass::targetsFor(const LightingTerms& terms, bool temporal) {
    targets_.select(terms.width(), terms.height());
    Targets& t = targets_.current();
    if (!t.traceMask) {
        // Only 0 and 1 are written: 16 bits is the smallest depth format.
        t.traceMask = gl::Texture("indirect trace mask", {GL_TEXTURE_2D, GL_DEPTH_COMPONENT16, t.width, t.height, 1, 1});
        t.termIds[0] = t.termIds[1] = 0;
    }
    const bool historyAllocated = static_cast<bool>(t.history[0].diffuse);
    if (temporal && !historyAllocated) {
        for (HistorySet& set : t.history) {
            set.diffuse = gl::Texture("indirect history diffuse", {GL_TEXTURE_2D, GL_RGBA16F, t.width, t.height, 1, 1});
            set.specular = gl::Texture("indirect history specular", {GL_TEXTURE_2D, GL_RGBA16F, t.width, t.height, 1, 1});
            // Clip w is a distance in metres: 16F keeps 11 bits, 0.05 % of it, far below the 2 %
            // rejection tolerance.
            set.guide = gl::Texture("indirect history guide", {GL_TEXTURE_2D, GL_RGBA16F, t.width, t.height, 1, 1});
            for (const gl::Texture* h : {&set.diffuse, &set.specular, &set.guide}) h->setFilter(GL_NEAREST, GL_NEAREST);
        }
        t.historyWritten = false;  // new textures hold nothing
    }
    // The framebuffers write the terms' textures of this size: rebuilt when those were reallocated.
    const GLuint ids[2] = {terms.texture(Term::IndirectDiffuse).id(), terms.texture(Term::IndirectSpecular).id()};
    if (ids[0] == t.termIds[0] && ids[1] == t.termIds[1] && historyAllocated == static_cast<bool>(t.history[0].diffuse))
        return t;
    t.termIds[0] = ids[0];
    t.termIds[1] = ids[1];
    t.plainTarget = gl::Framebuffer("indirect resolve");
    t.plainTarget.attach(GL_COLOR_ATTACHMENT0, terms.texture(Term::IndirectDiffuse));
    t.plainTarget.attach(GL_COLOR_ATTACHMENT1, terms.texture(Term::IndirectSpecular));
    t.plainTarget.attach(GL_DEPTH_ATTACHMENT, t.traceMask);
    t.plainTarget.setDrawBuffers(2);  // outputs 2..4 (history) have no buffer and are dropped
    t.plainTarget.checkComplete("indirect resolve");
    if (!t.history[0].diffuse) return t;
    for (HistorySet& set : t.history) {
        set.target = gl::Framebuffer("indirect resolve");
        set.target.attach(GL_COLOR_ATTACHMENT0, terms.texture(Term::IndirectDiffuse));
        set.target.attach(GL_COLOR_ATTACHMENT1, terms.texture(Term::IndirectSpecular));
        set.target.attach(GL_COLOR_ATTACHMENT2, set.diffuse);
        set.target.attach(GL_COLOR_ATTACHMENT3, set.specular);
        set.target.attach(GL_COLOR_ATTACHMENT4, set.guide);
        set.target.attach(GL_DEPTH_ATTACHMENT, t.traceMask);
        set.target.setDrawBuffers(5);
        set.target.checkComplete("indirect resolve");
    }
    return t;
}

void IndirectResolvePass::bindInputs(const gl::Program& program) const {
    last_.target->bind();
    glViewport(0, 0, last_.targets->width, last_.targets->height);
    if (last_.history >= 0) {
        const HistorySet& read = last_.targets->history[last_.history];
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
    glProgramUniform1f(id, program.location("uClampMargin"), last_.clampMargin);
    glProgramUniformMatrix4fv(id, program.location("uPrevViewProjection"), 1, GL_FALSE,
                              &last_.previousViewProjection[0][0]);
}

bool IndirectResolvePass::bindForFallback(const gl::Program& program) const {
    if (!last_.ran) return false;
    bindInputs(program);
    return true;
}

float IndirectResolvePass::clampMargin(const RenderSettings& settings, const ConeTracePass::Sampling& sampling) {
    return sampling.coneSubset >= 0 && ConeFeatures::of(settings).footprint ? kSubsetClampMargin : kClampMargin;
}

void IndirectResolvePass::execute(const LightingTerms& terms, ConeTracePass& cone, const VoxelVolume& volume,
                                  const RenderSettings& settings, const ConeTracePass::Sampling& sampling,
                                  const glm::mat4& viewProjection, bool materialLayers) {
    last_.ran = false;
    const ConeTracePass::Work work = ConeTracePass::workFor(settings);
    if ((!work.diffuse && !work.specular) || !volume.radiance()) {
        terms.clearIndirect();
        resetHistory();
        return;
    }
    const bool temporal = settings.indirect.temporalAccumulation;
    Targets& t = targetsFor(terms, temporal);
    last_.targets = &t;
    last_.history = -1;
    last_.historyValid = false;
    if (temporal) {
        last_.historyValid = historyUsable(t, generation_);
        last_.previousViewProjection = t.viewProjection;
        t.current = 1 - t.current;
        last_.history = 1 - t.current;
        last_.target = &t.history[t.current].target;
    } else {
        last_.target = &t.plainTarget;
    }
    last_.cone = &cone;
    last_.volume = &volume;
    last_.traceTerms = {work.diffuse ? 1 : 0, work.specular ? 1 : 0};
    last_.smoothRoughness = settings.indirect.specularFullResRoughness;
    last_.scale = ConeTracePass::indirectScale(settings);
    last_.sampling = sampling;
    last_.maxFrames = std::max(settings.indirect.temporalMaxFrames, 1);
    last_.clampMargin = clampMargin(settings, sampling);
    const gl::Program& program = (temporal ? program_ : plainProgram_).get(MaterialLayersVariant{materialLayers});
    bindInputs(program);
    // Every pixel writes the trace mask (gl_FragDepth): the depth test must be on to write it.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    program.use();
    triangle_.draw();
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // The history (only a temporal frame writes it) and the camera it was written with; the other
    // size's history is left as it is, for when that size comes back.
    t.historyWritten = temporal;
    t.generation = generation_;
    t.viewProjection = viewProjection;
    last_.ran = true;
}

}  // namespace lit
