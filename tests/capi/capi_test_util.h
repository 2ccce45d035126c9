// Inputs for the C API tests: a mesh as the C arrays, an SPD matrix as a
// lower-triangle CSC, and the oriented-triangle set the codec keeps.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"

namespace gab_test {

// The triangles as a set of oriented triangles: the codec keeps each
// triangle's vertices and orientation, not the list's order or which corner
// comes first.
inline std::vector<std::array<int32_t, 3>> oriented_set(const int32_t* triangles, int32_t t) {
  std::vector<std::array<int32_t, 3>> set;
  for (int32_t f = 0; f < t; ++f) {
    std::array<int32_t, 3> c = {triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    set.push_back(c);
  }
  std::sort(set.begin(), set.end());
  return set;
}

// Lower triangle of the 5-point Laplacian of a k x k grid plus shift * I:
// symmetric positive definite for shift > 0, n = k^2.
inline gab::CscMatrix grid_laplacian(int32_t k, double shift) {
  std::vector<gab::Triplet> entries;
  for (int32_t y = 0; y < k; ++y) {
    for (int32_t x = 0; x < k; ++x) {
      const int32_t v = x + k * y;
      entries.push_back({v, v, 4.0 + shift});
      if (x + 1 < k) entries.push_back({v + 1, v, -1.0});
      if (y + 1 < k) entries.push_back({v + k, v, -1.0});
    }
  }
  gab::CscMatrix a;
  if (!gab::csc_from_triplets(k * k, k * k, entries, &a).ok()) a = gab::CscMatrix();
  return a;
}

// ||A x - b|| / ||b|| for a symmetric A given by its lower triangle.
inline double relative_residual(const gab::CscMatrix& lower, const double* x, const double* b) {
  std::vector<double> ax(lower.nrows);
  gab::symmetric_lower_matvec(lower, x, ax.data());
  double r = 0, nb = 0;
  for (int32_t i = 0; i < lower.nrows; ++i) {
    r += (ax[i] - b[i]) * (ax[i] - b[i]);
    nb += b[i] * b[i];
  }
  return std::sqrt(r / nb);
}

}  // namespace gab_test
