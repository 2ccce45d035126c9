// The pieces of the nested-dissection ordering (nested_dissection.h) and the
// weighted graph they pass around. Private to the engine.
//
//   nested_dissection.cpp          the recursion: components, dense rows, leaves (halo AMD), tree
//   fork_join.h                    the pool whose workers take large pieces' sides as tasks
//   nested_dissection_bisect.cpp   one vertex separator, multilevel: coarsen, separate, refine
//   nested_dissection_coarsen.cpp  heavy-edge matching and contraction
//   nested_dissection_restrict.cpp a part's coarsenings read off its parent's
//   nested_dissection_initial.cpp  separator of the coarsest graph by greedy growing
//   nested_dissection_refine.cpp   FM refinement of a vertex separator
//   nested_dissection_graph.cpp    induced subgraphs, connected components
//
// Where the time goes (callgrind, igea's benchmark matrix, n = 134,345, 1.81G
// instructions in nested_dissection_order): FM refinement 35% (about 4,000
// calls, 1.4M moves, most of them speculative moves undone at a pass's end),
// restrict_hierarchy 16%, induced_subgraph 13%, AMD on the leaves 14%,
// coarsening 9%. Every depth of the recursion walks every edge a few times.
// Measured and not kept (mean nnz(L) and flops over 4 seeds on igea, horse,
// nefertiti, bunny, feline; instructions on igea):
// - refine_passes 3: -5% instructions, horse +5% flops; refine_patience 40:
//   -2.5%, nefertiti +6%; stopping passes that gain under 1% of the
//   separator: a few percent, horse +6%.
// - leaf_size 900: -6% instructions; 1200: -8% time, flops up to +7%; 300:
//   +37% time, flops -1..4%. candidates 2, candidate_tries 2,
//   large_candidates 4: -4%, -1%, -1%.
// - Dissecting the mesh's 1-ring (the matrix's negative entries, checked to
//   reach every matrix edge within two steps) with separators widened by the
//   lighter neighbouring layer and bridges across each part's removed
//   vertices: -7% instructions only (the per-depth passes stay; bridging and
//   widening cost what the thinner graph saves), flops +2% (igea) to +32%
//   (nefertiti): FM minimises the thin separator, not the widened one.
// - Raw pointers and hoisted row ends in induced_subgraph and
//   restrict_hierarchy: no fewer instructions (the compiler already did it).
#pragma once

#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include "gab/sparse/large_buffer.h"
#include "gab/sparse/nested_dissection.h"
#include "gab/sparse/splitmix64.h"

