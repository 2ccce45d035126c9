// Small meshes generated in code, shared by the mesh-layer and codec tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "gab/mesh/mesh.h"

namespace gab {
namespace testing_util {

// An nx x ny grid of unit squares in the z = 0 plane, each split in two
// triangles; vertex (i, j) is i + j (nx + 1), at (i, j, 0) * spacing.
inline Mesh grid(int nx, int ny, double spacing = 1.0) {
  Mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.positions.insert(m.positions.end(), {i * spacing, j * spacing, 0.0});
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int32_t v = i + j * (nx + 1), r = v + 1, u = v + nx + 1, ur = u + 1;
      m.triangles.insert(m.triangles.end(), {v, r, ur, v, ur, u});
    }
  }
  return m;
}

// A closed torus (genus 1): n x m quads split in two, radii R and r.
inline Mesh torus(int n, int m, double R = 1.0, double r = 0.3) {
  Mesh t;
  const double kPi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      t.positions.insert(t.positions.end(),
                         {(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const int32_t a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m,
                    d = i * m + (j + 1) % m;
      t.triangles.insert(t.triangles.end(), {a, b, c, a, c, d});
    }
  }
  return t;
}

// A torus with a deterministic bumpy radius (no symmetry, so no exact ties
// in the greedy error ranking).
inline Mesh bumpy_torus(int n, int m) {
  Mesh t = torus(n, m);
  for (int32_t v = 0; v < t.num_vertices(); ++v) {
    double* p = &t.positions[3 * static_cast<size_t>(v)];
    const double bump = 1.0 + 0.08 * std::sin(3.1 * p[0] + 1.3) * std::cos(2.3 * p[1] - 0.4) + 0.03 * std::sin(7.0 * p[2]);
    for (int c = 0; c < 3; ++c) p[c] *= bump;
  }
  return t;
}

// A bumpy torus whose radius also carries vertex-scale noise (relative
// `amplitude`): detail a smooth prior cannot predict, so at a tight target
// most vertices become anchors.
inline Mesh rough_torus(int n, int m, double amplitude) {
  Mesh t = bumpy_torus(n, m);
  uint32_t state = 12345;
  for (int32_t v = 0; v < t.num_vertices(); ++v) {
    state = state * 1664525u + 1013904223u;
    const double noise = amplitude * (static_cast<double>(state >> 8) / (1u << 24) - 0.5);
    for (int c = 0; c < 3; ++c) t.positions[3 * static_cast<size_t>(v) + c] *= 1.0 + noise;
  }
  return t;
}

// A random triangle soup for the connectivity tests: 1..max_count
// triangles over n = min_n..max_n vertices with uniform indices (so
// non-manifold edges and vertices, mixed orientations and isolated vertices
// abound); `proper` leaves out triangles with a repeated vertex. *n gets n.
inline std::vector<int32_t> random_soup(std::mt19937* rng, int32_t min_n, int32_t max_n, int32_t max_count,
                                        bool proper, int32_t* n) {
  *n = min_n + static_cast<int32_t>((*rng)() % static_cast<uint32_t>(max_n - min_n + 1));
  const int32_t count = 1 + static_cast<int32_t>((*rng)() % static_cast<uint32_t>(max_count));
  std::vector<int32_t> t;
  while (static_cast<int32_t>(t.size()) < 3 * count) {
    const int32_t a = static_cast<int32_t>((*rng)() % static_cast<uint32_t>(*n)),
                  b = static_cast<int32_t>((*rng)() % static_cast<uint32_t>(*n)),
                  c = static_cast<int32_t>((*rng)() % static_cast<uint32_t>(*n));
    if (!proper || (a != b && b != c && a != c)) t.insert(t.end(), {a, b, c});
  }
  return t;
}

}  // namespace testing_util
}  // namespace gab
