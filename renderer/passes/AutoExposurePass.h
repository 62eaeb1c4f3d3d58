#pragma once
// Auto exposure: meters the linear HDR image and adapts the exposure the tone mapper uses.
//   1. luminance_histogram.comp.glsl: a histogram of log2 luminance (LIT_EXPOSURE_BINS bins over
//      [LIT_EXPOSURE_LOG2_MIN, LIT_EXPOSURE_LOG2_MAX], black pixels in bin 0, not metered);
//   2. auto_exposure.comp.glsl (one work group): the mean log2 luminance between the
//      LIT_EXPOSURE_LOW_PERCENT and LIT_EXPOSURE_HIGH_PERCENT quantiles, the exposure that maps it
//      to OutputSettings::autoExposureKey (plus exposureEv as compensation, clamped to the min/max
//      stops), approached exponentially at autoExposureSpeed per second; written to the
//      LIT_SSBO_EXPOSURE buffer that tonemap.frag.glsl reads. Nothing is read back to the CPU.

#include "RenderSettings.h"
#include "passes/Pass.h"

namespace lit {

class AutoExposurePass : public Pass {
public:
    explicit AutoExposurePass(const std::filesystem::path& shaderRoot);

    // Meters `hdr` (RGBA32F, settings.output.width × height) and adapts. `deltaSeconds` is the time since
    // the previous metered frame; the first frame after reset() takes the metered value at once.
    void execute(const gl::Texture& hdr, const RenderSettings& settings, float deltaSeconds);
    void reset() { valid_ = false; }
    // Binds the exposure buffer at LIT_SSBO_EXPOSURE for the tone mapper.
    void bindExposure() const;
    // The current exposure in stops (log2 multiplier). Reads the buffer back: tests and tools only.
    float readExposureEv() const;

    std::vector<gl::Program*> programs() override { return {&histogram_, &adapt_}; }

private:
    gl::Program histogram_, adapt_;
    gl::Buffer histogramBuffer_, exposureBuffer_;
    bool valid_ = false;
};

}  // namespace lit
