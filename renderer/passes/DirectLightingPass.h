#pragma once
// Direct lighting: L_DD (Lambert) and L_DS (GGX) from every punctual light with shadow-map
// visibility, one full-screen pass over the G-buffer (direct_lighting.frag.glsl).

#include "gl/ProgramVariants.h"
#include "passes/LightSetup.h"
#include "passes/MaterialLayersVariant.h"
#include "passes/Pass.h"

namespace lit {

class LightingTerms;
struct RenderSettings;

class DirectLightingPass : public Pass {
public:
    explicit DirectLightingPass(const std::filesystem::path& shaderRoot);
    // The program variant: the kinds of shadow map the bound light table uses (ShadowKinds::of)
    // and whether the scene's materials have specular layers (GpuScene::hasMaterialLayers).
    struct Variant {
        ShadowKinds shadows;
        MaterialLayersVariant layers;
        static constexpr std::size_t kVariants = ShadowKinds::kVariants * MaterialLayersVariant::kVariants;
        std::size_t index() const { return shadows.index() * MaterialLayersVariant::kVariants + layers.index(); }
        std::string defines() const { return shadows.defines() + layers.defines(); }
        std::string label() const { return shadows.label() + layers.label(); }
    };
    // Expects the G-buffer, shadow maps, frame UBO, light SSBO and (with material layers) the
    // material table bound.
    void execute(const LightingTerms& terms, const RenderSettings& settings, Variant variant = {});
    std::vector<gl::Program*> programs() override { return programs_.built(); }

private:
    gl::ProgramVariants<Variant::kVariants> programs_;  // by Variant::index()
    FullscreenTriangle triangle_;
};

}  // namespace lit
