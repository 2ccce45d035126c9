// The mesh the .gab fuzzer's geometry-only seeds were made from (and that
// tests/codec replays them with): a 10 x 6 torus, built in code.
#pragma once

#include <cmath>

#include "gab/mesh/mesh.h"

namespace gab_fuzz {

inline gab::Mesh seed_torus() {
  const int n = 10, m = 6;
  const double kPi = 3.14159265358979323846;
  gab::Mesh t;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      t.positions.insert(t.positions.end(), {(1 + 0.3 * std::cos(v)) * std::cos(u),
                                             (1 + 0.3 * std::cos(v)) * std::sin(u), 0.3 * std::sin(v)});
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

}  // namespace gab_fuzz