namespace gab {
namespace nd {

// std::vector whose resize() leaves new ints unset: the graphs' arrays are
// written in full right after they are sized, and zero-filling them first
// (and the subgraphs and coarse levels of every recursion step) was a few
// percent of the ordering.
template <typename T>
struct UninitializedAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  // Arrays of a huge page or more (the large graphs' and their coarsenings')
  // are aligned to one and advised for huge pages (large_buffer.h), as the
  // CLI's malloc does for everything (malloc_tuning.h) but a library caller's
  // may not: each 4 KiB fault costs tens of microseconds on the virtual
  // machines we measure on, and the dissection faults in its arrays afresh
  // at every level (the 603k-vertex mesh on two threads: see docs/tuning-engine.md).
  T* allocate(size_t count) {
    const size_t bytes = count * sizeof(T);
    if (bytes < kLargeAlignment) return std::allocator<T>::allocate(count);
    void* p = ::operator new(bytes, std::align_val_t(kLargeAlignment));
    advise_huge_pages(p, bytes);
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t count) {
    if (count * sizeof(T) < kLargeAlignment) {
      std::allocator<T>::deallocate(p, count);
    } else {
      ::operator delete(p, std::align_val_t(kLargeAlignment));
    }
  }
};
using IntArray = std::vector<int32_t, UninitializedAllocator<int32_t>>;

// An undirected graph without self loops, adjacency lists in CSR form, with
// vertex weights (how many original vertices a coarse vertex stands for) and
// edge weights (how many original edges a coarse edge stands for).
struct Graph {
  int32_t n = 0;
  IntArray xadj;    // n + 1
  IntArray adj;     // xadj[n] neighbours
  IntArray adjw;    // weight of each adj entry; empty: every weight is 1
  IntArray vw;      // n vertex weights
  int64_t total_weight = 0;     // sum of vw
};

// Where a vertex lies with respect to a separator.
enum Side : uint8_t { kLeft = 0, kRight = 1, kSeparator = 2 };

// The matching order's generator: the same sequence on every platform.
using Rng = SplitMix64;

// The heaviest a side may be: (1 + imbalance) / 2 of the graph's weight.
int64_t max_side_weight(const Graph& g, double imbalance);

// The FM refinement's state (nested_dissection_refine.cpp), kept between
// calls: pos[] is -1 and locked[] 0 for every vertex outside a call.
struct RefineWorkspace {
  std::vector<int32_t> ext;         // 2 per vertex: neighbour weight on side 0, side 1
  std::vector<uint8_t> locked;      // moved in this pass
  std::vector<int32_t> pos[2];      // place in the gain heap of the move to side 0 / 1
  std::vector<int32_t> key[2];      // gain of that move
  std::vector<int32_t> stored[2];   // the key the heap is ordered by (>= key: decreases are lazy)
  std::vector<int32_t> heap[2];     // the heaps themselves
  std::vector<int32_t> separator;   // the separator's vertices, each once
  std::vector<int32_t> moved;       // this pass's moves in order
  std::vector<int32_t> pulled;      // vertices each move pulled into the separator
  std::vector<int32_t> pulled_end;  // end of each move's run in pulled
};

// The coarsenings of a graph g (nested_dissection_bisect.cpp): levels[0 ..
// depth) in use, those past depth kept for their buffers.
struct Hierarchy {
  std::vector<Graph> levels;
  std::vector<IntArray> maps;  // maps[k]: level k-1 (the graph for k = 0) -> level k
  size_t depth = 0;
};

class ForkJoinPool;  // fork_join.h

// Buffers reused by every call so the recursion does not allocate per
// vertex; sized for the largest graph (grow() keeps the invariants below).
// One per pool worker, which it names.
struct Workspace {
  ForkJoinPool* pool = nullptr;  // null: everything on the calling thread
  int32_t worker = 0;            // the pool worker using this workspace
  std::vector<int32_t> local;   // vertex -> its index in a subgraph being built; -1 elsewhere
  std::vector<int32_t> slot;    // coarse vertex -> its entry in the row being built; -1 elsewhere
  std::vector<int32_t> queue;   // breadth-first searches
  std::vector<int32_t> mark;    // scratch labels (no invariant)
  RefineWorkspace refine;
  std::vector<int32_t> restrict_source[2];  // restrict_hierarchy's vertex lists (no invariant)
  void grow(int32_t n);
};

// Induced subgraph on `vertices` (increasing), numbered in that order; the
// adjacency lists stay sorted when g's are. O(sum of their degrees).
void induced_subgraph(const Graph& g, const std::vector<int32_t>& vertices, Workspace* ws, Graph* sub);

// Connected components: component[v] in 0..count-1, numbered in order of
// their smallest vertex; returns count. O(n + edges).
int32_t connected_components(const Graph& g, Workspace* ws, std::vector<int32_t>* component);

// One level of coarsening: a heavy-edge matching visited in a seeded random
// order, each matched pair (or lone vertex) contracted into one coarse vertex.
// No coarse vertex weighs more than max_vertex_weight. fine_to_coarse[v] is
// v's coarse vertex. O(n + edges). With ws's pool and at least
// thread_entries adjacency entries, half the contraction is a pool task
// (the same result).
void coarsen(const Graph& fine, int64_t max_vertex_weight, size_t thread_entries, Rng* rng, Workspace* ws,
             IntArray* fine_to_coarse, Graph* coarse);

// Vertex separators of a small graph: regions grown breadth-first from
// `tries` seeds to half the weight, their boundary taken as separator,
// refined; the `count` best distinct ones are kept (fewer when the tries gave
// fewer distinct), best first: least weight beyond the side bound, then least
// separator weight, then earliest try. Each holds a Side per vertex.
void initial_separators(const Graph& g, const NestedDissectionOptions& params, int32_t tries, int32_t count,
                        Rng* rng, Workspace* ws, std::vector<std::vector<uint8_t>>* separators);

// Improves the vertex separator `where` of g in place by FM passes: moves
// separator vertices to a side (pulling their neighbours on the other side
// into the separator) while it shrinks, keeping both sides under
// max_side_weight, undoing each pass's moves past its best point.
void refine_separator(const Graph& g, const NestedDissectionOptions& params, Workspace* ws,
                      std::vector<uint8_t>* where);

// A small, balanced vertex separator of a connected graph, multilevel:
// coarsen, initial_separator on the coarsest graph, then project back level
// by level, refining at each. *h holds g's coarsenings: those it comes with
// (restrict_hierarchy) are kept and coarsened further down to
// coarsest_size; the caller may restrict them to the parts.
void find_separator(const Graph& g, const NestedDissectionOptions& params, Rng* rng, Workspace* ws, Hierarchy* h,
                    std::vector<uint8_t>* where);

// The coarsenings of the part g[vertices] (vertices increasing) read off g's
// coarsenings h, down to the first level with at most `target` vertices or
// h's coarsest: each level's vertices are the coarse vertices holding part
// vertices, weighing what they hold, with h's edges among them (a superset
// of the part's coarse edges, so coarse separators stay separators).
// O(n + edges) of h's levels.
void restrict_hierarchy(const Graph& g, const Hierarchy& h, const std::vector<int32_t>& vertices, int32_t target,
                        Workspace* ws, Hierarchy* part);

}  // namespace nd
}  // namespace gab
