// The material table (GpuMaterial, shared.h): the passes that draw geometry read their draw's
// material, the lighting passes the one the G-buffer's ID target names per pixel.
#include "shared.h"

layout(std430, binding = LIT_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};
