// Textbook Cholesky variants used as oracles (Golub & Van Loan, alg. 4.2.1;
// Davis, "Direct Methods", sec. 4.8 for the left-looking sparse form).
#include "common/oracles.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace gab {

namespace {

Status not_positive(int32_t j) {
  return Status::Error(StatusCode::kNotPositiveDefinite,
                       "matrix is not positive definite: pivot " + std::to_string(j) +
                           " is not positive");
}

}  // namespace

Status dense_cholesky(const CscMatrix& lower, std::vector<double>* l) {
  const int32_t n = lower.ncols;
  std::vector<double>& a = *l;
  a.assign(static_cast<size_t>(n) * n, 0.0);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      a[lower.rowind[p] + static_cast<size_t>(j) * n] += lower.values[p];
    }
  }
  for (int32_t j = 0; j < n; ++j) {
    double d = a[j + static_cast<size_t>(j) * n];
    for (int32_t k = 0; k < j; ++k) d -= a[j + static_cast<size_t>(k) * n] * a[j + static_cast<size_t>(k) * n];
    if (!(d > 0.0)) return not_positive(j);
    const double djj = std::sqrt(d);
    a[j + static_cast<size_t>(j) * n] = djj;
    for (int32_t i = j + 1; i < n; ++i) {
      double v = a[i + static_cast<size_t>(j) * n];
      for (int32_t k = 0; k < j; ++k) v -= a[i + static_cast<size_t>(k) * n] * a[j + static_cast<size_t>(k) * n];
      a[i + static_cast<size_t>(j) * n] = v / djj;
    }
  }
  return Status::Ok();
}

Status simplicial_cholesky(const CscMatrix& lower, CscMatrix* out) {
  const int32_t n = lower.ncols;
  // Columns of L as they are finished, plus, for each row i, the list of
  // finished columns k with L(i, k) != 0 (the columns that update column i).
  std::vector<std::vector<int32_t>> col_rows(n), row_cols(n);
  std::vector<std::vector<double>> col_vals(n);
  std::vector<double> x(n, 0.0);
  std::vector<int32_t> mark(n, -1), pattern;
  for (int32_t j = 0; j < n; ++j) {
    pattern.clear();
    auto touch = [&](int32_t i) {
      if (mark[i] != j) {
        mark[i] = j;
        pattern.push_back(i);
      }
    };
    touch(j);
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      touch(lower.rowind[p]);
      x[lower.rowind[p]] += lower.values[p];
    }
    for (int32_t k : row_cols[j]) {
      // L(j, k) is in column k; subtract L(i, k) L(j, k) for every i >= j.
      double ljk = 0.0;
      for (size_t q = 0; q < col_rows[k].size(); ++q) {
        if (col_rows[k][q] == j) ljk = col_vals[k][q];
      }
      for (size_t q = 0; q < col_rows[k].size(); ++q) {
        const int32_t i = col_rows[k][q];
        if (i < j) continue;
        touch(i);
        x[i] -= col_vals[k][q] * ljk;
      }
    }
    std::sort(pattern.begin(), pattern.end());
    const double d = x[j];
    if (!(d > 0.0)) return not_positive(j);
    const double djj = std::sqrt(d);
    for (int32_t i : pattern) {
      col_rows[j].push_back(i);
      col_vals[j].push_back(i == j ? djj : x[i] / djj);
      if (i != j) row_cols[i].push_back(j);
      x[i] = 0.0;
    }
  }
  CscMatrix l;
  l.nrows = l.ncols = n;
  l.colptr.assign(n + 1, 0);
  for (int32_t j = 0; j < n; ++j) {
    l.rowind.insert(l.rowind.end(), col_rows[j].begin(), col_rows[j].end());
    l.values.insert(l.values.end(), col_vals[j].begin(), col_vals[j].end());
    l.colptr[j + 1] = static_cast<int32_t>(l.rowind.size());
  }
  *out = std::move(l);
  return Status::Ok();
}

}  // namespace gab
