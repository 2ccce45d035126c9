// AMD (amd.h) on a graph already held as full adjacency lists, for the
// nested-dissection leaves: no lower triangle to build, validate and
// transpose back. Internal to the engine.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/amd.h"

namespace gab {

// The ordering amd_order gives for the lower triangle of the pattern whose
// off-diagonal entries are the lists adj[xadj[i] .. xadj[i + 1]): both
// triangles, no self loops, each list strictly increasing (not checked: the
// caller guarantees it). perm[k] is the k-th pivot. n < 2^30.
Status amd_order_graph(int32_t n, const int32_t* xadj, const int32_t* adj, std::vector<int32_t>* perm,
                       const AmdOptions& options = AmdOptions());

}  // namespace gab
