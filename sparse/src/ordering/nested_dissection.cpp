// Nested-dissection ordering (George, "Nested dissection of a regular finite
// element mesh", SIAM J. Numer. Anal. 10(2), 1973): a vertex separator S
// splits the graph into A and B with no edge between them; ordering A, then
// B, then S confines the fill of A's and B's columns to themselves and S, and
// the same is done to A and B recursively. Separators come from the
// multilevel scheme (nested_dissection_bisect.cpp); pieces below leaf_size
// are ordered by minimum degree, as METIS's ND hands its small pieces to
// minimum degree (Karypis & Kumar 1998, sec. 6), here with the piece's halo
// (the separators around it) in the graph, as Scotch does (Pellegrini,
// Roman & Amestoy 2000); rows denser than AMD's threshold are taken out
// first and ordered last (they would sit in every separator anyway).
//
// The recursion records the separator tree: a node per separator (and per
// AMD leaf), its columns, its subtree's columns and its parent.
//
// Why NestedDissectionOptions' defaults (flops are the factor's, means over
// igea, horse, nefertiti and bunny unless said; bench/bench_ordering.cpp):
// * leaf_size 600: against 300 with plain AMD on the leaves, with the halo
//   300 gave -1.6% flops (+13% ordering time), 450 -1.0% (+3%), 600 -0.3%
//   (-5%), 1200 +1.9% (-15%).
// * initial_tries 4 against 6 (with candidates 3 against 4), 12 seeds:
//   igea +0.7%, horse -1.1%, nefertiti +1.1%, ordering ~10% faster.
// * refine_passes 2 one-sided pairs: the flops of 6 in 10% fewer
//   instructions; 1 pair +4% flops. Two-sided refinement did best with 6
//   passes, and one-sided passes give 10% fewer flops than it.
// * polish_from 2000, 8 seeds: -1.3% flops for no measurable time; from 500
//   -1.5% for 8% more time; every graph -0.5% (4 seeds).
// * candidates 1: with several runs, the best of initial_tries does as well
//   as 3 below large_size, for less time.
// * large_candidates 2: with 5 runs and AMD leaves, 8 against 4 gave -0.4%,
//   -1.5%, -2.8% flops on igea, horse and nefertiti (8 seeds); with 3 runs
//   and halo leaves, 2 against 8 gave +0.45% flops (within the seeds' noise)
//   for 14% less ordering time.
// * runs 3 (was 5): the same measurement as large_candidates.
// * thread_entries 2^20: about 20 ms of contraction work on one thread.
// The tables and the commands behind these figures: docs/tuning-engine.md.
#include "gab/sparse/nested_dissection.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <string>

#include "gab/sparse/amd_graph.h"
#include "ordering/fork_join.h"
#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace {

using nd::Graph;

// A subtree's generator seed, from its parent's and which child it is: every
// piece draws from its own stream, so the permutation does not depend on the
// order the pieces are dissected in, nor on how many threads do it.
uint64_t child_seed(uint64_t parent, uint64_t child) {
  SplitMix64 mix(parent ^ (0xD1B54A32D192ED03ull * (child + 1)));
  return mix.next();
}

// The dissection of one graph into perm_; on one thread, or with a pool
// whose workers take the sides of large separators as tasks.
class Dissection {
 public:
  // `full` is the whole graph (both triangles, sorted lists), whose
  // vertices with halo_ok[v] == 0 (the dense rows) are out of the dissection.
  Dissection(const NestedDissectionOptions& options, const CscMatrix& full, const std::vector<uint8_t>& halo_ok,
             std::vector<int32_t>* perm, nd::ForkJoinPool* pool)
      : options_(options), full_(full), halo_ok_(halo_ok), perm_(*perm), pool_(pool), ws_(pool ? pool->size() : 1),
        leaf_ws_(ws_.size()) {
    for (size_t w = 0; w < ws_.size(); ++w) {
      ws_[w].pool = pool;
      ws_[w].worker = static_cast<int32_t>(w);
    }
  }

