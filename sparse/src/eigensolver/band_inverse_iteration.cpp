// Inverse iteration (Golub & Van Loan, sec. 8.2.2; Peters & Wilkinson's
// treatment of clusters as in LAPACK's xSTEIN): solve (T - theta I) y = x
// with Gaussian elimination with partial pivoting on the band (GVL sec.
// 4.3.5: the upper bandwidth grows from b to 2b), normalize, repeat. With
// theta accurate to eps ||T||, two solves from a random start give the
// vector to about eps ||T|| / gap. Vectors of close values are
// orthogonalized against each other after every solve.
#include "eigensolver/band_inverse_iteration.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gab/sparse/splitmix64.h"

namespace gab {
namespace eigen_detail {

namespace {

// T - theta I as a general band matrix (kl = b below, up to 2b above after
// pivoting), entry (i, j) at lu[(2b + i - j) + j * (3b + 1)], and its LU
// factors with row interchanges piv.
struct BandLu {
  int32_t m = 0, b = 0, ld = 0;
  std::vector<double> lu;
  std::vector<int32_t> piv;
  double& at(int32_t i, int32_t j) { return lu[(2 * b + i - j) + static_cast<int64_t>(j) * ld]; }

  void factor(const SymmetricBand& t, double theta, double tiny) {
    m = t.m;
    b = t.b;
    ld = 3 * b + 1;
    lu.assign(static_cast<size_t>(ld) * m, 0.0);
    piv.resize(m);
    for (int32_t j = 0; j < m; ++j) {
      for (int32_t r = 0; r <= b && j + r < m; ++r) {
        const double v = t.at(j + r, j) - (r == 0 ? theta : 0.0);
        at(j + r, j) = v;
        if (r > 0) at(j, j + r) = v;
      }
    }
    for (int32_t j = 0; j < m; ++j) {
      const int32_t last = std::min(m - 1, j + b);
      int32_t p = j;
      for (int32_t i = j + 1; i <= last; ++i) {
        if (std::abs(at(i, j)) > std::abs(at(p, j))) p = i;
      }
      piv[j] = p;
      const int32_t right = std::min(m - 1, j + 2 * b);
      if (p != j) {
        for (int32_t c = j; c <= right; ++c) std::swap(at(j, c), at(p, c));
      }
      // An exactly singular pivot (theta an exact eigenvalue) is nudged:
      // inverse iteration only needs the direction.
      if (std::abs(at(j, j)) < tiny) at(j, j) = at(j, j) < 0.0 ? -tiny : tiny;
      const double inv = 1.0 / at(j, j);
      for (int32_t i = j + 1; i <= last; ++i) {
        const double l = at(i, j) * inv;
        at(i, j) = l;
        if (l == 0.0) continue;
        for (int32_t c = j + 1; c <= right; ++c) at(i, c) -= l * at(j, c);
      }
    }
  }

  void solve(double* y) {
    for (int32_t j = 0; j < m; ++j) {
      std::swap(y[j], y[piv[j]]);
      const double yj = y[j];
      for (int32_t i = j + 1; i <= std::min(m - 1, j + b); ++i) y[i] -= at(i, j) * yj;
    }
    for (int32_t j = m - 1; j >= 0; --j) {
      y[j] /= at(j, j);
      const double yj = y[j];
      for (int32_t i = std::max(0, j - 2 * b); i < j; ++i) y[i] -= at(i, j) * yj;
    }
  }
};

double normalize(int32_t m, double* x) {
  double s = 0.0;
  for (int32_t i = 0; i < m; ++i) s += x[i] * x[i];
  s = std::sqrt(s);
  if (s > 0.0) {
    for (int32_t i = 0; i < m; ++i) x[i] /= s;
  }
  return s;
}

// x -= (y . x) y for each earlier vector y of the cluster, twice (one pass
// can leave the cancellation's rounding).
void orthogonalize(int32_t m, const double* first, int32_t count, double* x) {
  for (int pass = 0; pass < 2; ++pass) {
    for (int32_t t = 0; t < count; ++t) {
      const double* y = first + static_cast<int64_t>(t) * m;
      double dot = 0.0;
      for (int32_t i = 0; i < m; ++i) dot += y[i] * x[i];
      for (int32_t i = 0; i < m; ++i) x[i] -= dot * y[i];
    }
  }
}

}  // namespace

void band_eigenvectors(const SymmetricBand& band, const double* values, int32_t count,
                       double cluster_gap, uint64_t seed, double* vectors) {
  const int32_t m = band.m;
  double norm = 0.0;  // max |entry|: the scale of a negligible pivot
  for (double v : band.data) norm = std::max(norm, std::abs(v));
  const double tiny = std::max(norm, std::numeric_limits<double>::min()) *
                      std::numeric_limits<double>::epsilon();
  SplitMix64 rng(seed);
  BandLu lu;
  // The vectors already made whose values lie within cluster_gap of this
  // one: [near, t). A window, not a chain of close neighbours, so a long
  // run of close values costs each vector its few neighbours only; vectors
  // farther apart are orthogonal to about eps ||T|| / cluster_gap already.
  int32_t near = 0;
  for (int32_t t = 0; t < count; ++t) {
    while (std::abs(values[near] - values[t]) > cluster_gap) ++near;
    const int32_t cluster_first = near;
    double* x = vectors + static_cast<int64_t>(t) * m;
    for (int32_t i = 0; i < m; ++i) x[i] = rng.uniform() - 0.5;
    lu.factor(band, values[t], tiny);
    const double* cluster = vectors + static_cast<int64_t>(cluster_first) * m;
    for (int iteration = 0; iteration < 3; ++iteration) {
      normalize(m, x);
      lu.solve(x);
      orthogonalize(m, cluster, t - cluster_first, x);
      if (normalize(m, x) == 0.0) {
        // The start lay in the cluster's span: another random start.
        for (int32_t i = 0; i < m; ++i) x[i] = rng.uniform() - 0.5;
      }
    }
  }
}

}  // namespace eigen_detail
}  // namespace gab
