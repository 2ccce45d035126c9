// Band to tridiagonal by Givens rotations with bulge chasing (Rutishauser
// 1963, Schwarz 1968; Golub & Van Loan, sec. 8.3 and the band notes of
// sec. 4.3). Column j's entries below the subdiagonal are zeroed from the
// band's edge inwards, each by a rotation of the adjacent rows (i - 1, i).
// That rotation puts one entry outside the band, b + 1 below the diagonal
// (the bulge); a rotation b rows further down removes it and makes the next
// bulge b further on, until it falls off the matrix. The work array holds
// half-bandwidth b + 1, so a bulge has a place.
#include "eigensolver/band_tridiagonal.h"
#include "eigensolver/plane_rotation.h"

#include <algorithm>
#include <cmath>

namespace gab {
namespace eigen_detail {

namespace {

// The working band: half-bandwidth b + 1, symmetric access.
struct Work {
  int32_t m, b, ld;
  double* a;
  double& at(int32_t i, int32_t j) {
    if (i < j) std::swap(i, j);
    return a[(i - j) + static_cast<int64_t>(j) * ld];
  }
};

// Applies the rotation [c s; -s c] to rows and columns (q - 1, q): every
// entry that can be nonzero lies in columns [q - b - 1, q + b]. Left of the
// pair the two entries of column k are adjacent (rows p and q of it); right
// of it they lie in columns p and q at rows k; the three ranges are written
// apart so the loops index storage directly.
void rotate(Work& w, int32_t q, double c, double s) {
  const int32_t p = q - 1;
  const int32_t lo = std::max(0, q - w.b - 1), hi = std::min(w.m - 1, q + w.b);
  for (int32_t k = lo; k < p; ++k) {
    double* col = w.a + static_cast<int64_t>(k) * w.ld;
    const double x = col[p - k], y = col[q - k];
    col[p - k] = c * x + s * y;
    col[q - k] = -s * x + c * y;
  }
  double* cp = w.a + static_cast<int64_t>(p) * w.ld;  // column p: (p + t, p) at cp[t]
  double* cq = w.a + static_cast<int64_t>(q) * w.ld;
  for (int32_t k = q + 1; k <= hi; ++k) {
    const double x = cp[k - p], y = cq[k - q];
    cp[k - p] = c * x + s * y;
    cq[k - q] = -s * x + c * y;
  }
  const double app = cp[0], aqq = cq[0], apq = cp[1];
  cp[0] = c * c * app + 2.0 * c * s * apq + s * s * aqq;
  cq[0] = s * s * app - 2.0 * c * s * apq + c * c * aqq;
  cp[1] = c * s * (aqq - app) + (c * c - s * s) * apq;
}

// Zeroes entry (q, col) against (q - 1, col) by a rotation of (q - 1, q).
void eliminate(Work& w, int32_t q, int32_t col) {
  const double x = w.at(q - 1, col), y = w.at(q, col);
  if (y == 0.0) return;
  const double r = rotation_norm(x, y);
  rotate(w, q, x / r, y / r);
  w.at(q, col) = 0.0;  // exactly, not to rounding
}

}  // namespace

void band_to_tridiagonal(const SymmetricBand& band, std::vector<double>* work, double* d,
                         double* e) {
  const int32_t m = band.m, b = band.b;
  if (m == 0) return;
  if (b <= 1) {
    for (int32_t i = 0; i < m; ++i) {
      d[i] = band.at(i, i);
      e[i] = (b == 1 && i + 1 < m) ? band.at(i + 1, i) : 0.0;
    }
    return;
  }
  Work w{m, b, b + 2, nullptr};
  work->assign(static_cast<size_t>(w.ld) * m, 0.0);
  w.a = work->data();
  for (int32_t j = 0; j < m; ++j) {
    for (int32_t t = 0; t <= b && j + t < m; ++t) w.at(j + t, j) = band.at(j + t, j);
  }
  for (int32_t j = 0; j + 2 < m; ++j) {
    for (int32_t r = std::min(b, m - 1 - j); r >= 2; --r) {
      eliminate(w, j + r, j);
      // The rotation of (q - 1, q), q = j + r, left a bulge at (q + b, q - 1).
      for (int32_t q = j + r; q + b < m; q += b) eliminate(w, q + b, q - 1);
    }
  }
  for (int32_t i = 0; i < m; ++i) {
    d[i] = w.at(i, i);
    e[i] = i + 1 < m ? w.at(i + 1, i) : 0.0;
  }
}

}  // namespace eigen_detail
}  // namespace gab
