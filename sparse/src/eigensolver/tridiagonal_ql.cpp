// Implicit QL with Wilkinson's shift, eigenvalues only: Golub & Van Loan,
// "Matrix Computations" (4th ed.), sec. 8.3 (the symmetric QR step, here
// chased from the bottom up so the top eigenvalue converges first), and
// Parlett, "The Symmetric Eigenvalue Problem", ch. 8. Each sweep works on
// the unreduced block [l, end] above the first negligible subdiagonal; a
// plane rotation per row chases the shift's bulge up to row l.
#include "eigensolver/tridiagonal_ql.h"
#include "eigensolver/plane_rotation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gab {
namespace eigen_detail {

bool tridiagonal_eigenvalues(int32_t m, double* d, double* e) {
  if (m <= 0) return true;
  const double eps = std::numeric_limits<double>::epsilon();
  e[m - 1] = 0.0;
  bool ok = true;
  for (int32_t l = 0; l < m; ++l) {
    for (int32_t sweep = 0;; ++sweep) {
      // end: the first row at or below l whose coupling to the next is
      // negligible against its neighbours (GVL's deflation test).
      int32_t end = l;
      while (end < m - 1 && std::abs(e[end]) > eps * (std::abs(d[end]) + std::abs(d[end + 1]))) ++end;
      if (end == l) break;
      if (sweep == 60) {
        ok = false;
        break;
      }
      // Wilkinson's shift from the top 2 x 2, folded into the first
      // rotation's g.
      double g = (d[l + 1] - d[l]) / (2.0 * e[l]);
      double r = rotation_norm(g, 1.0);
      g = d[end] - d[l] + e[l] / (g + std::copysign(r, g));
      double s = 1.0, c = 1.0, p = 0.0;
      bool underflow = false;
      for (int32_t i = end - 1; i >= l; --i) {
        const double f = s * e[i];
        const double b = c * e[i];
        r = rotation_norm(f, g);
        e[i + 1] = r;
        if (r == 0.0) {
          // The bulge vanished: the block splits at i + 1; start over.
          d[i + 1] -= p;
          e[end] = 0.0;
          underflow = true;
          break;
        }
        s = f / r;
        c = g / r;
        g = d[i + 1] - p;
        r = (d[i] - g) * s + 2.0 * c * b;
        p = s * r;
        d[i + 1] = g + p;
        g = c * r - b;
      }
      if (underflow) continue;
      d[l] -= p;
      e[l] = g;
      e[end] = 0.0;
    }
  }
  std::sort(d, d + m);
  return ok;
}

}  // namespace eigen_detail
}  // namespace gab
