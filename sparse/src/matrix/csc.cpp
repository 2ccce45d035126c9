// CSC building blocks: triplet assembly, transpose, symmetric permutation,
// mat-vec. Each is the two-pass counting-sort construction (Davis, "Direct
// Methods for Sparse Linear Systems", ch. 2).
#include "gab/sparse/csc.h"

#include <algorithm>
#include <limits>
#include <string>

namespace gab {

namespace {

// Exclusive prefix sum of counts into colptr (size n+1); counts are left as
// the column starts so they can serve as insertion cursors.
void cumulative_sum(std::vector<int32_t>* colptr, std::vector<int32_t>* counts) {
  int32_t total = 0;
  const size_t n = counts->size();
  for (size_t j = 0; j < n; ++j) {
    (*colptr)[j] = total;
    total += (*counts)[j];
    (*counts)[j] = (*colptr)[j];
  }
  (*colptr)[n] = total;
}

}  // namespace

Status csc_from_triplets(int32_t nrows, int32_t ncols, const std::vector<Triplet>& triplets,
                         CscMatrix* out) {
  if (nrows < 0 || ncols < 0) {
    return Status::Error(StatusCode::kInvalidArgument, "negative matrix dimension");
  }
  if (triplets.size() > static_cast<size_t>(std::numeric_limits<int32_t>::max())) {
    return Status::Error(StatusCode::kOverflow, "more than 2^31-1 entries");
  }
  for (size_t t = 0; t < triplets.size(); ++t) {
    const Triplet& e = triplets[t];
    if (e.row < 0 || e.row >= nrows || e.col < 0 || e.col >= ncols) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "entry " + std::to_string(t) + " at (" + std::to_string(e.row) + ", " +
                               std::to_string(e.col) + ") is outside a " + std::to_string(nrows) +
                               " x " + std::to_string(ncols) + " matrix");
    }
  }
  // Bucket by row first (transpose of the target), then by column: the
  // second pass visits rows in increasing order, so columns come out sorted.
  std::vector<int32_t> rowptr(nrows + 1), cursor(nrows, 0);
  for (const Triplet& e : triplets) ++cursor[e.row];
  cumulative_sum(&rowptr, &cursor);
  std::vector<int32_t> by_row_col(triplets.size());
  std::vector<double> by_row_val(triplets.size());
  for (const Triplet& e : triplets) {
    const int32_t p = cursor[e.row]++;
    by_row_col[p] = e.col;
    by_row_val[p] = e.value;
  }
  std::vector<int32_t> colcount(ncols, 0);
  for (int32_t c : by_row_col) ++colcount[c];
  CscMatrix a;
  a.nrows = nrows;
  a.ncols = ncols;
  a.colptr.assign(ncols + 1, 0);
  cumulative_sum(&a.colptr, &colcount);
  std::vector<int32_t> rows(triplets.size());
  std::vector<double> vals(triplets.size());
  for (int32_t i = 0; i < nrows; ++i) {
    for (int32_t p = rowptr[i]; p < rowptr[i + 1]; ++p) {
      const int32_t q = colcount[by_row_col[p]]++;
      rows[q] = i;
      vals[q] = by_row_val[p];
    }
  }
  // Sum duplicates in place (they are adjacent within a column now).
  int32_t write = 0;
  for (int32_t j = 0; j < ncols; ++j) {
    const int32_t begin = a.colptr[j], end = a.colptr[j + 1];
    a.colptr[j] = write;
    for (int32_t p = begin; p < end; ++p) {
      if (write > a.colptr[j] && rows[write - 1] == rows[p]) {
        vals[write - 1] += vals[p];
      } else {
        rows[write] = rows[p];
        vals[write] = vals[p];
        ++write;
      }
    }
  }
  a.colptr[ncols] = write;
  rows.resize(write);
  vals.resize(write);
  a.rowind = std::move(rows);
  a.values = std::move(vals);
  *out = std::move(a);
  return Status::Ok();
}

CscMatrix transpose(const CscMatrix& a) {
  CscMatrix t;
  t.nrows = a.ncols;
  t.ncols = a.nrows;
  t.colptr.assign(t.ncols + 1, 0);
  std::vector<int32_t> cursor(t.ncols, 0);
  const int64_t nnz = a.nnz();
  for (int64_t p = 0; p < nnz; ++p) ++cursor[a.rowind[p]];
  cumulative_sum(&t.colptr, &cursor);
  t.rowind.resize(nnz);
  const bool values = !a.values.empty();
  if (values) t.values.resize(nnz);
  for (int32_t j = 0; j < a.ncols; ++j) {
    for (int32_t p = a.colptr[j]; p < a.colptr[j + 1]; ++p) {
      const int32_t q = cursor[a.rowind[p]]++;
      t.rowind[q] = j;
      if (values) t.values[q] = a.values[p];
    }
  }
  return t;
}

