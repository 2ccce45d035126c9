// The codec's greedy anchor selection (Sorkine et al. 2005, sec. IV; the
// one greedy loop, anchor_selection.cpp) seen through its error curve, and
// the rule that picks where the next anchors go (error_maxima.h).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "common/gab_files.h"
#include "common/test_meshes.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/edge_graph.h"
#include "pipeline/error_maxima.h"
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

}  // namespace
}  // namespace gab
