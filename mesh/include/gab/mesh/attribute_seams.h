// Per-corner attributes made per-vertex, for the formats that hold one
// value per vertex (PLY, OFF; OBJ for colours): a vertex whose corners refer
// to different elements (a seam: two texture coordinates, two normals)
// becomes one vertex per distinct combination.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh.h"

namespace gab {

// `mesh` with the per-corner attributes that `selected` names (one flag per
// attribute; every per-corner one when `selected` is empty) made per vertex.
// Each vertex keeps its index for the combination of elements its first
// corner (in triangle order) refers to; every other combination met at its
// corners is a new vertex, appended in the order first met, with the
// position and the per-vertex attributes of the vertex it copies; triangles
// are renamed, their order and corner order kept (so the per-corner
// attributes not selected stay valid). A vertex with no corner gets zeros in
// the attributes made per vertex. `added_vertices` (when given) receives the
// number of vertices added. `mesh` must be valid (validate_mesh). O(V + T *
// selected attributes * combinations per vertex).
Mesh split_attribute_seams(const Mesh& mesh, const std::vector<bool>& selected = {},
                           int64_t* added_vertices = nullptr);

}  // namespace gab