  // Orders g, whose vertex v is original vertex label[v], into
  // perm[begin .. begin + g.n) on pool worker `worker` (whose workspace it
  // uses); the tree nodes of
  // its pieces are appended to *nodes (children before parents), the
  // indices of their roots in *nodes to *roots. h holds coarsenings of g
  // inherited from its parent (none for the whole graph). With
  // find_components, g's connected components are ordered one by one. The
  // sides of a separator are not searched for components: the search cost a
  // tenth of the ordering's time and found none on the shared meshes, and
  // find_separator copes with a disconnected graph (its separator may then
  // be empty). Consumes g, label and h.
  Status order(Graph&& g, std::vector<int32_t>&& label, nd::Hierarchy&& h, bool find_components, int32_t begin,
               uint64_t seed, int32_t worker, std::vector<SeparatorTree::Node>* nodes, std::vector<int32_t>* roots) {
    if (g.n == 0) return Status::Ok();
    nd::Workspace& ws = ws_[worker];
    ws.grow(g.n);
    if (find_components) {
      std::vector<int32_t> component;
      const int32_t count = nd::connected_components(g, &ws, &component);
      if (count > 1) return order_components(g, label, h, component, count, begin, seed, worker, nodes, roots);
    }
    if (is_leaf(g.n)) return order_leaf(g.n, label, begin, worker, nodes, roots);

    std::vector<uint8_t> where;
    nd::Rng rng(seed);
    nd::find_separator(g, options_, &rng, &ws, &h, &where);
    std::vector<int32_t> side[3];
    for (int32_t v = 0; v < g.n; ++v) side[where[v]].push_back(v);
    // No proper separator (a clique, say), or one so lopsided that recursing
    // on it would go deep for little gain: the piece is ordered whole.
    const size_t larger = std::max(side[nd::kLeft].size(), side[nd::kRight].size());
    if (side[nd::kLeft].empty() || side[nd::kRight].empty() || larger > 0.9 * g.n) {
      return order_leaf(g.n, label, begin, worker, nodes, roots);
    }

    const int32_t part_size[2] = {static_cast<int32_t>(side[nd::kLeft].size()),
                                  static_cast<int32_t>(side[nd::kRight].size())};
    const int32_t separator_first = begin + part_size[0] + part_size[1];
    for (size_t k = 0; k < side[nd::kSeparator].size(); ++k) {
      perm_[separator_first + k] = label[side[nd::kSeparator][k]];
    }
    const int32_t separator_size = static_cast<int32_t>(side[nd::kSeparator].size());
    const int32_t part_begin[2] = {begin, begin + part_size[0]};
    Graph part[2];
    std::vector<int32_t> part_label[2];
    nd::Hierarchy part_hierarchy[2];
    // Side s's subgraph, labels and coarsenings, read off g with workspace ws.
    auto build_part = [&](int s, nd::Workspace* ws) {
      // A part that will be a leaf needs only its vertices (order_leaf reads
      // the whole graph); the others their subgraph and coarsenings.
      if (is_leaf(static_cast<int32_t>(side[s].size()))) {
        part[s].n = static_cast<int32_t>(side[s].size());
      } else {
        nd::induced_subgraph(g, side[s], ws, &part[s]);
        nd::restrict_hierarchy(g, h, side[s], options_.coarsest_size, ws, &part_hierarchy[s]);
      }
      part_label[s].reserve(side[s].size());
      for (int32_t v : side[s]) part_label[s].push_back(label[v]);
    };
    // The parts are all the recursion needs: g goes once both are built.
    auto release_graph = [&] {
      g = Graph();
      label = std::vector<int32_t>();
      h = nd::Hierarchy();
    };
    std::vector<int32_t> children;
    if (pool_ != nullptr && std::min(part_size[0], part_size[1]) >= options_.thread_size) {
      // The left side as a task any worker may take, the right one here,
      // each building its part (reading g, h and label, which the later of
      // the two releases); the left's nodes go first, as on one thread.
      std::atomic<int32_t> built{0};
      std::vector<SeparatorTree::Node> left_nodes, right_nodes;
      std::vector<int32_t> left_roots, right_roots;
      Status left_status = Status::Ok();
      nd::ForkJoinPool::Task left;
      left.fn = [&](int32_t w) {
        ws_[w].grow(g.n);  // build_part indexes the workspace by g's vertices
        build_part(0, &ws_[w]);
        if (built.fetch_add(1) == 1) release_graph();
        left_status = order(std::move(part[0]), std::move(part_label[0]), std::move(part_hierarchy[0]), false,
                            part_begin[0], child_seed(seed, 0), w, &left_nodes, &left_roots);
      };
      Status right_status = Status::Ok();
      pool_->fork_run_join(&left, [&] {
        build_part(1, &ws);
        if (built.fetch_add(1) == 1) release_graph();
        right_status = order(std::move(part[1]), std::move(part_label[1]), std::move(part_hierarchy[1]), false,
                             part_begin[1], child_seed(seed, 1), worker, &right_nodes, &right_roots);
      }, worker);
      GAB_RETURN_IF_ERROR(left_status);
      GAB_RETURN_IF_ERROR(right_status);
      append_nodes(left_nodes, left_roots, nodes, &children);
      append_nodes(right_nodes, right_roots, nodes, &children);
    } else {
      build_part(0, &ws);
      build_part(1, &ws);
      release_graph();
      for (int s = 0; s < 2; ++s) {
        GAB_RETURN_IF_ERROR(order(std::move(part[s]), std::move(part_label[s]), std::move(part_hierarchy[s]), false,
                                  part_begin[s], child_seed(seed, s), worker, nodes, &children));
      }
    }
    roots->push_back(add_node(separator_first, separator_size, begin, /*leaf=*/false, children, nodes));
    return Status::Ok();
  }

