#pragma once
// KHR_materials_transmission drawn as a thin sheet (docs/MATERIALS.md, "Transmission"): which
// materials are sheets, for the rasterizer (GpuScene) and the reference (ReferenceScene) alike.
// As material_table.glsl materialIsSheet.

#include <glm/exponential.hpp>

#include "scene/Scene.h"

namespace lit {

// A material whose dielectric share lets light through: transmission > 0, metallic < 1 (also
// from a file's factors before they are loaded: the memory budget's colour layers).
inline bool drawnAsSheet(double transmission, double metallic) { return transmission > 0.0 && metallic < 1.0; }
inline bool drawnAsSheet(const Material& m) { return drawnAsSheet(m.transmission, m.metallic); }

// KHR_materials_volume: the index of refraction of a sheet's volume (thickness > 0; its
// KHR_materials_ior, at least 1), whose faces bend the light that crosses them; 0 for a thin-walled
// material or one that is no sheet.
inline float refractiveIndexOfVolume(const Material& m) {
    return drawnAsSheet(m) && m.thickness > 0.0f && m.ior >= 1.0f ? m.ior : 0.0f;
}

// KHR_materials_volume's absorption coefficient σ_a (1/m, world, per channel): a sheet with a
// thickness encloses a medium that leaves attenuationColor of the light after attenuationDistance,
// exp(−σ_a·x) = attenuationColor^(x / attenuationDistance) (docs/MATERIALS.md, "Volume"). 0 for a
// thin-walled material (thickness 0), an infinite distance, or a material that is no sheet.
inline glm::vec3 volumeAbsorption(const Material& m) {
    if (!drawnAsSheet(m) || m.thickness <= 0.0f || m.attenuationDistance <= 0.0f) return glm::vec3(0.0f);
    // A channel the colour leaves at 0 absorbs everything over any distance worth drawing.
    return -glm::log(glm::max(m.attenuationColor, glm::vec3(1e-6f))) / m.attenuationDistance;
}

}  // namespace lit
