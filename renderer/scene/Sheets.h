#pragma once
// KHR_materials_transmission drawn as a thin sheet (docs/MATERIALS.md, "Transmission"): which
// materials are sheets, for the rasterizer (GpuScene) and the reference (ReferenceScene) alike.
// As material_table.glsl materialIsSheet.

#include "scene/Scene.h"

namespace lit {

// A material whose dielectric share lets light through: transmission > 0, metallic < 1 (also
// from a file's factors before they are loaded: the memory budget's colour layers).
inline bool drawnAsSheet(double transmission, double metallic) { return transmission > 0.0 && metallic < 1.0; }
inline bool drawnAsSheet(const Material& m) { return drawnAsSheet(m.transmission, m.metallic); }

}  // namespace lit