  // The dense rows, ordered last, as one root separating everything else.
  void add_dense_root(int32_t first, int32_t size, const std::vector<int32_t>& children,
                      std::vector<SeparatorTree::Node>* nodes) {
    add_node(first, size, 0, /*leaf=*/false, children, nodes);
  }

  void finish_tree(std::vector<SeparatorTree::Node>&& nodes, SeparatorTree* tree) {
    tree->nodes = std::move(nodes);
    const size_t count = tree->nodes.size();
    tree->child_ptr.assign(count + 1, 0);
    for (const SeparatorTree::Node& node : tree->nodes) {
      if (node.parent >= 0) ++tree->child_ptr[node.parent + 1];
    }
    for (size_t s = 0; s < count; ++s) tree->child_ptr[s + 1] += tree->child_ptr[s];
    tree->children.assign(tree->child_ptr[count], 0);
    std::vector<int32_t> cursor(tree->child_ptr.begin(), tree->child_ptr.end() - 1);
    // Nodes are numbered in column order, so each children list comes out sorted.
    for (size_t s = 0; s < count; ++s) {
      const int32_t parent = tree->nodes[s].parent;
      if (parent >= 0) tree->children[cursor[parent]++] = static_cast<int32_t>(s);
    }
    tree->column_node.assign(perm_.size(), -1);
    for (size_t s = 0; s < count; ++s) {
      const SeparatorTree::Node& node = tree->nodes[s];
      std::fill(tree->column_node.begin() + node.first, tree->column_node.begin() + node.first + node.size,
                static_cast<int32_t>(s));
    }
  }

 private:
  // Pieces this small are ordered by AMD whole.
  bool is_leaf(int32_t n) const { return n <= std::max<int32_t>(options_.leaf_size, 2); }

  Status order_components(const Graph& g, const std::vector<int32_t>& label, const nd::Hierarchy& h,
                          const std::vector<int32_t>& component, int32_t count, int32_t begin, uint64_t seed,
                          int32_t worker, std::vector<SeparatorTree::Node>* nodes, std::vector<int32_t>* roots) {
    nd::Workspace& ws = ws_[worker];
    std::vector<std::vector<int32_t>> members(static_cast<size_t>(count));
    for (int32_t v = 0; v < g.n; ++v) members[component[v]].push_back(v);
    for (int32_t c = 0; c < count; ++c) {
      Graph sub;
      nd::induced_subgraph(g, members[c], &ws, &sub);
      nd::Hierarchy sub_hierarchy;
      if (!is_leaf(sub.n)) nd::restrict_hierarchy(g, h, members[c], options_.coarsest_size, &ws, &sub_hierarchy);
      std::vector<int32_t> sub_label;
      sub_label.reserve(members[c].size());
      for (int32_t v : members[c]) sub_label.push_back(label[v]);
      // Components one after another on this thread: a mesh with several
      // large components is rare, and each still forks below.
      GAB_RETURN_IF_ERROR(order(std::move(sub), std::move(sub_label), std::move(sub_hierarchy), false, begin,
                                child_seed(seed, 2 + static_cast<uint64_t>(c)), worker, nodes, roots));
      begin += static_cast<int32_t>(members[c].size());
    }
    return Status::Ok();
  }

