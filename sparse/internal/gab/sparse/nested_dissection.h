// Nested-dissection ordering (George 1973) by multilevel vertex separators
// (Karypis & Kumar 1998; Ashcraft & Liu's FM refinement of separators), with
// the separator tree it builds kept as an explicit object: the update-cost
// bound of issue 19 speaks of these separators.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {

struct NestedDissectionOptions {
  // Subgraphs with at most this many vertices are not dissected further but
  // ordered by minimum degree with their halo (amd_graph.h). Mean flops over
  // igea, horse, nefertiti and bunny, 4 seeds, against 300 with plain AMD on
  // the leaves: 300 with the halo -1.6% (+13% ordering time), 450 -1.0%
  // (+3%), 600 -0.3% (-5%), 1200 +1.9% (-15%) (bench/TUNING.md, "Nested
  // dissection").
  int32_t leaf_size = 600;
  // A row with more than max(16, dense * sqrt(n)) off-diagonal entries is
  // removed before dissection and ordered last, as AmdOptions::dense does.
  // Negative: no row is dense.
  double dense = 10.0;
  // Each side of a separator may weigh up to (1 + imbalance) / 2 of the
  // vertices being dissected.
  double imbalance = 0.2;
  // Coarsening stops at this many vertices (or when matching stalls).
  int32_t coarsest_size = 120;
  // Separators grown on the coarsest graph from different seeds; the best is
  // kept. 4 against 6 (with candidates 3 against 4), mean flops over 12
  // seeds: igea +0.7%, horse -1.1%, nefertiti +1.1%, ordering ~10% faster.
  int32_t initial_tries = 4;
  // FM passes per level, and moves without improvement before a pass gives
  // up (one-sided: min(3 x separator, refine_patience), and 3x that).
  // One-sided, refine_passes counts pairs of passes: 2 pairs gave the flops
  // of 6 in 10% fewer instructions, 1 pair +4% flops. Two-sided
  // refinement measured best with 6 passes.
  int32_t refine_passes = 2;
  int32_t refine_patience = 80;
  // One-sided FM passes (each moves vertices into one side, alternating)
  // instead of two-sided ones: 10% fewer flops.
  bool one_sided_refinement = true;
  // Graphs of at least polish_from vertices end each refinement with one
  // two-sided pass after the one-sided ones. Mean flops over 8 seeds
  // (bench/TUNING.md): from 2,000 -1.3% for no measurable time, from 500
  // -1.5% for 8% more, every graph -0.5% (4 seeds).
  int32_t polish_from = 2000;
  // Coarsest separators carried up to the finest level with at most
  // trial_size vertices, where the smallest goes on and the others are
  // dropped. With `runs` taking several coarsenings, 1 (the best of
  // initial_tries) does as well as 3 below large_size, for less time.
  int32_t candidates = 1;
  int32_t trial_size = 2000;
  // Graphs of at least large_size vertices (the top separators, which weigh
  // most in the factor) carry large_candidates instead. With 5 runs and
  // AMD leaves, 8 against 4 measured -0.4%, -1.5%, -2.8% flops on igea,
  // horse and nefertiti (8 seeds); with 3 runs and halo leaves, 2 against 8
  // measured +0.45% flops (within the seeds' noise) for 14% less ordering
  // time (bench/TUNING.md, "Nested dissection").
  int32_t large_candidates = 2;
  int32_t large_size = 30000;
  // Where several candidates are carried, they are the best distinct
  // separators of candidate_tries tries per candidate on the coarsest graph.
  int32_t candidate_tries = 3;
  // Graphs of at least runs_from vertices are coarsened `runs` times below
  // a middle level (at most runs_levels coarsenings down, stopping at
  // 1 / runs_ratio of the vertices), each run separated and refined up to
  // it; the smallest separator there goes on. 3 (was 5): see
  // large_candidates.
  int32_t runs = 3;
  int32_t runs_from = 5000;
  int32_t runs_levels = 4;
  int32_t runs_ratio = 30;
  // Seed of the (self-contained, platform-independent) generators that order
  // the matching's visits and pick seeds, one stream per piece derived from
  // its parent's: the result depends on nothing else.
  uint64_t seed = 0x9E3779B97F4A7C15ull;
  // Threads: a pool of this many workers; a separator whose two sides both
  // have at least thread_size vertices hands one side to the pool as a task
  // (an idle worker takes it, or the forking one after its other side). The
  // permutation and tree are the same for every thread count.
  int32_t threads = 1;
  int32_t thread_size = 4000;
  // With threads > 1, a graph with at least this many adjacency entries
  // hands half its contraction to the pool (about 20 ms of work on one).
  int64_t thread_entries = 1 << 20;
};

