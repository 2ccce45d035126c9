// Nested-dissection ordering (George 1973) by multilevel vertex separators
// (Karypis & Kumar 1998; Ashcraft & Liu's FM refinement of separators), with
// the separator tree it builds kept as an explicit object, and the bound on
// an update's cost that its separators give.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {

// The knobs of the dissection. The defaults are measured (the notes sit in
// sparse/src/ordering/nested_dissection.cpp); a caller normally sets threads
// only. Every field changes the permutation except threads, thread_size
// and thread_entries.
struct NestedDissectionOptions {
  // Pieces of at most this many vertices are ordered by minimum degree with
  // their halo (the separators around them) instead of being dissected.
  int32_t leaf_size = 600;
  // A row with more than max(16, dense * sqrt(n)) off-diagonal entries is
  // ordered last, as AmdOptions::dense; negative: no row is dense.
  double dense = 10.0;
  // Each side of a separator weighs at most (1 + imbalance) / 2 of the piece.
  double imbalance = 0.2;
  // Coarsening stops at this many vertices (or when matching stalls).
  int32_t coarsest_size = 120;
  // Separators grown from different seeds on the coarsest graph; the best is kept.
  int32_t initial_tries = 4;
  // FM refinement per level: passes (pairs of passes when one-sided), and
  // moves without improvement before a pass gives up.
  int32_t refine_passes = 2;
  int32_t refine_patience = 80;
  // One-sided FM passes (each moves vertices into one side, alternating)
  // instead of two-sided ones.
  bool one_sided_refinement = true;
  // Graphs of at least polish_from vertices end each refinement with one
  // two-sided pass.
  int32_t polish_from = 2000;
  // Coarsest separators carried up to the finest level, for graphs below
  // large_size vertices and from it on; the smallest at trial_size vertices
  // goes on. Each candidate is the best of candidate_tries tries.
  int32_t candidates = 1;
  int32_t trial_size = 2000;
  int32_t large_candidates = 2;
  int32_t large_size = 30000;
  int32_t candidate_tries = 3;
  // Graphs of at least runs_from vertices are coarsened `runs` times below a
  // middle level (at most runs_levels coarsenings, down to 1 / runs_ratio of
  // the vertices); the smallest separator there goes on.
  int32_t runs = 3;
  int32_t runs_from = 5000;
  int32_t runs_levels = 4;
  int32_t runs_ratio = 30;
  // Seed of the platform-independent generators (one stream per piece): the
  // result depends on nothing else.
  uint64_t seed = 0x9E3779B97F4A7C15ull;
  // A pool of this many workers dissects the two sides of a separator
  // concurrently when both have thread_size vertices or more, and contracts
  // graphs of thread_entries adjacency entries or more by halves. The
  // permutation and tree are the same for every thread count.
  int32_t threads = 1;
  int32_t thread_size = 4000;
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

// The separator bound on the cost of an update, for every
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
