// The codec's greedy anchor selection (Sorkine et al. 2005, sec. IV; the
// one greedy loop, anchor_selection.cpp) seen through its error curve, and
// the rule that picks where the next anchors go (error_maxima.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "anchors/quantizer.h"
#include "common/gab_files.h"
#include "common/test_meshes.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/graph_distance.h"
#include "gab/mesh/metrics.h"
#include "pipeline/anchor_selection.h"
#include "pipeline/encoder_tuning.h"
#include "pipeline/error_maxima.h"
#include "pipeline/ordering_choice.h"
#include "reconstruction/shape_operator.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::encode_or_die;

// Anchors only, at a fixed grid: what the greedy loop alone decides.
EncodeOptions anchors_only(int32_t initial, int32_t max_anchors, double batch_fraction) {
  EncodeOptions o;
  o.initial_anchors = initial;
  o.max_anchors = max_anchors;
  o.batch_fraction = batch_fraction;
  o.bits = 14;
  o.detail = DetailMode::kOff;
  o.solver = Solver::kGlobal;  // each step's shape the exact least squares
  return o;
}

TEST(GreedySelection, OneAnchorPerStepLowersTheErrorAndATargetStopsEarly) {
  const Mesh mesh = bumpy_torus(24, 16);
  EncodeStats stats;
  encode_or_die(mesh, anchors_only(6, 60, 0.0), &stats);
  const std::vector<GreedyStep>& curve = stats.curve;
  ASSERT_EQ(curve.size(), 55u);  // 6, 7, ..., 60 anchors: one reconstruction each
  EXPECT_EQ(curve.front().anchors, 6);
  EXPECT_EQ(curve.back().anchors, 60);
  EXPECT_EQ(stats.anchors, 60);
  EXPECT_LT(curve.back().rms_rel, 0.5 * curve.front().rms_rel);
  EXPECT_LT(curve.back().linf_rel, curve.front().linf_rel);
  // The same loop with the RMS reached after 20 steps as its target.
  EncodeOptions target = anchors_only(6, 0, 0.0);
  target.target_rms_rel = curve[20].rms_rel;
  EncodeStats stopped;
  encode_or_die(mesh, target, &stopped);
  EXPECT_LE(stopped.curve.back().rms_rel, target.target_rms_rel);
  EXPECT_LE(stopped.anchors, 26);
}

TEST(GreedySelection, BatchesReachTheCountInFewerStepsAtComparableError) {
  const Mesh mesh = bumpy_torus(24, 16);
  EncodeStats single, batched;
  encode_or_die(mesh, anchors_only(10, 80, 0.0), &single);
  encode_or_die(mesh, anchors_only(10, 80, 0.1), &batched);
  EXPECT_EQ(batched.anchors, 80);  // the last batch is cut to the limit
  EXPECT_EQ(batched.curve.back().anchors, 80);
  EXPECT_LT(batched.curve.size(), single.curve.size() / 3);
  EXPECT_LT(batched.curve.back().rms_rel, 1.3 * single.curve.back().rms_rel);
}

TEST(GreedySelection, StopsWhenEveryVertexIsAnAnchor) {
  const Mesh mesh = bumpy_torus(8, 6);
  EncodeStats stats;
  encode_or_die(mesh, anchors_only(4, 1000, 0.5), &stats);
  EXPECT_EQ(stats.anchors, mesh.num_vertices());
}

TEST(GreedySelection, BatchesRankMaximaByTheirOneRingMassOneAtATimeByThePeak) {
  const Mesh m = bumpy_torus(24, 16);
  const EdgeGraph g = build_edge_graph(m);
  ShapeOperator rec(kGabReconstructionGlobal);
  ASSERT_TRUE(rec.init(g, 10.0, {0}, {m.positions[0], m.positions[1], m.positions[2]}).ok());
  // A one-vertex spike and, far from it, a lower but broad bump.
  const int32_t spike = 100, bump = 200;
  std::vector<double> error(m.num_vertices(), 0.0);
  error[spike] = 10.0;
  error[bump] = 8.0;
  for (int32_t p = g.offsets[bump]; p < g.offsets[bump + 1]; ++p) error[g.neighbors[p]] = 6.0;
  for (int32_t p = g.offsets[spike]; p < g.offsets[spike + 1]; ++p) ASSERT_EQ(error[g.neighbors[p]], 0.0);
  EXPECT_EQ(pick_error_maxima(g, error, rec, 1), std::vector<int32_t>({spike}));  // the paper's rule
  EXPECT_EQ(pick_error_maxima(g, error, rec, 2), std::vector<int32_t>({bump, spike}));
  // The bump's neighbours are not maxima; anchored vertices are never picked.
  const std::vector<int32_t> many = pick_error_maxima(g, error, rec, m.num_vertices());
  for (int32_t v : many) {
    EXPECT_NE(v, 0);
    EXPECT_TRUE(v == bump || error[v] != 6.0) << v;
  }
}

