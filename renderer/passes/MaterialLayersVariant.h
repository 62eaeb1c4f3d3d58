#pragma once
// Whether the passes that light the G-buffer read each pixel's specular layers
// (KHR_materials_ior, _specular, _clearcoat; docs/MATERIALS.md) from the material table, or take
// the metal-rough defaults: a program variant (LIT_MATERIAL_LAYERS, gbuffer.glsl), since
// llvmpipe pays for the ID fetch and the table read on every pixel even when no material has a
// layer, a measurable share of the lighting and cone passes.

#include <cstddef>
#include <string>

namespace lit {

struct MaterialLayersVariant {
    bool on = true;

    static constexpr std::size_t kVariants = 2;
    std::size_t index() const { return on ? 1u : 0u; }
    std::string defines() const { return std::string("#define LIT_MATERIAL_LAYERS ") + (on ? "1\n" : "0\n"); }
    std::string label() const { return on ? "" : " (no material layers)"; }
};

}  // namespace lit
