// The relaxed geometry-aware basis (relaxed_reconstruction.h) evaluated at a
// cost linear in n: the system (L^T L + w^2 S) x = w^2 S c, L = D - A the
// uniform Laplacian, S the anchors' indicator, c their coefficients, is
// approached by a given number of Jacobi-preconditioned conjugate-gradient
// steps, matrix-free (L applied twice per product), three independent
// recurrences (x, y, z) sharing each pass over the mesh, their vectors in
// single precision (the shape and the first residual in double). No factor,
// no ordering: memory is about 130 bytes per vertex beside the graph.
//
// The result is a fixed computation, not "the solution to a tolerance": the
// steps start from the previous shape (the first time, and after restart,
// from the start: each vertex at its nearest anchor's coefficients, ties
// broken by the NearestRule, then kStartSweeps harmonic sweeps or as many
// as set_start_sweeps says), and every floating-point operation happens in
// one order. Sums over vertices add runs of 64 vertices, then fixed blocks
// of kBlock vertices in vertex order, then the blocks in block order,
// whatever the thread count; so two programs making the same calls get the
// same bits on any machine with IEEE arithmetic and no contraction, which
// is what lets an encoder and a decoder share the shape (docs/format.md
// 5.2.1 to 5.2.3 spell out every operation).
//
// As the steps grow the shape tends to the global least squares, to about
// 1e-7 of the correction the steps add (single precision); how many a use
// needs depends on the anchors' spacing (about 2 n / k steps reach it to
// 1e-3 of the error, bench/reconstruction_candidates).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/status.h"

namespace gab {

class IterativeReconstruction {
 public:
  // Vertices per block of every sum over vertices.
  static constexpr int32_t kBlock = 4096;
  // Harmonic sweeps that smooth the nearest-anchor start.
  static constexpr int kStartSweeps = 8;

  // Which anchor a vertex starts at when several are equally near (either
  // way the order anchors were given in does not matter), and how the start
  // is swept: the two iterative operators of the format.
  enum class NearestRule {
    // Operator 1: breadth-first from the anchors in increasing vertex order,
    // a vertex taking the anchor of the first frontier vertex that reaches
    // it; sweeps in double, each mean a division by the degree.
    kDiscovery,
    // Operator 2: the fewest hops, then the lowest anchor vertex index, kept
    // up to date as anchors join (only the vertices they are nearer to
    // change), which makes start_at cost the neighbourhood it reads, not n;
    // sweeps in single precision in the anchors' frame (start_frame), each
    // mean a product by the degree's reciprocal.
    kFewestHopsLowest,
  };
  // Before init (default kDiscovery).
  void set_nearest_rule(NearestRule rule) { rule_ = rule; }
  // kFewestHopsLowest: the harmonic sweeps of start_at and start
  // (`prediction`) and of solve's fresh start (`final`), each in
  // 0..kMostStartSweeps (default kStartSweeps both). Before init.
  static constexpr int32_t kMostStartSweeps = 16;
  Status set_start_sweeps(int32_t prediction, int32_t final);

  // Starts over on `graph` (kept by reference: it must outlive this) with
  // weight w and the initial anchors (distinct vertices; every connected
  // component needs one) and their coefficients (3 per anchor). No shape
  // yet. O(n + anchors).
  Status init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
              const std::vector<double>& coefficients);

