#pragma once
#include "scene/Scene.h"

namespace lit {

// Fills Vertex::tangent for a triangle list from positions, normals and UVs (per-triangle UV
// derivatives accumulated per vertex, Gram-Schmidt against the normal, handedness in w).
// Vertices whose triangles have degenerate UVs get any unit vector perpendicular to the normal.
void computeTangents(Primitive& primitive);

// Fills flat normals for a primitive without them, as glTF requires: the primitive is unwelded
// (each triangle gets its own three vertices, indices become 0,1,2,...) and every vertex gets
// its triangle's face normal. Call it before computeTangents.
void computeNormals(Primitive& primitive);

}  // namespace lit
