// Closest points, the BVH against brute force, area-uniform sampling, and
// the metrics on cases with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gab/mesh/metrics.h"
#include "gab/mesh/point_triangle.h"
#include "gab/mesh/surface_sampling.h"
#include "gab/mesh/triangle_bvh.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

double dist2(const double* a, const double* b) {
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}

TEST(PointTriangleTest, EveryVoronoiRegion) {
  const double a[3] = {0, 0, 0}, b[3] = {2, 0, 0}, c[3] = {0, 2, 0};
  struct Case {
    double p[3], q[3];
  };
  const Case cases[] = {
      {{0.5, 0.5, 3}, {0.5, 0.5, 0}},    // face
      {{-1, -1, 1}, {0, 0, 0}},          // vertex a
      {{3, -1, 0}, {2, 0, 0}},           // vertex b
      {{-1, 3, 0}, {0, 2, 0}},           // vertex c
      {{1, -2, 1}, {1, 0, 0}},           // edge ab
      {{-2, 1, -1}, {0, 1, 0}},          // edge ca
      {{2, 2, 0}, {1, 1, 0}},            // edge bc
      {{0.25, 0.25, 0}, {0.25, 0.25, 0}} // inside
  };
  for (const Case& t : cases) {
    double q[3];
    const double d2 = closest_point_on_triangle(t.p, a, b, c, q);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(q[i], t.q[i], 1e-15);
    EXPECT_NEAR(d2, dist2(t.p, t.q), 1e-14);
  }
}

TEST(PointTriangleTest, DegenerateTrianglesAreTheirEdges) {
  const double p[3] = {1, 1, 0};
  const double a[3] = {0, 0, 0}, b[3] = {2, 0, 0}, c[3] = {4, 0, 0};  // collinear
  double q[3];
  EXPECT_DOUBLE_EQ(closest_point_on_triangle(p, a, b, c, q), 1.0);
  EXPECT_DOUBLE_EQ(q[0], 1.0);
  EXPECT_DOUBLE_EQ(closest_point_on_triangle(p, a, a, a, q), 2.0);  // a point
  EXPECT_DOUBLE_EQ(closest_point_on_triangle(p, a, a, b, q), 1.0);  // a segment
}

TEST(PointTriangleTest, NoPointOfTheTriangleIsCloser) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    double a[3], b[3], c[3], p[3], q[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = u(rng);
      b[i] = u(rng);
      c[i] = u(rng);
      p[i] = 2 * u(rng);
    }
    const double d2 = closest_point_on_triangle(p, a, b, c, q);
    EXPECT_NEAR(d2, dist2(p, q), 1e-12);
    // q lies in the triangle's plane region (barycentric weights >= 0) and
    // beats a dense grid of the triangle's points.
    for (int i = 0; i <= 40; ++i) {
      for (int j = 0; i + j <= 40; ++j) {
        const double s = i / 40.0, t = j / 40.0;
        double x[3];
        for (int k = 0; k < 3; ++k) x[k] = a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]);
        EXPECT_LE(d2, dist2(p, x) + 1e-12);
      }
    }
  }
}

TEST(TriangleBvhTest, EqualsBruteForceOnRandomPoints) {
  Mesh m = testing_util::torus(40, 25);
  // Add a far component, duplicate and degenerate triangles.
  const int32_t base = m.num_vertices();
  m.positions.insert(m.positions.end(), {3, 3, 3, 4, 3, 3, 3, 4, 3});
  m.triangles.insert(m.triangles.end(), {base, base + 1, base + 2, base, base + 1, base + 2, base, base, base + 1});
  const TriangleBvh tree(m);
  EXPECT_EQ(tree.num_triangles(), m.num_triangles());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-2, 5);
  int32_t hint = -1;
  for (int trial = 0; trial < 2000; ++trial) {
    const double p[3] = {u(rng), u(rng), u(rng) * 0.5};
    double best = INFINITY;
    for (int32_t t = 0; t < m.num_triangles(); ++t) {
      double q[3];
      best = std::min(best, closest_point_on_triangle(p, &m.positions[3 * m.triangles[3 * t]],
                                                      &m.positions[3 * m.triangles[3 * t + 1]],
                                                      &m.positions[3 * m.triangles[3 * t + 2]], q));
    }
    const TriangleBvh::Hit hit = tree.closest(p, hint);
    EXPECT_EQ(hit.distance_squared, best) << trial;
    EXPECT_DOUBLE_EQ(dist2(p, hit.point), hit.distance_squared);
    hint = trial % 3 == 0 ? -1 : hit.triangle;  // with and without a hint
    EXPECT_EQ(tree.closest(p).distance_squared, best);
  }
}

TEST(SurfaceSamplingTest, AreaUniformStratifiedAndDeterministic) {
  // Two triangles of areas 1 and 3, and a degenerate one that gets nothing.
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 2, 0, 10, 0, 0, 13, 0, 0, 10, 2, 0, 20, 0, 0, 21, 0, 0};
  m.triangles = {0, 1, 2, 6, 7, 6, 3, 4, 5};
  std::vector<int32_t> tri;
  const std::vector<double> pts = sample_surface(m, 4000, 42, &tri);
  ASSERT_EQ(pts.size(), 12000u);
  int count[3] = {0, 0, 0};
  for (size_t j = 0; j < tri.size(); ++j) {
    ++count[tri[j]];
    const double* p = &pts[3 * j];
    if (tri[j] == 0) {
      EXPECT_TRUE(p[0] >= 0 && p[1] >= 0 && 2 * p[0] + p[1] <= 2 + 1e-12);
    } else {
      EXPECT_TRUE(p[0] >= 10 && p[1] >= 0 && 2 * (p[0] - 10) + 3 * p[1] <= 6 + 1e-12);
    }
  }
  // Stratification: each triangle gets its area share up to one point.
  EXPECT_NEAR(count[0], 1000, 1);
  EXPECT_EQ(count[1], 0);
  EXPECT_NEAR(count[2], 3000, 1);
  // Uniform within a triangle: the mean is the centroid.
  double cx = 0, cy = 0;
  for (size_t j = 0; j < tri.size(); ++j) {
    if (tri[j] != 2) continue;
    cx += pts[3 * j];
    cy += pts[3 * j + 1];
  }
  EXPECT_NEAR(cx / count[2], 11.0, 0.03);
  EXPECT_NEAR(cy / count[2], 2.0 / 3.0, 0.03);
  EXPECT_EQ(sample_surface(m, 4000, 42), pts);
  EXPECT_NE(sample_surface(m, 4000, 43), pts);
}

