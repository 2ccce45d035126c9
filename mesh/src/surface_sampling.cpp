// Area-uniform surface sampling. Jittered stratification over the cumulative
// area keeps the estimate of a surface integral unbiased (each point is
// uniform over the surface) with less variance than independent draws; the
// point in its triangle uses the square-root map of Turk ("Generating random
// points in triangles", Graphics Gems, 1990): for r1, r2 uniform,
// (1 - sqrt r1) a + sqrt r1 (1 - r2) b + sqrt r1 r2 c is uniform on abc.
#include "gab/mesh/surface_sampling.h"

#include <cmath>
#include <random>

namespace gab {
namespace {

// Uniform in [0, 1) from 53 of the generator's bits. std::mt19937_64's
// sequence is fixed by the standard (unlike <random>'s distributions), so
// the samples are the same on every platform.
double uniform01(std::mt19937_64* rng) { return static_cast<double>((*rng)() >> 11) * (1.0 / 9007199254740992.0); }

}  // namespace

std::vector<double> triangle_areas(const Mesh& mesh) {
  const int32_t nt = mesh.num_triangles();
  std::vector<double> area(nt);
  for (int32_t t = 0; t < nt; ++t) {
    const double* a = &mesh.positions[3 * static_cast<size_t>(mesh.triangles[3 * static_cast<size_t>(t)])];
    const double* b = &mesh.positions[3 * static_cast<size_t>(mesh.triangles[3 * static_cast<size_t>(t) + 1])];
    const double* c = &mesh.positions[3 * static_cast<size_t>(mesh.triangles[3 * static_cast<size_t>(t) + 2])];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    area[t] = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

std::vector<double> sample_surface(const Mesh& mesh, int64_t count, uint64_t seed, std::vector<int32_t>* triangle_of) {
  std::vector<double> points;
  if (triangle_of != nullptr) triangle_of->clear();
  const std::vector<double> area = triangle_areas(mesh);
  double total = 0;
  for (double a : area) total += a;
  if (count <= 0 || !(total > 0)) return points;
  points.reserve(static_cast<size_t>(count) * 3);
  if (triangle_of != nullptr) triangle_of->reserve(static_cast<size_t>(count));
  std::mt19937_64 rng(seed);
  const int32_t nt = mesh.num_triangles();
  int32_t last = nt - 1;  // the last triangle with area: rounding must not leave us on a later, empty one
  while (area[last] == 0) --last;
  int32_t t = 0;
  double below = 0;  // area of triangles before t
  for (int64_t j = 0; j < count; ++j) {
    const double target = (static_cast<double>(j) + uniform01(&rng)) / static_cast<double>(count) * total;
    // Targets increase with j, so the triangle cursor only moves forward.
    while (t < last && (below + area[t] <= target || area[t] == 0)) below += area[t++];
    const double r1 = std::sqrt(uniform01(&rng)), r2 = uniform01(&rng);
    const double wa = 1 - r1, wb = r1 * (1 - r2), wc = r1 * r2;
    const double* a = &mesh.positions[3 * static_cast<size_t>(mesh.triangles[3 * static_cast<size_t>(t)])];
    const double* b = &mesh.positions[3 * static_cast<size_t>(mesh.triangles[3 * static_cast<size_t>(t) + 1])];
    const double* c = &mesh.positions[3 * static_cast<size_t>(mesh.triangles[3 * static_cast<size_t>(t) + 2])];
    for (int i = 0; i < 3; ++i) points.push_back(wa * a[i] + wb * b[i] + wc * c[i]);
    if (triangle_of != nullptr) triangle_of->push_back(t);
  }
  return points;
}

}  // namespace gab
