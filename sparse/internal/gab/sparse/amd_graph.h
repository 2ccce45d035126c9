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

// Minimum degree on the first `inner` vertices of such a graph, the others
// being its halo: vertices that stay in the graph, so that they count in
// the degrees, but are never chosen as pivots ("halo approximate minimum
// degree", Pellegrini, Roman & Amestoy, "Hybridizing nested dissection and
// halo approximate minimum degree for efficient sparse matrix ordering",
// Concurrency: Pract. Exper. 12, 2000). A nested-dissection leaf's halo is
// the separators around it, eliminated after it: the leaf's vertices next
// to them then go last, where plain AMD on the leaf alone ends anywhere.
// perm gets the `inner` pivots. The halo's lists need only their inner
// neighbours (edges inside the halo change no inner vertex's degree); dense
// rows are not set apart.
Status amd_order_graph_with_halo(int32_t n, int32_t inner, const int32_t* xadj, const int32_t* adj,
                                 std::vector<int32_t>* perm, const AmdOptions& options = AmdOptions());

}  // namespace gab
