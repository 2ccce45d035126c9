// Vertex and surface error metrics. Sums run in a fixed order over samples
// in triangle order, so results are reproducible bit for bit.
#include "gab/mesh/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gab/mesh/surface_sampling.h"
#include "gab/mesh/triangle_bvh.h"

namespace gab {

double bounding_box_diagonal(const Mesh& mesh) {
  if (mesh.positions.empty()) return 0;
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i) lo[i] = hi[i] = mesh.positions[i];
  for (size_t k = 0; k < mesh.positions.size(); ++k) {
    lo[k % 3] = std::min(lo[k % 3], mesh.positions[k]);
    hi[k % 3] = std::max(hi[k % 3], mesh.positions[k]);
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

void squared_vertex_errors(const Mesh& mesh, const std::vector<double>& shape, std::vector<double>* error2,
                           VertexDistance* out) {
  const int32_t n = mesh.num_vertices();
  error2->resize(n);
  double sum2 = 0.0, max2 = 0.0;
  for (int32_t v = 0; v < n; ++v) {
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = shape[3 * static_cast<size_t>(v) + c] - mesh.positions[3 * static_cast<size_t>(v) + c];
      d2 += d * d;
    }
    (*error2)[v] = d2;
    sum2 += d2;
    max2 = std::max(max2, d2);
  }
  out->rms = std::sqrt(sum2 / std::max(n, 1));
  out->linf = std::sqrt(max2);
}

Status vertex_distance(const Mesh& a, const Mesh& b, VertexDistance* out) {
  if (a.num_vertices() != b.num_vertices()) {
    return Status::Error(StatusCode::kInvalidArgument, "vertex counts differ (" + std::to_string(a.num_vertices()) +
                                                           " and " + std::to_string(b.num_vertices()) + ")");
  }
  const int32_t n = a.num_vertices();
  double max2 = 0, sum2 = 0;
  for (int32_t v = 0; v < n; ++v) {
    double d2 = 0;
    for (int i = 0; i < 3; ++i) {
      const double d = a.positions[3 * static_cast<size_t>(v) + i] - b.positions[3 * static_cast<size_t>(v) + i];
      d2 += d * d;
    }
    max2 = std::max(max2, d2);
    sum2 += d2;
  }
  out->linf = std::sqrt(max2);
  out->rms = n > 0 ? std::sqrt(sum2 / n) : 0.0;
  return Status::Ok();
}

namespace {

// Distances from `from`'s samples and vertices to the surface of `to`.
// Returns sum and sum of squares for the caller's pooled statistics.
DirectedDistance directed(const Mesh& from, const TriangleBvh& to, const SurfaceDistanceOptions& options,
                          uint64_t seed, double* sum, double* sum2) {
  DirectedDistance d;
  std::vector<int32_t> tri_of;
  const std::vector<double> points = sample_surface(from, options.samples, seed, &tri_of);
  d.samples = static_cast<int64_t>(tri_of.size());
  double s = 0, s2 = 0, max2 = 0;
  int32_t hint = -1;  // samples come in triangle order: the last answer is a good first bound
  for (int64_t j = 0; j < d.samples; ++j) {
    const TriangleBvh::Hit hit = to.closest(&points[3 * static_cast<size_t>(j)], hint);
    hint = hit.triangle;
    s += std::sqrt(hit.distance_squared);
    s2 += hit.distance_squared;
    max2 = std::max(max2, hit.distance_squared);
  }
  // Vertices used by a triangle: where the max of a piecewise-linear
  // difference usually sits, and where random samples never land.
  std::vector<char> used(from.num_vertices(), 0);
  for (int32_t v : from.triangles) used[v] = 1;
  for (int32_t v = 0; v < from.num_vertices(); ++v) {
    if (!used[v]) continue;
    const TriangleBvh::Hit hit = to.closest(&from.positions[3 * static_cast<size_t>(v)], hint);
    hint = hit.triangle;
    max2 = std::max(max2, hit.distance_squared);
  }
  d.mean = d.samples > 0 ? s / d.samples : 0.0;
  d.rms = d.samples > 0 ? std::sqrt(s2 / d.samples) : 0.0;
  d.max = std::sqrt(max2);
  *sum = s;
  *sum2 = s2;
  return d;
}

}  // namespace

int64_t default_sample_count(const Mesh& a, const Mesh& b) {
  const int64_t most = std::max(a.num_triangles(), b.num_triangles());
  return std::max<int64_t>(100000, 2 * most);
}

Status surface_distance(const Mesh& a, const Mesh& b, const SurfaceDistanceOptions& given, SurfaceDistance* out) {
  GAB_RETURN_IF_ERROR(validate_mesh(a, "first mesh"));
  GAB_RETURN_IF_ERROR(validate_mesh(b, "second mesh"));
  SurfaceDistanceOptions options = given;
  if (options.samples < 0) options.samples = default_sample_count(a, b);
  const TriangleBvh tree_a(a), tree_b(b);
  double sa, sa2, sb, sb2;
  SurfaceDistance r;
  // Different streams for the two surfaces, both fixed by the seed.
  r.a_to_b = directed(a, tree_b, options, options.seed, &sa, &sa2);
  r.b_to_a = directed(b, tree_a, options, options.seed ^ 0x5bd1e9955bd1e995ULL, &sb, &sb2);
  const int64_t total = r.a_to_b.samples + r.b_to_a.samples;
  r.mean = total > 0 ? (sa + sb) / total : 0.0;
  r.rms = total > 0 ? std::sqrt((sa2 + sb2) / total) : 0.0;
  r.hausdorff = std::max(r.a_to_b.max, r.b_to_a.max);
  *out = r;
  return Status::Ok();
}

}  // namespace gab
