#version 450 core
// The node IDs of transmissive sheets into the G-buffer's ID target after the lighting (SheetPass):
// a click on a sheet picks it and the selection outline follows it, as the G-buffer pass writes
// them for opaque surfaces (gbuffer.frag.glsl's outNodeId).
#include "material.glsl"

#include "geometry_varyings.glsl"

layout(location = 0) out uvec4 outNodeId;

layout(location = LIT_LOC_NODE_ID) uniform uint uNodeId;
layout(location = LIT_LOC_PRIMITIVE) uniform uint uPrimitive;

void main() {
    GpuMaterial m = materials[uMaterialIndex];
    if (materialAlphaDiscard(m, materialBaseColor(m, fs.uv).a)) discard;
    outNodeId = uvec4(uNodeId, uPrimitive, uint(uMaterialIndex), 0u);
}
