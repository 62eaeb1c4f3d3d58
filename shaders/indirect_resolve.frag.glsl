#version 450 core
// Indirect resolve (IndirectResolvePass): upsampling and temporal accumulation of the reduced-
// resolution indirect terms; pixels that need their own cone trace are marked for
// indirect_fallback.frag.glsl. The body is include/indirect_resolve.glsl.
#include "indirect_resolve.glsl"
