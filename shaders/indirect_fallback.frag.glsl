#version 450 core
// Indirect fallback (IndirectFallbackPass): the pixels the resolve marked (no low-resolution
// neighbour on their surface, or too smooth for reduced-resolution specular) trace their own
// cones at full resolution; early depth tests against the resolve's trace mask skip all others.
// The body is include/indirect_resolve.glsl.
#define LIT_INDIRECT_FALLBACK 1
#include "indirect_resolve.glsl"
