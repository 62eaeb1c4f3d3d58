#pragma once
#include "scene/Scene.h"

namespace lit {

// Fills Vertex::tangent for a triangle list from positions, normals and UVs (per-triangle UV
// derivatives accumulated per vertex, Gram-Schmidt against the normal, handedness in w).
// `uvSet` is the set the normal texture reads (0: Vertex::uv, 1: Vertex::uv1; drawnTexCoord):
// a normal map is painted in the frame of its own UVs. Vertices whose triangles have degenerate
// UVs get any unit vector perpendicular to the normal.
void computeTangents(Primitive& primitive, int uvSet = 0);

// Fills flat normals for a primitive without them, as glTF requires: the primitive is unwelded
// (each triangle gets its own three vertices, indices become 0,1,2,...) and every vertex gets
// its triangle's face normal. Call it before computeTangents.
void computeNormals(Primitive& primitive);

}  // namespace lit