Status check_csc(const CscMatrix& a) {
  if (a.nrows < 0 || a.ncols < 0) {
    return Status::Error(StatusCode::kInvalidArgument, "negative matrix dimension");
  }
  if (a.colptr.size() != static_cast<size_t>(a.ncols) + 1 || a.colptr[0] != 0) {
    return Status::Error(StatusCode::kInvalidArgument, "colptr must have ncols+1 entries, first 0");
  }
  for (int32_t j = 0; j < a.ncols; ++j) {
    if (a.colptr[j + 1] < a.colptr[j]) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "colptr decreases at column " + std::to_string(j));
    }
  }
  if (a.rowind.size() != static_cast<size_t>(a.nnz()) ||
      (!a.values.empty() && a.values.size() != a.rowind.size())) {
    return Status::Error(StatusCode::kInvalidArgument, "rowind/values size differs from nnz");
  }
  for (int32_t j = 0; j < a.ncols; ++j) {
    for (int32_t p = a.colptr[j]; p < a.colptr[j + 1]; ++p) {
      const int32_t i = a.rowind[p];
      if (i < 0 || i >= a.nrows || (p > a.colptr[j] && a.rowind[p - 1] >= i)) {
        return Status::Error(StatusCode::kInvalidArgument,
                             "column " + std::to_string(j) +
                                 " has an out-of-range or unsorted row index");
      }
    }
  }
  return Status::Ok();
}

CscMatrix lower_triangle(const CscMatrix& a) {
  CscMatrix l;
  l.nrows = a.nrows;
  l.ncols = a.ncols;
  l.colptr.assign(a.ncols + 1, 0);
  const bool values = !a.values.empty();
  for (int32_t j = 0; j < a.ncols; ++j) {
    for (int32_t p = a.colptr[j]; p < a.colptr[j + 1]; ++p) {
      if (a.rowind[p] < j) continue;
      l.rowind.push_back(a.rowind[p]);
      if (values) l.values.push_back(a.values[p]);
    }
    l.colptr[j + 1] = static_cast<int32_t>(l.rowind.size());
  }
  return l;
}

CscMatrix symmetric_graph(const CscMatrix& lower) {
  const int32_t n = lower.ncols;
  CscMatrix g;
  g.nrows = g.ncols = n;
  g.colptr.assign(n + 1, 0);
  std::vector<int32_t> cursor(n, 0);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t i = lower.rowind[p];
      if (i == j) continue;
      ++cursor[i];
      ++cursor[j];
    }
  }
  cumulative_sum(&g.colptr, &cursor);
  g.rowind.resize(g.colptr[n]);
  // First every column receives its upper entries (rows j < i, in increasing
  // j), then its lower entries (sorted in the input): columns come out sorted.
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t i = lower.rowind[p];
      if (i == j) continue;
      g.rowind[cursor[i]++] = j;
    }
  }
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t i = lower.rowind[p];
      if (i == j) continue;
      g.rowind[cursor[j]++] = i;
    }
  }
  return g;
}

CscMatrix permute_symmetric_lower(const CscMatrix& lower, const std::vector<int32_t>& perm) {
  const int32_t n = lower.ncols;
  const std::vector<int32_t> inv = invert_permutation(perm);
  const bool values = !lower.values.empty();
  // Entry (i, j) of A lands at (max, min) of (inv[i], inv[j]) in C. Count,
  // scatter, then sort each column (scatter order is not row order).
  CscMatrix c;
  c.nrows = c.ncols = n;
  c.colptr.assign(n + 1, 0);
  std::vector<int32_t> cursor(n, 0);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      ++cursor[std::min(inv[lower.rowind[p]], inv[j])];
    }
  }
  cumulative_sum(&c.colptr, &cursor);
  c.rowind.resize(lower.nnz());
  if (values) c.values.resize(lower.nnz());
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t a = inv[lower.rowind[p]], b = inv[j];
      const int32_t q = cursor[std::min(a, b)]++;
      c.rowind[q] = std::max(a, b);
      if (values) c.values[q] = lower.values[p];
    }
  }
  // Sort rows within each column, carrying values (insertion sort: columns
  // of mesh matrices are short).
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = c.colptr[j] + 1; p < c.colptr[j + 1]; ++p) {
      const int32_t r = c.rowind[p];
      const double v = values ? c.values[p] : 0.0;
      int32_t q = p - 1;
      while (q >= c.colptr[j] && c.rowind[q] > r) {
        c.rowind[q + 1] = c.rowind[q];
        if (values) c.values[q + 1] = c.values[q];
        --q;
      }
      c.rowind[q + 1] = r;
      if (values) c.values[q + 1] = v;
    }
  }
  return c;
}

void symmetric_lower_matvec(const CscMatrix& lower, const double* x, double* y) {
  const int32_t n = lower.ncols;
  for (int32_t i = 0; i < n; ++i) y[i] = 0.0;
  for (int32_t j = 0; j < n; ++j) {
    double yj = 0.0;
    const double xj = x[j];
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t i = lower.rowind[p];
      const double v = lower.values[p];
      if (i == j) {
        yj += v * xj;
      } else {
        y[i] += v * xj;
        yj += v * x[i];
      }
    }
    y[j] += yj;
  }
}

std::vector<int32_t> invert_permutation(const std::vector<int32_t>& perm) {
  std::vector<int32_t> inv(perm.size());
  for (size_t k = 0; k < perm.size(); ++k) inv[perm[k]] = static_cast<int32_t>(k);
  return inv;
}

bool is_permutation(const std::vector<int32_t>& perm, int32_t n) {
  if (perm.size() != static_cast<size_t>(n)) return false;
  std::vector<char> seen(n, 0);
  for (int32_t v : perm) {
    if (v < 0 || v >= n || seen[v]) return false;
    seen[v] = 1;
  }
  return true;
}

}  // namespace gab
