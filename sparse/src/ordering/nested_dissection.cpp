// Nested-dissection ordering (George, "Nested dissection of a regular finite
// element mesh", SIAM J. Numer. Anal. 10(2), 1973): a vertex separator S
// splits the graph into A and B with no edge between them; ordering A, then
// B, then S confines the fill of A's and B's columns to themselves and S, and
// the same is done to A and B recursively. Separators come from the
// multilevel scheme (nested_dissection_bisect.cpp); pieces below leaf_size
// are ordered by AMD, as METIS's ND hands its small pieces to minimum degree
// (Karypis & Kumar 1998, sec. 6); rows denser than AMD's threshold are taken
// out first and ordered last (they would sit in every separator anyway).
//
// The recursion records the separator tree: a node per separator (and per
// AMD leaf), its columns, its subtree's columns and its parent.
#include "gab/sparse/nested_dissection.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "gab/sparse/amd_graph.h"
#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace {

using nd::Graph;

class Dissection {
 public:
  Dissection(const NestedDissectionOptions& options, int32_t n, std::vector<int32_t>* perm)
      : options_(options), rng_(options.seed), perm_(*perm) {
    ws_.grow(n);
  }

  // Orders g, whose vertex v is original vertex label[v], into
  // perm[begin .. begin + g.n); the tree nodes of its pieces' roots are
  // appended to *roots. h holds coarsenings of g inherited from its parent
  // (none for the whole graph). With find_components, g's connected
  // components are ordered one by one. The sides of a separator are not
  // searched for components: the search cost a tenth of the ordering's time
  // and found none on the shared meshes, and find_separator copes with a
  // disconnected graph (its separator may then be empty). Consumes g, label and h.
  Status order(Graph&& g, std::vector<int32_t>&& label, nd::Hierarchy&& h, bool find_components, int32_t begin,
               std::vector<int32_t>* roots) {
    if (g.n == 0) return Status::Ok();
    if (find_components) {
      std::vector<int32_t> component;
      const int32_t count = nd::connected_components(g, &ws_, &component);
      if (count > 1) return order_components(g, label, h, component, count, begin, roots);
    }
    if (is_leaf(g.n)) return order_leaf(g, label, begin, roots);

    std::vector<uint8_t> where;
    nd::find_separator(g, options_, &rng_, &ws_, &h, &where);
    std::vector<int32_t> side[3];
    for (int32_t v = 0; v < g.n; ++v) side[where[v]].push_back(v);
    // No proper separator (a clique, say), or one so lopsided that recursing
    // on it would go deep for little gain: the piece is ordered whole.
    const size_t larger = std::max(side[nd::kLeft].size(), side[nd::kRight].size());
    if (side[nd::kLeft].empty() || side[nd::kRight].empty() || larger > 0.9 * g.n) {
      return order_leaf(g, label, begin, roots);
    }

    Graph part[2];
    std::vector<int32_t> part_label[2];
    nd::Hierarchy part_hierarchy[2];
    for (int s = 0; s < 2; ++s) {
      nd::induced_subgraph(g, side[s], &ws_, &part[s]);
      // A part that will be a leaf needs no coarsening.
      if (!is_leaf(part[s].n)) {
        nd::restrict_hierarchy(g, h, side[s], options_.coarsest_size, &ws_, &part_hierarchy[s]);
      }
      part_label[s].reserve(side[s].size());
      for (int32_t v : side[s]) part_label[s].push_back(label[v]);
    }
    const int32_t separator_first = begin + part[0].n + part[1].n;
    for (size_t k = 0; k < side[nd::kSeparator].size(); ++k) {
      perm_[separator_first + k] = label[side[nd::kSeparator][k]];
    }
    const int32_t separator_size = static_cast<int32_t>(side[nd::kSeparator].size());
    g = Graph();  // the parts are all the recursion needs
    label = std::vector<int32_t>();
    h = nd::Hierarchy();
    std::vector<int32_t> children;
    const int32_t left_size = part[0].n;
    GAB_RETURN_IF_ERROR(
        order(std::move(part[0]), std::move(part_label[0]), std::move(part_hierarchy[0]), false, begin, &children));
    GAB_RETURN_IF_ERROR(order(std::move(part[1]), std::move(part_label[1]), std::move(part_hierarchy[1]), false,
                              begin + left_size, &children));
    roots->push_back(add_node(separator_first, separator_size, begin, /*leaf=*/false, children));
    return Status::Ok();
  }

  // The dense rows, ordered last, as one root separating everything else.
  void add_dense_root(int32_t first, int32_t size, const std::vector<int32_t>& children) {
    add_node(first, size, 0, /*leaf=*/false, children);
  }