// The dissection as a tree. Node s owns the pivots perm[first .. first + size);
// its subtree (s and all its descendants) owns perm[subtree_first .. first + size),
// a contiguous range. A separator node's columns separate its children: no
// edge of the graph joins the subtrees of two different children. A leaf was
// ordered by AMD as one subgraph. Nodes are stored children before parents.
struct SeparatorTree {
  struct Node {
    int32_t first = 0;
    int32_t size = 0;
    int32_t subtree_first = 0;
    int32_t parent = -1;  // -1 for a root (one root per connected component,
                          // or one root holding the dense rows)
    bool leaf = false;
  };
  std::vector<Node> nodes;
  std::vector<int32_t> child_ptr;  // nodes.size() + 1 offsets into children
  std::vector<int32_t> children;   // in increasing column order
  std::vector<int32_t> column_node;  // n: the node owning pivot k (perm[k]'s separator or leaf)
};

// Orders a symmetric matrix given by its lower triangle (only the pattern is
// read; the diagonal is optional; entries above the diagonal are an error) by
// nested dissection of its graph symmetric_graph(lower): each connected
// component separately; a separator is ordered after both sides, recursively;
// small pieces by minimum degree with the separators around them in view;
// dense rows last. On success perm[k] is the original
// index of the k-th pivot (as amd_order) and *tree, when given, holds the
// dissection. Deterministic: the same input and options give the same perm
// on every machine. Time about O(nnz(A) log n); memory O(nnz(A) + n).
Status nested_dissection_order(const CscMatrix& lower, std::vector<int32_t>* perm,
                               const NestedDissectionOptions& options = {},
                               SeparatorTree* tree = nullptr);

// The same from the graph itself, symmetric_graph(lower) (both triangles,
// no diagonal, sorted lists; not checked), for a caller that needs that
// graph anyway (the symbolic analysis).
Status nested_dissection_order_of_graph(const CscMatrix& graph, std::vector<int32_t>* perm,
                                        const NestedDissectionOptions& options = {},
                                        SeparatorTree* tree = nullptr);

// The separator bound on the cost of an update (issue 19), for every
// original index j: an upper bound on the entries of L that adding a row with
// one nonzero in column j touches, the nonzeros of L in the columns of the
// elimination-tree path from j to the root, for the factor of the matrix the
// tree was built from, ordered by perm (or by perm followed by a postorder of
// its elimination tree, which leaves each vertex's path and column counts as
// they are). With t the node holding j at pivot k (perm[k] = j),
// m = t.first + t.size - k its columns from j's on, and A(s) the sum of the
// sizes of s's proper ancestors,
//
//   bound(j) = m (m + 1) / 2 + m A(t)
//              + sum over the proper ancestors a of t of |a| (|a| + 1) / 2 + |a| A(a).
//
// Why: the subdiagonal rows of L's column c are the later columns reached
// from c through earlier ones (Rose, Tarjan & Lueker 1976). A path leaving
// the subtree of c's node s must cross an ancestor's separator, whose columns
// come after c, so L's column c has at most (s's columns from c on) + A(s)
// entries; its elimination-tree parent is the first of them, so the path
// climbs through the later columns of t and then through ancestors only, each
// column once. Summing the column bound over those columns gives the formula:
// the O(n) per-update bound of the paper for a graph whose separators grow
// like sqrt of their subgraph. Fails on a tree and perm that do not fit
// (sizes, column ranges, parents after children).
Status separator_update_bounds(const SeparatorTree& tree, const std::vector<int32_t>& perm,
                               std::vector<int64_t>* bound);

}  // namespace gab
