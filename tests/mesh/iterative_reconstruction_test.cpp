// The relaxed basis by a fixed number of conjugate-gradient steps
// (iterative_reconstruction.h), against the factored global solve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/test_meshes.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/graph_distance.h"
#include "gab/mesh/iterative_reconstruction.h"
#include "gab/mesh/relaxed_reconstruction.h"

namespace gab {
namespace {

std::vector<double> coefficients(const Mesh& m, const std::vector<int32_t>& anchors) {
  std::vector<double> c;
  for (int32_t a : anchors) {
    for (int k = 0; k < 3; ++k) c.push_back(m.positions[3 * static_cast<size_t>(a) + k]);
  }
  return c;
}

// Every `stride`-th vertex from `first`.
std::vector<int32_t> every(int32_t n, int32_t stride, int32_t first = 0) {
  std::vector<int32_t> anchors;
  for (int32_t v = first; v < n; v += stride) anchors.push_back(v);
  return anchors;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

std::vector<double> global_shape(const EdgeGraph& g, double w, const std::vector<int32_t>& anchors,
                                 const std::vector<double>& c) {
  RelaxedReconstruction rec;
  EXPECT_TRUE(rec.init(g, w, anchors, c).ok());
  std::vector<double> x;
  EXPECT_TRUE(rec.reconstruct(&x).ok());
  return x;
}

TEST(IterativeReconstructionTest, StepsApproachTheGlobalLeastSquares) {
  const Mesh m = testing_util::bumpy_torus(24, 16);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> anchors = every(m.num_vertices(), 7);
  const std::vector<double> c = coefficients(m, anchors);
  const std::vector<double> global = global_shape(g, 100, anchors, c);
  double previous = INFINITY;
  for (int32_t steps : {0, 4, 12, 160}) {
    IterativeReconstruction rec;
    ASSERT_TRUE(rec.init(g, 100, anchors, c).ok());
    std::vector<double> x;
    ASSERT_TRUE(rec.solve(steps, &x).ok());
    const double distance = max_difference(x, global);
    EXPECT_LT(distance, previous) << steps;
    previous = distance;
  }
  // The steps' vectors are single precision: the shape settles within
  // about 1e-7 of the correction they add (here ~1 unit).
  EXPECT_LT(previous, 1e-6);
}

// Hops from `source` to every vertex (one breadth-first search).
std::vector<int32_t> hops_from(const EdgeGraph& g, int32_t source) {
  std::vector<int32_t> hops(g.num_vertices(), -1), queue = {source};
  hops[source] = 0;
  for (size_t i = 0; i < queue.size(); ++i) {
    for (int32_t p = g.offsets[queue[i]]; p < g.offsets[queue[i] + 1]; ++p) {
      const int32_t w = g.neighbors[p];
      if (hops[w] < 0) {
        hops[w] = hops[queue[i]] + 1;
        queue.push_back(w);
      }
    }
  }
  return hops;
}

TEST(IterativeReconstructionTest, TheStartPutsEachVertexAtItsNearestAnchor) {
  const Mesh m = testing_util::grid(9, 4);
  const EdgeGraph g = build_edge_graph(m);
  // Anchors given as 35 then 0: a vertex as near to both takes 0's (the
  // search starts from the anchors in vertex order, not in the given one).
  const std::vector<int32_t> anchors = {35, 0};
  const std::vector<double> c = {5, 6, 7, 1, 2, 3};
  IterativeReconstruction rec;
  ASSERT_TRUE(rec.init(g, 100, anchors, c).ok());
  const std::vector<double> x = rec.nearest_anchor_shape();
  const std::vector<int32_t> to_35 = hops_from(g, 35), to_0 = hops_from(g, 0);
  int ties = 0;
  for (int32_t v = 0; v < m.num_vertices(); ++v) {
    const bool first = to_35[v] < to_0[v];
    ties += to_35[v] == to_0[v];
    for (int k = 0; k < 3; ++k) EXPECT_EQ(x[3 * v + k], first ? c[k] : c[3 + k]) << v;
  }
  EXPECT_GT(ties, 0);
}

TEST(IterativeReconstructionTest, TheFewestHopsRuleTakesTheNearestThenTheLowestAnchor) {
  // kFewestHopsLowest: the anchor fewest hops away, the lowest vertex index
  // among equals; the same whether the anchors come at once or in batches
  // (the map is updated where each batch is nearer), in any order.
  const Mesh m = testing_util::bumpy_torus(16, 10);
  const EdgeGraph g = build_edge_graph(m);
  const int32_t n = m.num_vertices();
  const std::vector<int32_t> anchors = {97, 3, 150, 41, 120, 8, 64, 159, 30};
  std::vector<std::vector<int32_t>> hops;
  for (int32_t a : anchors) hops.push_back(hops_from(g, a));
  std::vector<double> c(3 * anchors.size());
  for (size_t i = 0; i < c.size(); ++i) c[i] = static_cast<double>(i);
  auto expected = [&](size_t count) {  // the rule over the first `count` anchors, by brute force
    std::vector<double> x(3 * static_cast<size_t>(n));
    int ties = 0;
    for (int32_t v = 0; v < n; ++v) {
      size_t best = 0;
      for (size_t i = 1; i < count; ++i) {
        const bool nearer = hops[i][v] < hops[best][v];
        ties += hops[i][v] == hops[best][v];
        if (nearer || (hops[i][v] == hops[best][v] && anchors[i] < anchors[best])) best = i;
      }
      for (int k = 0; k < 3; ++k) x[3 * v + k] = c[3 * best + k];
    }
    EXPECT_GT(ties, 0) << count;
    return x;
  };
  IterativeReconstruction whole;
  whole.set_nearest_rule(IterativeReconstruction::NearestRule::kFewestHopsLowest);
  ASSERT_TRUE(whole.init(g, 100, anchors, c).ok());
  EXPECT_EQ(whole.nearest_anchor_shape(), expected(anchors.size()));
  IterativeReconstruction batches;
  batches.set_nearest_rule(IterativeReconstruction::NearestRule::kFewestHopsLowest);
  ASSERT_TRUE(batches.init(g, 100, {anchors.begin(), anchors.begin() + 2}, {c.begin(), c.begin() + 6}).ok());
  EXPECT_EQ(batches.nearest_anchor_shape(), expected(2));
  for (size_t first = 2; first < anchors.size(); first += 3) {
    const size_t last = std::min(anchors.size(), first + 3);
    ASSERT_TRUE(batches
                    .add_anchors({anchors.begin() + first, anchors.begin() + last},
                                 {c.begin() + 3 * first, c.begin() + 3 * last})
                    .ok());
    EXPECT_EQ(batches.nearest_anchor_shape(), expected(last)) << last;
  }
}

TEST(IterativeReconstructionTest, AGivenNearestMapGivesTheSearchedOnesShapes) {
  // init and add_anchors with a farthest-point sampler's nearest map (its
  // chosen vertices the anchors): the same starts and shapes as the
  // reconstruction's own search. A map that names a vertex that is no
  // anchor is refused and leaves everything as it was.
  const Mesh m = testing_util::bumpy_torus(16, 10);
  const EdgeGraph g = build_edge_graph(m);
  FarthestPointSampler sampler;
  ASSERT_TRUE(sampler.start(g, {97, 3}, nullptr).ok());
  std::vector<int32_t> chosen;
  sampler.next(2, &chosen);
  std::vector<double> c(3 * 40);
  for (size_t i = 0; i < c.size(); ++i) c[i] = std::sin(static_cast<double>(i));
  auto coefficients_of = [&](size_t first, size_t last) {
    return std::vector<double>(c.begin() + 3 * first, c.begin() + 3 * last);
  };
  IterativeReconstruction given, searched;
  for (IterativeReconstruction* rec : {&given, &searched}) {
    rec->set_nearest_rule(IterativeReconstruction::NearestRule::kFewestHopsLowest);
  }
  ASSERT_TRUE(given.init(g, 100, chosen, coefficients_of(0, 2), sampler.nearest()).ok());
  ASSERT_TRUE(searched.init(g, 100, chosen, coefficients_of(0, 2)).ok());
  std::vector<double> a(3 * static_cast<size_t>(m.num_vertices())), b = a;
  for (size_t done = 2; done < 40; done += 9) {
    const size_t last = std::min<size_t>(40, done + 9);
    sampler.next(static_cast<int32_t>(last - done), &chosen);
    const std::vector<int32_t> batch(chosen.begin() + static_cast<std::ptrdiff_t>(done), chosen.end());
    // A map the batch does not match: refused, nothing changed.
    std::vector<uint64_t> wrong = sampler.nearest();
    wrong[5] = (wrong[5] & ~uint64_t{0xffffffffu}) | 6;  // vertex 6 is no anchor
    ASSERT_FALSE(given.is_anchor(6));
    EXPECT_EQ(given.add_anchors(batch, coefficients_of(done, last), wrong).message(),
              "the nearest map names a vertex that is not an anchor");
    EXPECT_EQ(given.num_anchors(), static_cast<int32_t>(done));
    ASSERT_TRUE(given.add_anchors(batch, coefficients_of(done, last), sampler.nearest()).ok());
    ASSERT_TRUE(searched.add_anchors(batch, coefficients_of(done, last)).ok());
    EXPECT_EQ(given.nearest_anchor_shape(), searched.nearest_anchor_shape()) << last;
    ASSERT_TRUE(given.start(&a).ok());
    ASSERT_TRUE(searched.start(&b).ok());
    EXPECT_EQ(a, b) << last;
  }
  ASSERT_TRUE(given.solve(5, &a).ok());
  ASSERT_TRUE(searched.solve(5, &b).ok());
  EXPECT_EQ(a, b);
  EXPECT_EQ(given.add_anchors({6}, {0, 0, 0}, std::vector<uint64_t>(3, 0)).message(),
            "a nearest map needs one entry per vertex");
  IterativeReconstruction discovery;  // operator 1 keeps no map
  EXPECT_EQ(discovery.init(g, 100, {97, 3}, coefficients_of(0, 2), sampler.nearest()).message(),
            "a nearest map needs the fewest-hops nearest rule");
}

TEST(IterativeReconstructionTest, StartAtIsTheStartAtThoseVertices) {
  // start_at evaluates the start (solve(0) after restart) around the given
  // vertices only: the same values there, other entries untouched; before
  // and after anchors join, for a few vertices (their neighbourhoods alone
  // swept) and for all of them (every vertex swept); with the default
  // sweeps and others (set_start_sweeps, the same for both), which change
  // the start.
  const Mesh m = testing_util::bumpy_torus(80, 60);
  const EdgeGraph g = build_edge_graph(m);
  const int32_t n = m.num_vertices();
  const std::vector<int32_t> anchors = every(n, 37);
  std::vector<double> default_start;
  for (int32_t sweeps : {IterativeReconstruction::kStartSweeps, 0, 3, IterativeReconstruction::kMostStartSweeps}) {
    IterativeReconstruction rec;
    rec.set_nearest_rule(IterativeReconstruction::NearestRule::kFewestHopsLowest);
    ASSERT_TRUE(rec.set_start_sweeps(sweeps, sweeps).ok());
    ASSERT_TRUE(rec.init(g, 100, anchors, coefficients(m, anchors)).ok());
    for (int round = 0; round < 2; ++round) {
      std::vector<double> start;
      rec.restart();
      ASSERT_TRUE(rec.solve(0, &start).ok());
      if (round == 0 && sweeps == IterativeReconstruction::kStartSweeps) default_start = start;
      if (round == 0 && sweeps != IterativeReconstruction::kStartSweeps) {
        EXPECT_NE(start, default_start) << sweeps;
      }
      // A few vertices (their neighbourhoods swept), every 7th (every
      // vertex swept but in the last sweep), all of them.
      for (const std::vector<int32_t>& some : {std::vector<int32_t>{5, 3000, 3001, 4799, 17}, every(n, 7, 3)}) {
        std::vector<double> x(3 * static_cast<size_t>(n), -7.0);
        ASSERT_TRUE(rec.start_at(some, &x).ok());
        for (int32_t v = 0; v < n; ++v) {
          const bool asked = std::find(some.begin(), some.end(), v) != some.end();
          for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(x[3 * v + k], asked ? start[3 * v + k] : -7.0) << sweeps << " " << v;
          }
        }
      }
      std::vector<double> x(3 * static_cast<size_t>(n), -7.0);
      ASSERT_TRUE(rec.start_at(every(n, 1), &x).ok());
      EXPECT_EQ(x, start) << sweeps;
      const std::vector<int32_t> more = every(n, 37, 11 + round);
      ASSERT_TRUE(rec.add_anchors(more, coefficients(m, more)).ok());
    }
  }
}

TEST(IterativeReconstructionTest, PredictionsAndTheFinalStartTakeTheirOwnSweeps) {
  // set_start_sweeps(p, f): start and start_at sweep p times, a fresh
  // solve's start f times; each is the start of an operator set to that
  // count for both.
  const Mesh m = testing_util::bumpy_torus(40, 30);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> anchors = every(m.num_vertices(), 23);
  auto made = [&](int32_t prediction, int32_t final, std::vector<double>* predicted, std::vector<double>* solved) {
    IterativeReconstruction rec;
    rec.set_nearest_rule(IterativeReconstruction::NearestRule::kFewestHopsLowest);
    ASSERT_TRUE(rec.set_start_sweeps(prediction, final).ok());
    ASSERT_TRUE(rec.init(g, 100, anchors, coefficients(m, anchors)).ok());
    predicted->assign(3 * static_cast<size_t>(m.num_vertices()), 0.0);
    ASSERT_TRUE(rec.start(predicted).ok());
    ASSERT_TRUE(rec.solve(0, solved).ok());
  };
  std::vector<double> p2, f2, p6, f6, p, f;
  made(2, 2, &p2, &f2);
  made(6, 6, &p6, &f6);
  made(2, 6, &p, &f);
  EXPECT_EQ(p, p2);
  EXPECT_EQ(f, f6);
  EXPECT_NE(p2, p6);
}

TEST(IterativeReconstructionTest, ZeroStepsGiveTheStartAfterItsHarmonicSweeps) {
  // A fresh solve starts from the nearest-anchor shape rounded off by
  // kStartSweeps Jacobi sweeps: each free vertex to its neighbours' mean,
  // the anchors at their coefficients, every vertex from the sweep before.
  const Mesh m = testing_util::bumpy_torus(12, 8);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> anchors = every(m.num_vertices(), 9);
  const std::vector<double> c = coefficients(m, anchors);
  IterativeReconstruction rec;
  ASSERT_TRUE(rec.init(g, 100, anchors, c).ok());
  std::vector<double> expected = rec.nearest_anchor_shape(), x;
  ASSERT_TRUE(rec.solve(0, &x).ok());
  for (int sweep = 0; sweep < IterativeReconstruction::kStartSweeps; ++sweep) {
    std::vector<double> next = expected;
    for (int32_t v = 0; v < g.num_vertices(); ++v) {
      if (rec.is_anchor(v)) continue;
      for (int k = 0; k < 3; ++k) {
        double sum = 0;
        for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) sum += expected[3 * g.neighbors[p] + k];
        next[3 * v + k] = sum / g.degree(v);
      }
    }
    expected.swap(next);
  }
  EXPECT_EQ(x, expected);
  for (size_t i = 0; i < anchors.size(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(x[3 * anchors[i] + k], c[3 * i + k]);
  }
}

TEST(IterativeReconstructionTest, AddedAnchorsContinueFromTheShapeSoFar) {
  const Mesh m = testing_util::bumpy_torus(20, 12);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> first = every(m.num_vertices(), 12), more = every(m.num_vertices(), 12, 5);
  IterativeReconstruction rec;
  ASSERT_TRUE(rec.init(g, 100, first, coefficients(m, first)).ok());
  std::vector<double> coarse, x;
  ASSERT_TRUE(rec.solve(30, &coarse).ok());
  ASSERT_TRUE(rec.add_anchors(more, coefficients(m, more)).ok());
  // No steps: the shape so far, unchanged by the new anchors.
  ASSERT_TRUE(rec.solve(0, &x).ok());
  EXPECT_EQ(x, coarse);
  ASSERT_TRUE(rec.solve(800, &x).ok());
  std::vector<int32_t> all = first;
  all.insert(all.end(), more.begin(), more.end());
  EXPECT_LT(max_difference(x, global_shape(g, 100, all, coefficients(m, all))), 1e-6);
  EXPECT_EQ(rec.num_anchors(), static_cast<int32_t>(all.size()));
}

TEST(IterativeReconstructionTest, RestartForgetsTheShapeSoFar) {
  const Mesh m = testing_util::bumpy_torus(20, 12);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> first = every(m.num_vertices(), 12), more = every(m.num_vertices(), 12, 5);
  std::vector<int32_t> all = more;  // the same set, another order
  all.insert(all.end(), first.begin(), first.end());
  IterativeReconstruction warm, fresh;
  ASSERT_TRUE(warm.init(g, 100, first, coefficients(m, first)).ok());
  std::vector<double> a, b;
  ASSERT_TRUE(warm.solve(25, &a).ok());
  ASSERT_TRUE(warm.add_anchors(more, coefficients(m, more)).ok());
  warm.restart();
  ASSERT_TRUE(warm.solve(9, &a).ok());
  ASSERT_TRUE(fresh.init(g, 100, all, coefficients(m, all)).ok());
  ASSERT_TRUE(fresh.solve(9, &b).ok());
  EXPECT_EQ(a, b);
}

TEST(IterativeReconstructionTest, AGivenStartIsKeptAndTheSolutionIsAFixedPoint) {
  const Mesh m = testing_util::bumpy_torus(20, 12);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> anchors = every(m.num_vertices(), 8);
  const std::vector<double> c = coefficients(m, anchors);
  const std::vector<double> global = global_shape(g, 100, anchors, c);
  IterativeReconstruction rec;
  ASSERT_TRUE(rec.init(g, 100, anchors, c).ok());
  EXPECT_EQ(rec.set_start(std::vector<double>(5, 0.0)).message(), "a start needs 3 coordinates per vertex");
  std::vector<double> nan_start = global;
  nan_start[7] = NAN;
  EXPECT_EQ(rec.set_start(nan_start).message(), "a start coordinate is not finite");
  ASSERT_TRUE(rec.set_start(global).ok());
  std::vector<double> x;
  ASSERT_TRUE(rec.solve(0, &x).ok());
  EXPECT_EQ(x, global);
  ASSERT_TRUE(rec.solve(5, &x).ok());
  EXPECT_LT(max_difference(x, global), 1e-12);
}

TEST(IterativeReconstructionTest, TheSameCallsGiveTheSameBits) {
  const Mesh m = testing_util::bumpy_torus(30, 20);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> first = every(m.num_vertices(), 9), more = every(m.num_vertices(), 9, 4);
  std::vector<double> shapes[2];
  for (std::vector<double>& x : shapes) {
    IterativeReconstruction rec;
    ASSERT_TRUE(rec.init(g, 100, first, coefficients(m, first)).ok());
    ASSERT_TRUE(rec.solve(7, &x).ok());
    ASSERT_TRUE(rec.add_anchors(more, coefficients(m, more)).ok());
    ASSERT_TRUE(rec.solve(13, &x).ok());
  }
  EXPECT_EQ(shapes[0], shapes[1]);
}

TEST(IterativeReconstructionTest, AnyThreadCountGivesTheSameBits) {
  // Three blocks of kBlock vertices and a part: every split of the blocks.
  const Mesh m = testing_util::bumpy_torus(130, 80);
  ASSERT_GT(m.num_vertices(), 2 * IterativeReconstruction::kBlock);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> anchors = every(m.num_vertices(), 11);
  std::vector<double> one;
  for (int32_t threads : {1, 2, 3, 8}) {
    IterativeReconstruction rec;
    rec.set_threads(threads);
    ASSERT_TRUE(rec.init(g, 100, anchors, coefficients(m, anchors)).ok());
    std::vector<double> x;
    ASSERT_TRUE(rec.solve(12, &x).ok());
    if (threads == 1) {
      one = x;
    } else {
      EXPECT_EQ(x, one) << threads << " threads";
    }
  }
}

TEST(IterativeReconstructionTest, TranslatedCoefficientsTranslateTheShape) {
  // L annihilates constants, so moving every coefficient by t moves the
  // least-squares shape by t; after enough steps the iterate agrees, to the
  // single-precision steps' rounding of the 2.5 they add.
  const Mesh m = testing_util::bumpy_torus(16, 10);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> anchors = every(m.num_vertices(), 6);
  std::vector<double> c = coefficients(m, anchors);
  IterativeReconstruction rec;
  ASSERT_TRUE(rec.init(g, 100, anchors, c).ok());
  std::vector<double> before, after;
  ASSERT_TRUE(rec.solve(600, &before).ok());
  for (size_t i = 0; i < c.size(); ++i) c[i] += (i % 3 == 1) ? 2.5 : 0.0;
  ASSERT_TRUE(rec.set_coefficients(0, c).ok());
  ASSERT_TRUE(rec.solve(600, &after).ok());
  for (size_t i = 0; i < before.size(); ++i) EXPECT_NEAR(after[i], before[i] + (i % 3 == 1 ? 2.5 : 0.0), 2.5e-6);
}

TEST(IterativeReconstructionTest, BadArgumentsNameTheProblem) {
  Mesh two = testing_util::grid(2, 2);
  const int32_t offset = two.num_vertices();
  const Mesh other = testing_util::grid(2, 2);
  for (double p : other.positions) two.positions.push_back(p);
  for (int32_t t : other.triangles) two.triangles.push_back(t + offset);
  const EdgeGraph g = build_edge_graph(two);
  IterativeReconstruction rec;
  std::vector<double> x;
  EXPECT_EQ(rec.solve(1, &x).message(), "solve before init");
  EXPECT_EQ(rec.init(g, 100, {0}, {0, 0, 0}).message(),
            "the connected component of vertex 9 has no anchor (every component needs one)");
  EXPECT_EQ(rec.init(g, 0, {0, 9}, std::vector<double>(6, 0)).message(), "anchor weight must be positive and finite");
  EXPECT_EQ(rec.init(g, 100, {0, 0}, std::vector<double>(6, 0)).message(), "anchor 0 given twice");
  EXPECT_EQ(rec.init(g, 100, {0, 18}, std::vector<double>(6, 0)).message(), "anchor 18 is not a vertex (n = 18)");
  EXPECT_EQ(rec.init(g, 100, {0, 9}, std::vector<double>(5, 0)).message(),
            "need 3 coefficients per anchor: got 5 for 2 anchors");
  ASSERT_TRUE(rec.init(g, 100, {0, 9}, std::vector<double>(6, 0)).ok());
  EXPECT_EQ(rec.add_anchors({9}, {1, 1, 1}).message(), "vertex 9 is already an anchor");
  EXPECT_EQ(rec.set_coefficients(1, std::vector<double>(6, 0)).message(), "coefficients past the last anchor");
  EXPECT_EQ(rec.solve(-1, &x).message(), "negative step count");
  EXPECT_EQ(rec.set_start_sweeps(17, 8).message(), "start sweeps must be in 0..16");
  EXPECT_EQ(rec.set_start_sweeps(8, -1).message(), "start sweeps must be in 0..16");
  x.assign(3 * 18, 0.0);
  EXPECT_EQ(rec.start_at({1}, &x).message(), "start_at needs the fewest-hops nearest rule");
  rec.set_nearest_rule(IterativeReconstruction::NearestRule::kFewestHopsLowest);
  ASSERT_TRUE(rec.init(g, 100, {0, 9}, std::vector<double>(6, 0)).ok());
  EXPECT_EQ(rec.start_at({18}, &x).message(), "start_at: vertex out of range");
  x.resize(5);
  EXPECT_EQ(rec.start_at({1}, &x).message(), "positions need 3 per vertex");
  // The fewest-hops rule finds an unanchored component by its own search:
  // the same message, and nothing to go on from.
  EXPECT_EQ(rec.init(g, 100, {0}, {0, 0, 0}).message(),
            "the connected component of vertex 9 has no anchor (every component needs one)");
  EXPECT_EQ(rec.add_anchors({9}, {1, 1, 1}).message(), "add_anchors before init");
  EXPECT_EQ(rec.solve(1, &x).message(), "solve before init");
}

}  // namespace
}  // namespace gab
