// The material table (GpuMaterial, shared.h): the passes that draw geometry read their draw's
// material, the lighting passes the one the G-buffer's ID target names per pixel.
#include "shared.h"

layout(std430, binding = LIT_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};

// A transmissive sheet (KHR_materials_transmission, docs/MATERIALS.md "Transmission"): SheetPass
// draws it over the lit image; the G-buffer, the shadow maps and the voxelization discard it.
// As GpuScene.h drawnAsSheet.
bool materialIsSheet(GpuMaterial m) { return m.alpha.y > 0.0 && m.params.x < 1.0; }
