// Vertex normals from a mesh's own triangles: what most exporters write
// when asked for smooth normals, and what a mesh without normals can be
// given before it is coded.
#pragma once

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_attribute.h"

namespace gab {

// Per vertex, the sum of its triangles' normals weighted by their areas
// (the cross products of their edges, in the triangles' orientation), of
// unit length; (0, 0, 1) where the sum is zero (a vertex in no triangle, or
// only in degenerate ones). A kNormal attribute, float32-typed. O(V + T).
MeshAttribute area_weighted_normals(const Mesh& mesh);

}  // namespace gab
