// cholmod_updown timed on one update of the anchor rule (a column of w = 1
// entries at the anchors' rows), for both CHOLMOD peer benchmarks.
#pragma once

#include <cholmod.h>

#include <chrono>
#include <cstdint>
#include <vector>

namespace gab_bench {

// The inverse of f's permutation: original row -> row of f.
inline std::vector<int32_t> factor_inverse_perm(const cholmod_factor* f) {
  const int32_t n = static_cast<int32_t>(f->n);
  const int32_t* perm = static_cast<const int32_t*>(f->Perm);
  std::vector<int32_t> inverse(static_cast<size_t>(n));
  for (int32_t k = 0; k < n; ++k) inverse[perm[k]] = k;
  return inverse;
}

// Seconds cholmod_updown takes to add the `width` anchors rows[0 .. width)
// (original numbering) to f, a simplicial LDL^T (cholmod_change_factor
// first); building the update's columns is not timed.
inline double timed_updown(cholmod_factor* f, const std::vector<int32_t>& inverse, const int32_t* rows,
                           int32_t width, cholmod_common* c) {
  const int32_t n = static_cast<int32_t>(f->n);
  cholmod_sparse* cs = cholmod_allocate_sparse(n, width, width, 1, 1, 0, CHOLMOD_REAL, c);
  int32_t* cp = static_cast<int32_t*>(cs->p);
  int32_t* ci = static_cast<int32_t*>(cs->i);
  double* cx = static_cast<double*>(cs->x);
  for (int32_t q = 0; q < width; ++q) {
    cp[q] = q;
    ci[q] = inverse[rows[q]];
    cx[q] = 1.0;
  }
  cp[width] = width;
  cholmod_sort(cs, c);
  const auto t0 = std::chrono::steady_clock::now();
  cholmod_updown(1, cs, f, c);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  cholmod_free_sparse(&cs, c);
  return seconds;
}

}  // namespace gab_bench