  // A piece ordered by minimum degree with its halo (amd_graph.h): the
  // piece's vertices and, never pivots, their neighbours outside it in the
  // whole graph, which are the separators around the piece (all ordered
  // after it). Measured against AMD on the piece alone: docs/tuning-engine.md.
  // The piece is label[0 .. m).
  Status order_leaf(int32_t m, const std::vector<int32_t>& label, int32_t begin, int32_t worker,
                    std::vector<SeparatorTree::Node>* nodes, std::vector<int32_t>* roots) {
    LeafWorkspace& lw = leaf_ws_[worker];
    if (lw.local.empty()) lw.local.assign(perm_.size(), -1);
    for (int32_t k = 0; k < m; ++k) lw.local[label[k]] = k;
    // The halo, numbered from m in order of first sight.
    lw.halo.clear();
    for (int32_t k = 0; k < m; ++k) {
      const int32_t v = label[k];
      for (int32_t p = full_.colptr[v]; p < full_.colptr[v + 1]; ++p) {
        const int32_t u = full_.rowind[p];
        if (lw.local[u] >= 0 || !halo_ok_[u]) continue;
        lw.local[u] = m + static_cast<int32_t>(lw.halo.size());
        lw.halo.push_back(u);
      }
    }
    const int32_t total = m + static_cast<int32_t>(lw.halo.size());
    // Lists: a piece vertex's neighbours (piece and halo), a halo vertex's
    // piece neighbours, each list sorted.
    lw.xadj.assign(static_cast<size_t>(total) + 1, 0);
    for (int32_t k = 0; k < m; ++k) {
      const int32_t v = label[k];
      for (int32_t p = full_.colptr[v]; p < full_.colptr[v + 1]; ++p) {
        const int32_t x = lw.local[full_.rowind[p]];
        if (x < 0) continue;
        ++lw.xadj[k + 1];
        if (x >= m) ++lw.xadj[x + 1];
      }
    }
    for (int32_t x = 0; x < total; ++x) lw.xadj[x + 1] += lw.xadj[x];
    lw.adj.resize(static_cast<size_t>(lw.xadj[total]));
    lw.cursor.assign(lw.xadj.begin(), lw.xadj.end() - 1);
    for (int32_t k = 0; k < m; ++k) {
      const int32_t v = label[k];
      for (int32_t p = full_.colptr[v]; p < full_.colptr[v + 1]; ++p) {
        const int32_t x = lw.local[full_.rowind[p]];
        if (x < 0) continue;
        lw.adj[lw.cursor[k]++] = x;
        if (x >= m) lw.adj[lw.cursor[x]++] = k;  // k increasing: halo lists come out sorted
      }
      std::sort(lw.adj.begin() + lw.xadj[k], lw.adj.begin() + lw.xadj[k + 1]);
    }
    for (int32_t k = 0; k < m; ++k) lw.local[label[k]] = -1;
    for (int32_t u : lw.halo) lw.local[u] = -1;
    std::vector<int32_t> order;
    GAB_RETURN_IF_ERROR(amd_order_graph_with_halo(total, m, lw.xadj.data(), lw.adj.data(), &order));
    for (int32_t k = 0; k < m; ++k) perm_[begin + k] = label[order[k]];
    roots->push_back(add_node(begin, m, begin, /*leaf=*/true, {}, nodes));
    return Status::Ok();
  }

  static int32_t add_node(int32_t first, int32_t size, int32_t subtree_first, bool leaf,
                          const std::vector<int32_t>& children, std::vector<SeparatorTree::Node>* nodes) {
    const int32_t id = static_cast<int32_t>(nodes->size());
    SeparatorTree::Node node;
    node.first = first;
    node.size = size;
    node.subtree_first = subtree_first;
    node.leaf = leaf;
    nodes->push_back(node);
    for (int32_t c : children) (*nodes)[c].parent = id;
    return id;
  }

  // Appends a side's nodes (numbered from 0) after *nodes, renumbered, and
  // its roots, renumbered, to *roots.
  static void append_nodes(const std::vector<SeparatorTree::Node>& side, const std::vector<int32_t>& side_roots,
                           std::vector<SeparatorTree::Node>* nodes, std::vector<int32_t>* roots) {
    const int32_t offset = static_cast<int32_t>(nodes->size());
    for (SeparatorTree::Node node : side) {
      if (node.parent >= 0) node.parent += offset;
      nodes->push_back(node);
    }
    for (int32_t r : side_roots) roots->push_back(r + offset);
  }

