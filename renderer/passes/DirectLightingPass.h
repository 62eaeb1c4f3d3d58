#pragma once
// Direct lighting: L_DD (Lambert) and L_DS (GGX) from every punctual light with shadow-map
// visibility, one full-screen pass over the G-buffer (direct_lighting.frag.glsl).

#include "gl/ProgramVariants.h"
#include "passes/LightSetup.h"
#include "passes/Pass.h"

namespace lit {

class LightingTerms;
struct RenderSettings;

class DirectLightingPass : public Pass {
public:
    explicit DirectLightingPass(const std::filesystem::path& shaderRoot);
    // Expects the G-buffer, shadow maps, frame UBO and light SSBO bound; `shadows`: the kinds of
    // shadow map the bound light table uses (ShadowKinds::of).
    void execute(const LightingTerms& terms, const RenderSettings& settings, ShadowKinds shadows = {});
    std::vector<gl::Program*> programs() override { return programs_.built(); }

private:
    gl::ProgramVariants<ShadowKinds::kVariants> programs_;  // by ShadowKinds::index()
    FullscreenTriangle triangle_;
};

}  // namespace lit
