// Eigenvalues of a symmetric tridiagonal matrix by the implicit QL
// algorithm (internal).
#pragma once

#include <cstdint>

namespace gab {
namespace eigen_detail {

// d (m) the diagonal, e (m) the subdiagonal: e[i] couples rows i and i + 1,
// e[m - 1] is workspace. On return d holds the eigenvalues ascending and e
// is destroyed. False if some eigenvalue needed more than 60 sweeps (never
// seen in practice; d is then unordered). O(m^2), no allocation.
bool tridiagonal_eigenvalues(int32_t m, double* d, double* e);

}  // namespace eigen_detail
}  // namespace gab