  // A leaf's lists with its halo, built per worker.
  struct LeafWorkspace {
    std::vector<int32_t> local;  // whole-graph vertex -> its number in the leaf's graph; -1 elsewhere
    std::vector<int32_t> halo, xadj, adj, cursor;
  };

  const NestedDissectionOptions& options_;
  const CscMatrix& full_;
  const std::vector<uint8_t>& halo_ok_;
  std::vector<int32_t>& perm_;
  nd::ForkJoinPool* pool_;         // null: everything on the calling thread
  std::vector<nd::Workspace> ws_;  // one per worker
  std::vector<LeafWorkspace> leaf_ws_;  // one per worker
};

Status check_lower(const CscMatrix& lower) {
  GAB_RETURN_IF_ERROR(check_csc(lower));
  if (lower.nrows != lower.ncols) {
    return Status::Error(StatusCode::kInvalidArgument, "nested_dissection_order: matrix is not square");
  }
  for (int32_t j = 0; j < lower.ncols; ++j) {
    if (lower.colptr[j] < lower.colptr[j + 1] && lower.rowind[lower.colptr[j]] < j) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "nested_dissection_order: entry above the diagonal in column " +
                               std::to_string(j));
    }
  }
  return Status::Ok();
}

}  // namespace

Status nested_dissection_order(const CscMatrix& lower, std::vector<int32_t>* perm,
                               const NestedDissectionOptions& options, SeparatorTree* tree) {
  GAB_RETURN_IF_ERROR(check_lower(lower));
  return nested_dissection_order_of_graph(symmetric_graph(lower), perm, options, tree);
}

Status nested_dissection_order_of_graph(const CscMatrix& full, std::vector<int32_t>* perm,
                                        const NestedDissectionOptions& options, SeparatorTree* tree) {
  const int32_t n = full.ncols;
  perm->assign(static_cast<size_t>(n), -1);

  // Dense rows (AMD's rule): out of the graph, ordered last.
  const int32_t dense_limit =
      options.dense < 0 ? n : std::max(16, static_cast<int32_t>(options.dense * std::sqrt(double(n))));
  std::vector<int32_t> kept, dense;
  std::vector<uint8_t> halo_ok(static_cast<size_t>(n), 1);
  for (int32_t v = 0; v < n; ++v) {
    const bool is_dense = full.colptr[v + 1] - full.colptr[v] > dense_limit;
    (is_dense ? dense : kept).push_back(v);
    halo_ok[v] = is_dense ? 0 : 1;
  }

  Graph g;
  g.n = n;
  g.xadj.assign(full.colptr.begin(), full.colptr.end());
  g.adj.assign(full.rowind.begin(), full.rowind.end());
  // adjw stays empty: every edge of the matrix graph weighs 1.
  g.vw.assign(static_cast<size_t>(n), 1);
  g.total_weight = n;
  // The pool outlives the dissection's tasks; with one thread there is none.
  std::unique_ptr<nd::ForkJoinPool> pool;
  if (options.threads > 1) pool.reset(new nd::ForkJoinPool(options.threads));
  Dissection dissection(options, full, halo_ok, perm, pool.get());
  if (!dense.empty()) {
    Graph sparse_part;
    nd::Workspace ws;
    ws.grow(n);
    nd::induced_subgraph(g, kept, &ws, &sparse_part);
    g = std::move(sparse_part);
  }
  std::vector<SeparatorTree::Node> nodes;
  std::vector<int32_t> roots;
  GAB_RETURN_IF_ERROR(
      dissection.order(std::move(g), std::move(kept), nd::Hierarchy(), true, 0, options.seed, 0, &nodes, &roots));
  const int32_t dense_first = n - static_cast<int32_t>(dense.size());
  std::copy(dense.begin(), dense.end(), perm->begin() + dense_first);
  if (!dense.empty()) dissection.add_dense_root(dense_first, static_cast<int32_t>(dense.size()), roots, &nodes);
  if (tree) dissection.finish_tree(std::move(nodes), tree);
  return Status::Ok();
}

}  // namespace gab