  void finish_tree(SeparatorTree* tree) {
    tree->nodes = std::move(nodes_);
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
                          const std::vector<int32_t>& component, int32_t count, int32_t begin,
                          std::vector<int32_t>* roots) {
    std::vector<std::vector<int32_t>> members(static_cast<size_t>(count));
    for (int32_t v = 0; v < g.n; ++v) members[component[v]].push_back(v);
    for (int32_t c = 0; c < count; ++c) {
      Graph sub;
      nd::induced_subgraph(g, members[c], &ws_, &sub);
      nd::Hierarchy sub_hierarchy;
      if (!is_leaf(sub.n)) nd::restrict_hierarchy(g, h, members[c], options_.coarsest_size, &ws_, &sub_hierarchy);
      std::vector<int32_t> sub_label;
      sub_label.reserve(members[c].size());
      for (int32_t v : members[c]) sub_label.push_back(label[v]);
      GAB_RETURN_IF_ERROR(order(std::move(sub), std::move(sub_label), std::move(sub_hierarchy), false, begin, roots));
      begin += static_cast<int32_t>(members[c].size());
    }
    return Status::Ok();
  }

  // A small piece ordered by AMD on its own lists (amd_graph.h), which are
  // sorted when the original graph's are: the induced subgraphs keep the
  // order. Otherwise on a sorted copy.
  Status order_leaf(const Graph& g, const std::vector<int32_t>& label, int32_t begin,
                    std::vector<int32_t>* roots) {
    bool sorted = true;
    for (int32_t v = 0; v < g.n && sorted; ++v) {
      for (int32_t p = g.xadj[v] + 1; p < g.xadj[v + 1]; ++p) sorted &= g.adj[p - 1] < g.adj[p];
    }
    std::vector<int32_t> local;
    if (sorted) {
      GAB_RETURN_IF_ERROR(amd_order_graph(g.n, g.xadj.data(), g.adj.data(), &local));
    } else {
      std::vector<int32_t> adj(g.adj.begin(), g.adj.end());
      for (int32_t v = 0; v < g.n; ++v) std::sort(adj.begin() + g.xadj[v], adj.begin() + g.xadj[v + 1]);
      GAB_RETURN_IF_ERROR(amd_order_graph(g.n, g.xadj.data(), adj.data(), &local));
    }
    for (int32_t k = 0; k < g.n; ++k) perm_[begin + k] = label[local[k]];
    roots->push_back(add_node(begin, g.n, begin, /*leaf=*/true, {}));
    return Status::Ok();
  }

  int32_t add_node(int32_t first, int32_t size, int32_t subtree_first, bool leaf,
                   const std::vector<int32_t>& children) {
    const int32_t id = static_cast<int32_t>(nodes_.size());
    SeparatorTree::Node node;
    node.first = first;
    node.size = size;
    node.subtree_first = subtree_first;
    node.leaf = leaf;
    nodes_.push_back(node);
    for (int32_t c : children) nodes_[c].parent = id;
    return id;
  }

  const NestedDissectionOptions& options_;
  nd::Rng rng_;
  nd::Workspace ws_;
  std::vector<int32_t>& perm_;
  std::vector<SeparatorTree::Node> nodes_;
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
  const int32_t n = lower.ncols;
  const CscMatrix full = symmetric_graph(lower);
  perm->assign(static_cast<size_t>(n), -1);

  // Dense rows (AMD's rule): out of the graph, ordered last.
  const int32_t dense_limit =
      options.dense < 0 ? n : std::max(16, static_cast<int32_t>(options.dense * std::sqrt(double(n))));
  std::vector<int32_t> kept, dense;
  for (int32_t v = 0; v < n; ++v) {
    (full.colptr[v + 1] - full.colptr[v] > dense_limit ? dense : kept).push_back(v);
  }

  Graph g;
  g.n = n;
  g.xadj.assign(full.colptr.begin(), full.colptr.end());
  g.adj.assign(full.rowind.begin(), full.rowind.end());
  // adjw stays empty: every edge of the matrix graph weighs 1.
  g.vw.assign(static_cast<size_t>(n), 1);
  g.total_weight = n;
  Dissection dissection(options, n, perm);
  if (!dense.empty()) {
    Graph sparse_part;
    nd::Workspace ws;
    ws.grow(n);
    nd::induced_subgraph(g, kept, &ws, &sparse_part);
    g = std::move(sparse_part);
  }
  std::vector<int32_t> roots;
  GAB_RETURN_IF_ERROR(dissection.order(std::move(g), std::move(kept), nd::Hierarchy(), true, 0, &roots));
  const int32_t dense_first = n - static_cast<int32_t>(dense.size());
  std::copy(dense.begin(), dense.end(), perm->begin() + dense_first);
  if (!dense.empty()) dissection.add_dense_root(dense_first, static_cast<int32_t>(dense.size()), roots);
  if (tree) dissection.finish_tree(tree);
  return Status::Ok();
}

}  // namespace gab
