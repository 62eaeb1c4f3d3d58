#include "passes/TemporalAntialiasPass.h"

#include <shared.h>

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "passes/PostPass.h"

namespace lit {

namespace {

// Radical inverse of `index` in `base`: the Halton sequence's coordinate in [0, 1).
float halton(std::uint32_t index, std::uint32_t base) {
    float result = 0.0f, scale = 1.0f;
    while (index > 0) {
        scale /= static_cast<float>(base);
        result += scale * static_cast<float>(index % base);
        index /= base;
    }
    return result;
}

}  // namespace

TemporalAntialiasPass::TemporalAntialiasPass(const std::filesystem::path& shaderRoot)
    : still_(shaderRoot, "temporal anti-aliasing (still)",
             {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "taa_resolve.frag.glsl"}},
             "#define LIT_TAA_MOVING 0\n"),
      moving_(shaderRoot, "temporal anti-aliasing (moving)",
              {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "taa_resolve.frag.glsl"}},
              "#define LIT_TAA_MOVING 1\n"),
      linearSampler_("anti-aliasing history, bilinear") {
    linearSampler_.set(GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    linearSampler_.set(GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    linearSampler_.set(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    linearSampler_.set(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

glm::vec2 TemporalAntialiasPass::sampleOffset(std::uint32_t index, int frames) {
    const std::uint32_t k = index % static_cast<std::uint32_t>(std::max(frames, 1));
    if (k == 0) return glm::vec2(0.0f);
    return glm::vec2(halton(k, 2), halton(k, 3)) - 0.5f;
}

glm::mat4 TemporalAntialiasPass::jittered(const glm::mat4& projection, glm::vec2 offsetPixels, int width, int height) {
    // clip.xy += 2·offset/size · clip.w: a translation in NDC, for perspective and orthographic
    // projections alike.
    glm::mat4 shift(1.0f);
    shift[3][0] = 2.0f * offsetPixels.x / static_cast<float>(std::max(width, 1));
    shift[3][1] = 2.0f * offsetPixels.y / static_cast<float>(std::max(height, 1));
    return shift * projection;
}

int TemporalAntialiasPass::frames(const RenderSettings& settings) {
    return std::clamp(settings.output.antialiasingFrames, 1, kMaxFrames);
}

bool TemporalAntialiasPass::applies(const RenderSettings& settings) {
    return settings.output.antialiasing && frames(settings) > 1 && !isDataView(settings.debug.view);
}

glm::vec2 TemporalAntialiasPass::begin(const RenderSettings& settings, const FrameStart& frame) {
    viewProjection_ = frame.viewProjection;
    if (!applies(settings)) {
        restart_ = true;
        return glm::vec2(0.0f);
    }
    const Targets& t = targets_.current();
    const bool history =
        t.generation == generation_ && t.width == settings.output.width && t.height == settings.output.height;
    nodesMoved_ = history && frame.nodesMoved;
    moved_ = history && (t.viewProjection != frame.viewProjection || nodesMoved_);
    // A still history holds only still samples: it starts again when the camera stops.
    restart_ = !history || (!moved_ && (frame.changed || movedLast_));
    if (restart_) sample_ = 0;
    return sampleOffset(sample_, frames(settings));
}

void TemporalAntialiasPass::reset() {
    ++generation_;
    sample_ = 0;
    historyFrames_ = 0;
}

void TemporalAntialiasPass::execute(const RenderSettings& settings, const gl::Texture& hdr, const gl::Texture& depth,
                                    const gl::Texture& motion, bool giChanged) {
    const int width = settings.output.width, height = settings.output.height;
    if (targets_.select(width, height) == TargetsBySize<Targets>::Selected::Empty) {
        Targets& t = targets_.current();
        for (int i = 0; i < 2; ++i) {
            t.history[i] = gl::Texture("anti-aliasing history", {GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, 1});
            t.history[i].setFilter(GL_NEAREST, GL_NEAREST);
            t.framebuffer[i] = gl::Framebuffer::withColours("anti-aliasing history", {&t.history[i]});
        }
        t.depth =
            gl::Texture("anti-aliasing history depth", {GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height, 1, 1});
        t.depth.setFilter(GL_NEAREST, GL_NEAREST);
    }
    Targets& t = targets_.current();
    // Moving, the history is reprojected and clamped, which also bounds what a change leaves
    // behind; still, it is the pixel's own mean, read unclamped, and a change starts it again.
    // (begin() found this size's history unless it restarted, so select() kept these targets.)
    const bool hasHistory = !restart_ && (moved_ || !giChanged);
    // Still, a full history is the mean of every offset in the cycle, which the next frames only
    // repeat: it is shown as it is, exactly the still's converged image.
    const bool full = hasHistory && !moved_ && historyFrames_ >= frames(settings);
    historyFrames_ = hasHistory ? std::min(historyFrames_ + 1, frames(settings)) : 1;
    const auto showHistory = [&] {
        glCopyImageSubData(t.history[t.current].id(), GL_TEXTURE_2D, 0, 0, 0, 0, hdr.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                           width, height, 1);
        glCopyImageSubData(depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, t.depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, width,
                           height, 1);
        t.viewProjection = viewProjection_;
        t.generation = generation_;
        ++sample_;
        restart_ = false;
        movedLast_ = moved_;
    };
    if (full) {
        showHistory();
        return;
    }
    const float weight = 1.0f / static_cast<float>(historyFrames_);

    const int previous = t.current, next = 1 - t.current;
    t.framebuffer[next].bind();
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    // Without history the still program takes this frame alone (weight 1).
    const gl::Program& program = moved_ && hasHistory ? moving_ : still_;
    program.use();
    program.set("uWeight", hasHistory ? weight : 1.0f);
    if (&program == &moving_) {
        moving_.set("uViewProjection", glm::value_ptr(viewProjection_));
        moving_.set("uPreviousViewProjection", glm::value_ptr(t.viewProjection));
        moving_.set("uNodesMoved", nodesMoved_ ? 1 : 0);
        const glm::mat4 previousInverse = glm::inverse(t.viewProjection);
        moving_.set("uPreviousInverseViewProjection", glm::value_ptr(previousInverse));
        motion.bind(LIT_TEX_GBUFFER_MOTION);
        t.depth.bind(LIT_TEX_TAA_HISTORY_DEPTH);
    }
    hdr.bind(LIT_TEX_HDR_INPUT);
    depth.bind(LIT_TEX_GBUFFER_DEPTH);
    t.history[previous].bind(LIT_TEX_TAA_HISTORY);
    linearSampler_.bind(LIT_TEX_TAA_HISTORY);
    triangle_.draw();
    glBindSampler(LIT_TEX_TAA_HISTORY, 0);
    t.current = next;
    showHistory();
}

}  // namespace lit
