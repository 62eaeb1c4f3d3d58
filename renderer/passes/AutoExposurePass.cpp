#include "passes/AutoExposurePass.h"

#include <shared.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace lit {

AutoExposurePass::AutoExposurePass(const std::filesystem::path& shaderRoot)
    : histogram_(shaderRoot, "luminance histogram", {{GL_COMPUTE_SHADER, "luminance_histogram.comp.glsl"}}),
      adapt_(shaderRoot, "auto exposure", {{GL_COMPUTE_SHADER, "auto_exposure.comp.glsl"}}),
      histogramBuffer_("luminance histogram", sizeof(std::uint32_t) * LIT_EXPOSURE_BINS, nullptr, GL_DYNAMIC_STORAGE_BIT),
      exposureBuffer_("exposure", sizeof(glm::vec4), nullptr, GL_DYNAMIC_STORAGE_BIT) {
    const std::array<std::uint32_t, LIT_EXPOSURE_BINS> zeros{};
    histogramBuffer_.update(0, sizeof zeros, zeros.data());
    const glm::vec4 unit(1.0f, 0.0f, 0.0f, 0.0f);
    exposureBuffer_.update(unit);
}

void AutoExposurePass::execute(const gl::Texture& hdr, const RenderSettings& settings, float deltaSeconds) {
    hdr.bind(LIT_TEX_HDR_INPUT);
    histogramBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_LUMINANCE_HISTOGRAM);
    exposureBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_EXPOSURE);
    histogram_.use();
    const auto groups = [](int pixels) {
        return static_cast<GLuint>((pixels + LIT_EXPOSURE_GROUP_SIZE - 1) / LIT_EXPOSURE_GROUP_SIZE);
    };
    glDispatchCompute(groups(settings.output.width), groups(settings.output.height), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    adapt_.use();
    adapt_.set("uKey", settings.output.autoExposureKey);
    adapt_.set("uCompensationEv", settings.output.exposureEv);
    adapt_.set("uMinEv", settings.output.autoExposureMinEv);
    adapt_.set("uMaxEv", settings.output.autoExposureMaxEv);
    // Share of the way to the target this frame: 1 − e^(−speed·Δt); all of it when adaptation is
    // instant (speed 0) or the previous value is not valid.
    const float blend = !valid_ || settings.output.autoExposureSpeed <= 0.0f
                            ? 1.0f
                            : 1.0f - std::exp(-settings.output.autoExposureSpeed * std::max(deltaSeconds, 0.0f));
    adapt_.set("uBlend", blend);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_UNIFORM_BARRIER_BIT);
    valid_ = true;
}

void AutoExposurePass::bindExposure() const { exposureBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_EXPOSURE); }

float AutoExposurePass::readExposureEv() const {
    glm::vec4 value(0.0f);
    glGetNamedBufferSubData(exposureBuffer_.id(), 0, sizeof value, &value);
    return value.y;
}

}  // namespace lit