TEST(GreedySelection, SeparatedBatchesTakeTheRankedMaximaThatNoneBeforeIsNear) {
  const Mesh m = bumpy_torus(24, 16);
  const EdgeGraph g = build_edge_graph(m);
  ShapeOperator rec(kGabReconstructionGlobal);
  ASSERT_TRUE(rec.init(g, 10.0, {0}, {m.positions[0], m.positions[1], m.positions[2]}).ok());
  // Many local maxima, some of them a hop or two apart.
  std::vector<double> error(m.num_vertices());
  for (int32_t v = 0; v < m.num_vertices(); ++v) error[v] = 2.0 + std::sin(0.7 * v) * std::cos(1.3 * v);
  const int32_t separation = 3;
  const std::vector<int32_t> ranked = pick_error_maxima(g, error, rec, m.num_vertices());  // every maximum
  EXPECT_EQ(pick_error_maxima(g, error, rec, 30, 0), std::vector<int32_t>(ranked.begin(), ranked.begin() + 30));
  // The ranking walked in order: each maximum taken unless within
  // `separation` hops of one taken before it, up to the count; the torus
  // holds fewer than 30 such.
  const std::vector<int32_t> apart = pick_error_maxima(g, error, rec, 30, separation);
  EXPECT_LT(apart.size(), 30u);
  EXPECT_GT(apart.size(), 10u);
  EXPECT_EQ(pick_error_maxima(g, error, rec, 8, separation), std::vector<int32_t>(apart.begin(), apart.begin() + 8));
  std::vector<int32_t> expected;
  for (int32_t v : ranked) {
    bool near = false;
    for (int32_t u : expected) {
      std::vector<int32_t> hops;
      ASSERT_TRUE(bfs_distances(g, {u}, &hops).ok());
      near = near || hops[v] <= separation;
    }
    if (!near) expected.push_back(v);
  }
  EXPECT_EQ(apart, expected);
  // Without the separation some of the first 30 are that near each other.
  bool some_near = false;
  for (size_t i = 0; i < 30 && !some_near; ++i) {
    std::vector<int32_t> hops;
    ASSERT_TRUE(bfs_distances(g, {ranked[i]}, &hops).ok());
    for (size_t j = 0; j < i; ++j) some_near = some_near || hops[ranked[j]] <= separation;
  }
  EXPECT_TRUE(some_near);
}

// select_anchors with operator 3 on a mesh at a grid: the selection and the
// decoder's shape of a prefix of its order (a fresh operator, as a decoder).
struct IterativeSelection {
  Mesh mesh = bumpy_torus(60, 40);
  EdgeGraph graph = build_edge_graph(mesh);
  Quantizer quantizer;
  double scale = 1;
  IterativeTuning tuning = default_iterative_tuning(mesh.num_vertices());

  IterativeSelection() {
    double lo[3], hi[3];
    for (int c = 0; c < 3; ++c) lo[c] = hi[c] = mesh.positions[c];
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], mesh.positions[i]);
      hi[i % 3] = std::max(hi[i % 3], mesh.positions[i]);
    }
    quantizer = Quantizer::for_box(lo, hi, 12);
    scale = 1 / std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                          (hi[2] - lo[2]) * (hi[2] - lo[2]));
  }

  void select(const AnchorRules& rules, Selection* out, int32_t* anchors) {
    const GridPositions grid(mesh, quantizer);
    ShapeOperator rec(kGabReconstructionIterativeTuned);
    ASSERT_TRUE(tune(tuning, &rec).ok());
    ASSERT_TRUE(select_anchors(mesh, graph, rules, EncodeOptions(), grid, scale, OrderingPlan(Ordering::kAuto), &rec,
                               out).ok());
    *anchors = rec.num_anchors();
  }

  // The decoder's shape of order[0, k) and its relative RMS.
  double prefix_rms(const std::vector<int32_t>& order, int32_t k, std::vector<double>* shape) {
    const GridPositions grid(mesh, quantizer);
    ShapeOperator op(kGabReconstructionIterativeTuned);
    EXPECT_TRUE(tune(tuning, &op).ok());
    const std::vector<int32_t> prefix(order.begin(), order.begin() + k);
    EXPECT_TRUE(op.init(graph, EncodeOptions().weight, prefix, grid.coefficients_of(prefix)).ok());
    EXPECT_TRUE(op.shape(shape).ok());
    std::vector<double> error2;
    VertexDistance d;
    squared_vertex_errors(mesh, *shape, &error2, &d);
    return d.rms * scale;
  }
};

TEST(GreedySelection, TheIterativeLoopKeepsTheShortestPrefixOfItsOrderThatMeetsTheTarget) {
  IterativeSelection s;
  AnchorRules rules;
  rules.bits = 12;
  rules.target_rms_rel = 2e-3;
  Selection selection;
  int32_t anchors = 0;
  s.select(rules, &selection, &anchors);
  const std::vector<int32_t>& order = selection.schedule.order;
  const int32_t k = static_cast<int32_t>(order.size());
  EXPECT_EQ(anchors, k);
  EXPECT_EQ(selection.schedule.cuts.back(), k);
  // What the selection reports is the decoder's shape of its anchors, bit for bit.
  std::vector<double> shape;
  const double rms = s.prefix_rms(order, k, &shape);
  EXPECT_EQ(shape, selection.shape);
  EXPECT_EQ(rms, selection.rms_rel);
  EXPECT_LE(rms, rules.target_rms_rel);
  EXPECT_EQ(selection.curve.back().anchors, k);
  // A batch is 10% of the anchors here: the search took the last one's
  // overshoot back, to within its precision (k / kTrimPrecision).
  const int32_t shorter = k - std::max(2, 2 * k / kTrimPrecision);
  EXPECT_GT(s.prefix_rms(order, shorter, &shape), rules.target_rms_rel) << k;
}

}  // namespace
}  // namespace gab