TEST(MetricsTest, VertexDistances) {
  const Mesh a = testing_util::grid(2, 1);
  Mesh b = a;
  b.positions[2] += 3;   // vertex 0 moves 3 along z
  b.positions[3] += 4;   // vertex 1 moves 4 along x
  VertexDistance d;
  ASSERT_TRUE(vertex_distance(a, b, &d).ok());
  EXPECT_DOUBLE_EQ(d.linf, 4.0);
  EXPECT_DOUBLE_EQ(d.rms, std::sqrt((9.0 + 16.0) / 6.0));
  EXPECT_DOUBLE_EQ(bounding_box_diagonal(a), std::sqrt(5.0));
  EXPECT_EQ(vertex_distance(a, testing_util::grid(1, 1), &d).message(), "vertex counts differ (6 and 4)");
}

TEST(MetricsTest, ShiftedSquareHasHausdorffD) {
  // A unit square and the same square lifted by d: every distance is d.
  const double d = 0.125;
  const Mesh a = testing_util::grid(4, 4, 0.25);
  Mesh b = a;
  for (size_t i = 2; i < b.positions.size(); i += 3) b.positions[i] += d;
  SurfaceDistanceOptions o;
  o.samples = 20000;
  SurfaceDistance s;
  ASSERT_TRUE(surface_distance(a, b, o, &s).ok());
  EXPECT_NEAR(s.hausdorff, d, 1e-15);
  EXPECT_NEAR(s.mean, d, 1e-15);
  EXPECT_NEAR(s.rms, d, 1e-15);
  EXPECT_EQ(s.a_to_b.samples, 20000);
}

TEST(MetricsTest, SlidSquareHasKnownMeanAndHausdorff) {
  // The unit square slid by s in x within its plane: points of A with
  // x < s are at distance s - x from B, the others at 0. A to B: mean
  // s^2 / 2, mean square s^3 / 3, max s; B to A is the mirror image.
  const double s = 0.3;
  const Mesh a = testing_util::grid(10, 10, 0.1);
  Mesh b = a;
  for (size_t i = 0; i < b.positions.size(); i += 3) b.positions[i] += s;
  SurfaceDistanceOptions o;
  o.samples = 200000;
  SurfaceDistance r;
  ASSERT_TRUE(surface_distance(a, b, o, &r).ok());
  EXPECT_NEAR(r.a_to_b.mean, s * s / 2, 1e-4);
  EXPECT_NEAR(r.b_to_a.mean, s * s / 2, 1e-4);
  EXPECT_NEAR(r.rms, std::sqrt(s * s * s / 3), 1e-4);
  EXPECT_NEAR(r.hausdorff, s, 1e-12);  // reached at the vertices (0, y)
}

TEST(MetricsTest, ConcentricToriWithDifferentVertexCounts) {
  // Two concentric tori with different tessellations and minor radii:
  // every distance is close to the radius difference.
  const Mesh a = testing_util::torus(160, 60, 1.0, 0.30);
  const Mesh b = testing_util::torus(100, 50, 1.0, 0.25);
  SurfaceDistance r;
  ASSERT_TRUE(surface_distance(a, b, SurfaceDistanceOptions(), &r).ok());
  EXPECT_NEAR(r.mean, 0.05, 0.002);
  EXPECT_NEAR(r.hausdorff, 0.05, 0.003);
  EXPECT_EQ(r.a_to_b.samples, default_sample_count(a, b));
  // Same inputs, same numbers.
  SurfaceDistance again;
  ASSERT_TRUE(surface_distance(a, b, SurfaceDistanceOptions(), &again).ok());
  EXPECT_EQ(again.mean, r.mean);
  EXPECT_EQ(again.hausdorff, r.hausdorff);
}

TEST(MetricsTest, IsolatedVerticesAreNotSurface) {
  // A far, unreferenced vertex changes neither the samples nor the max; a
  // degenerate face and a duplicate face change nothing either.
  const Mesh a = testing_util::grid(2, 2);
  Mesh b = a;
  b.positions.insert(b.positions.end(), {100, 100, 100});
  b.triangles.insert(b.triangles.end(), {0, 1, 1, 0, 1, 4});
  SurfaceDistanceOptions o;
  o.samples = 1000;
  SurfaceDistance r;
  ASSERT_TRUE(surface_distance(a, b, o, &r).ok());
  EXPECT_LT(r.hausdorff, 1e-12);
}

TEST(MetricsTest, RejectsInvalidMeshes) {
  Mesh bad = testing_util::grid(1, 1);
  bad.triangles.clear();
  SurfaceDistance r;
  EXPECT_EQ(surface_distance(testing_util::grid(1, 1), bad, SurfaceDistanceOptions(), &r).message(),
            "second mesh: mesh has no faces");
}

}  // namespace
}  // namespace gab
