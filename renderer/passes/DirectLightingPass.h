#pragma once
// Direct lighting: L_DD (Lambert) and L_DS (GGX) from every punctual light with shadow-map
// visibility, one full-screen pass over the G-buffer (direct_lighting.frag.glsl).

#include "passes/Pass.h"

namespace lit {

class LightingTerms;
struct RenderSettings;

class DirectLightingPass : public Pass {
public:
    explicit DirectLightingPass(const std::filesystem::path& shaderRoot);
    // Expects the G-buffer, shadow maps, frame UBO and light SSBO bound.
    void execute(const LightingTerms& terms, const RenderSettings& settings);
    std::vector<gl::Program*> programs() override { return {&program_}; }

private:
    gl::Program program_;
    FullscreenTriangle triangle_;
};

}  // namespace lit
