// What the valence coder conquers (valence_coder.h): a closed oriented
// combinatorial manifold. Open meshes are closed first (close_boundaries):
// one dummy vertex per boundary loop, flagged in the stream, whose
// triangles the decoder drops.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/manifold_cut.h"

namespace gab {

// A closed oriented combinatorial manifold: every half-edge has an opposite.
struct ClosedMesh {
  int32_t num_vertices = 0;
  std::vector<int32_t> triangles;  // 3 per triangle
  std::vector<int32_t> opposite;   // per half-edge (see manifold_cut.h), all >= 0
  std::vector<uint8_t> dummy;      // per vertex: 1 for a boundary loop's dummy
};

// The cut mesh with each boundary loop closed by a fan of triangles around a
// dummy vertex (numbered after the cut's vertices, in the order of the
// loops' first boundary half-edges). The cut's triangles keep their indices.
// O(T).
ClosedMesh close_boundaries(const ManifoldCut& cut);
// The same, taking the cut's triangles and opposites (left empty; its
// other fields stay) instead of copying them: a closed mesh costs no copy.
ClosedMesh close_boundaries(ManifoldCut* cut);

// Connected components of a closed mesh (through the opposites). O(T).
int32_t count_components(const ClosedMesh& mesh);

}  // namespace gab
