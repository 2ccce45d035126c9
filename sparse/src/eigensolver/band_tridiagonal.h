// Reduction of a symmetric band matrix to tridiagonal form by plane
// rotations, eigenvalues only (internal).
#pragma once

#include <cstdint>
#include <vector>

namespace gab {
namespace eigen_detail {

// A symmetric m x m matrix of half-bandwidth b, its lower band stored by
// columns: entry (i, j), 0 <= i - j <= b, at data[(i - j) + j * (b + 1)].
struct SymmetricBand {
  int32_t m = 0;
  int32_t b = 0;
  std::vector<double> data;  // (b + 1) * m

  double& at(int32_t i, int32_t j) { return data[(i - j) + static_cast<int64_t>(j) * (b + 1)]; }
  double at(int32_t i, int32_t j) const { return data[(i - j) + static_cast<int64_t>(j) * (b + 1)]; }
};

// The tridiagonal matrix orthogonally similar to `band`: diagonal d (m),
// subdiagonal e (m; e[i] couples i and i + 1, e[m - 1] = 0). `work` is
// resized to (b + 2) m. About 6 (b + 2) m^2 / 2 flops for b > 1; a copy
// for b <= 1.
void band_to_tridiagonal(const SymmetricBand& band, std::vector<double>* work, double* d,
                         double* e);

}  // namespace eigen_detail
}  // namespace gab