  // Adds anchors (distinct, not anchored yet) with their coefficients; the
  // shape so far stays the next solve's start. O(anchors), and with
  // kFewestHopsLowest the search for the vertices they are nearest to.
  Status add_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);

  // init and add_anchors with the nearest anchors after them given instead
  // of searched (kFewestHopsLowest only): `nearest` as a
  // FarthestPointSampler's nearest() gives it when the vertices it has
  // chosen are exactly the anchors (graph_distance.h). Each entry is
  // checked to name an anchor; on a failed check add_anchors leaves
  // everything as it was. O(n).
  Status init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
              const std::vector<double>& coefficients, const std::vector<uint64_t>& nearest);
  Status add_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                     const std::vector<uint64_t>& nearest);

  // Replaces the coefficients of anchors first.. (in anchors() order). O(k).
  Status set_coefficients(int32_t first, const std::vector<double>& coefficients);

  // `steps` conjugate-gradient steps (>= 0) from the shape so far (or, the
  // first time and after restart, from the nearest-anchor start);
  // *positions receives the shape (x0 y0 z0 x1 ...). O(steps (n + edges)).
  Status solve(int32_t steps, std::vector<double>* positions);
  // Threads for solve (default 1); the shape is the same bits for any count.
  void set_threads(int32_t threads) { threads_ = std::max(1, threads); }
  // The next solve starts from `positions` (3 per vertex, finite) instead
  // of the shape so far. O(n).
  Status set_start(const std::vector<double>& positions);
  // Each vertex at its nearest anchor's coefficients (3 per vertex): the
  // start before its harmonic sweeps. Changes nothing. O(n + edges).
  std::vector<double> nearest_anchor_shape() const;
  // The start (what solve(0) gives after restart) at the vertices `at`
  // only, the same values: positions[3 v ..] for v in at (positions sized 3 n;
  // its other entries untouched). Reads the ring of the prediction sweeps'
  // hops around `at`, so its cost is that ring's size, not n.
  // kFewestHopsLowest only.
  Status start_at(const std::vector<int32_t>& at, std::vector<double>* positions);
  // start_at at every vertex (every entry of positions set). O(n + edges).
  Status start(std::vector<double>* positions);
  // Forgets the shape: the next solve starts from the nearest-anchor start,
  // so its result depends on the anchors and coefficients alone. O(1).
  void restart() { shape_.clear(); }

  double weight() const { return weight_; }
  int32_t num_vertices() const { return n_; }
  int32_t num_anchors() const { return static_cast<int32_t>(anchors_.size()); }
  const std::vector<int32_t>& anchors() const { return anchors_; }
  const std::vector<double>& coefficients() const { return coefficients_; }
  bool is_anchor(int32_t v) const { return anchor_of_[v] >= 0; }
  // Whether solve has made a shape yet.
  bool has_shape() const { return !shape_.empty(); }

 private:
  Status check_new(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);
  // init with the nearest map given (nearest) or searched (null).
  Status init_with(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
                   const std::vector<double>& coefficients, const std::vector<uint64_t>* nearest);
  // The nearest map `nearest` checked and kept.
  Status take_nearest(const std::vector<uint64_t>& nearest);
  void record(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);
  // kFewestHopsLowest: lowers nearest_ breadth-first from `anchors`
  // (just recorded) where they are nearer, by the rule's order.
  void update_nearest(const std::vector<int32_t>& anchors);
  // start_at at `at_or_all`, or at every vertex when it is null, with
  // `sweeps` harmonic sweeps.
  Status start_values(const std::vector<int32_t>* at_or_all, int32_t sweeps, std::vector<double>* positions);
  // Operator 2's frame for the start in single precision: per axis the
  // anchors' lowest coefficient and 2^-E, their extent = m 2^E, m in [0.5, 1).
  void start_frame(double origin[3], double scale[3]) const;

  const EdgeGraph* graph_ = nullptr;
  int32_t n_ = 0;
  double weight_ = 0.0;
  int32_t threads_ = 1;
  std::vector<int32_t> anchors_;
  std::vector<double> coefficients_;  // 3 per anchor
  std::vector<int32_t> anchor_of_;    // vertex -> index in anchors_, or -1
  std::vector<double> shape_;         // 3 per vertex once solved
  NearestRule rule_ = NearestRule::kDiscovery;
  int32_t prediction_sweeps_ = kStartSweeps, final_sweeps_ = kStartSweeps;
  // kFewestHopsLowest: per vertex (hops to its nearest anchor << 32) | that
  // anchor's vertex index, so one comparison orders by the rule.
  std::vector<uint64_t> nearest_;
  int32_t nearest_anchor(int32_t v) const { return static_cast<int32_t>(nearest_[v] & 0xffffffffu); }
  // start_at's scratch, kept between calls: per vertex the call that last
  // reached it; the values before and after a sweep (4 per vertex, the
  // fourth 0).
  std::vector<uint32_t> reached_;
  std::vector<int8_t> depth_;  // hops from `at`, where reached
  std::vector<float> from_, to_;
  uint32_t call_ = 0;
};

}  // namespace gab
