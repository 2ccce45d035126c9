#include "gab/mesh/iterative_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "anchor_checks.h"

namespace gab {

namespace {

// Sums of three columns over vertices [0, n): per block of kBlock vertices
// in vertex order, then the blocks in order (the order IterativeReconstruction
// promises whatever the thread count). `term(v, s)` adds vertex v's terms to s.
template <typename Term>
void blocked_sum(int32_t n, Term term, double total[3]) {
  total[0] = total[1] = total[2] = 0.0;
  for (int32_t begin = 0; begin < n; begin += IterativeReconstruction::kBlock) {
    const int32_t end = std::min(n, begin + IterativeReconstruction::kBlock);
    double block[3] = {0.0, 0.0, 0.0};
    for (int32_t v = begin; v < end; ++v) term(v, block);
    for (int c = 0; c < 3; ++c) total[c] += block[c];
  }
}

}  // namespace

Status IterativeReconstruction::check_new(const std::vector<int32_t>& anchors,
                                          const std::vector<double>& coefficients) const {
  GAB_RETURN_IF_ERROR(check_anchor_coefficients(anchors.size(), coefficients));
  std::vector<int32_t> sorted = anchors;
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 0; i < sorted.size(); ++i) {
    const int32_t a = sorted[i];
    if (a < 0 || a >= n_) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "anchor " + std::to_string(a) + " is not a vertex (n = " + std::to_string(n_) + ")");
    }
    if (anchor_of_[a] >= 0) {
      return Status::Error(StatusCode::kInvalidArgument, "vertex " + std::to_string(a) + " is already an anchor");
    }
    if (i > 0 && sorted[i - 1] == a) {
      return Status::Error(StatusCode::kInvalidArgument, "anchor " + std::to_string(a) + " given twice");
    }
  }
  return Status::Ok();
}

void IterativeReconstruction::record(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients) {
  for (size_t i = 0; i < anchors.size(); ++i) {
    anchor_of_[anchors[i]] = static_cast<int32_t>(anchors_.size());
    anchors_.push_back(anchors[i]);
    coefficients_.insert(coefficients_.end(), &coefficients[3 * i], &coefficients[3 * i] + 3);
  }
}

Status IterativeReconstruction::init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
                                     const std::vector<double>& coefficients) {
  if (!(weight > 0.0) || !std::isfinite(weight)) {
    return Status::Error(StatusCode::kInvalidArgument, "anchor weight must be positive and finite");
  }
  graph_ = &graph;
  n_ = graph.num_vertices();
  weight_ = weight;
  anchors_.clear();
  coefficients_.clear();
  shape_.clear();
  anchor_of_.assign(n_, -1);
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  int32_t ncomp = 0;
  const std::vector<int32_t> comp = connected_components(graph, &ncomp);
  std::vector<char> covered(ncomp, 0);
  for (int32_t a : anchors) covered[comp[a]] = 1;
  for (int32_t v = 0; v < n_; ++v) {
    if (!covered[comp[v]]) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "the connected component of vertex " + std::to_string(v) +
                               " has no anchor (every component needs one)");
    }
  }
  record(anchors, coefficients);
  return Status::Ok();
}

Status IterativeReconstruction::add_anchors(const std::vector<int32_t>& anchors,
                                            const std::vector<double>& coefficients) {
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  record(anchors, coefficients);
  return Status::Ok();
}

Status IterativeReconstruction::set_coefficients(int32_t first, const std::vector<double>& coefficients) {
  if (first < 0 || coefficients.size() % 3 != 0 ||
      static_cast<size_t>(first) + coefficients.size() / 3 > anchors_.size()) {
    return Status::Error(StatusCode::kInvalidArgument, "coefficients past the last anchor");
  }
  GAB_RETURN_IF_ERROR(check_anchor_coefficients(coefficients.size() / 3, coefficients));
  std::copy(coefficients.begin(), coefficients.end(), coefficients_.begin() + 3 * static_cast<size_t>(first));
  return Status::Ok();
}

void IterativeReconstruction::nearest_anchor_start() {
  const EdgeGraph& g = *graph_;
  std::vector<int32_t> source(n_, -1), frontier = anchors_, next;
  std::sort(frontier.begin(), frontier.end());
  for (int32_t a : frontier) source[a] = anchor_of_[a];
  while (!frontier.empty()) {
    next.clear();
    for (int32_t u : frontier) {
      for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
        const int32_t w = g.neighbors[p];
        if (source[w] >= 0) continue;
        source[w] = source[u];
        next.push_back(w);
      }
    }
    frontier.swap(next);
  }
  shape_.assign(3 * static_cast<size_t>(n_), 0.0);
  for (int32_t v = 0; v < n_; ++v) {
    for (int c = 0; c < 3; ++c) shape_[3 * static_cast<size_t>(v) + c] = coefficients_[3 * static_cast<size_t>(source[v]) + c];
  }
}

void IterativeReconstruction::laplacian(const std::vector<double>& x, std::vector<double>* y) const {
  const int32_t* offsets = graph_->offsets.data();
  const int32_t* neighbors = graph_->neighbors.data();
  const double* in = x.data();
  double* out = y->data();
  for (int32_t v = 0; v < n_; ++v) {
    const double d = offsets[v + 1] - offsets[v];
    double s0 = d * in[3 * v], s1 = d * in[3 * v + 1], s2 = d * in[3 * v + 2];
    for (int32_t p = offsets[v]; p < offsets[v + 1]; ++p) {
      const double* u = in + 3 * static_cast<size_t>(neighbors[p]);
      s0 -= u[0];
      s1 -= u[1];
      s2 -= u[2];
    }
    out[3 * v] = s0;
    out[3 * v + 1] = s1;
    out[3 * v + 2] = s2;
  }
}

Status IterativeReconstruction::solve(int32_t steps, std::vector<double>* positions) {
  if (graph_ == nullptr) return Status::Error(StatusCode::kInvalidArgument, "solve before init");
  if (steps < 0) return Status::Error(StatusCode::kInvalidArgument, "negative step count");
  if (shape_.empty()) nearest_anchor_start();
  const size_t m = 3 * static_cast<size_t>(n_);
  const double w2 = weight_ * weight_;
  // 1 / diag(L^T L + w^2 S): (L^T L)_vv = d^2 + d for L = D - A.
  std::vector<double> inv_diag(n_);
  for (int32_t v = 0; v < n_; ++v) {
    const double d = graph_->degree(v);
    inv_diag[v] = 1.0 / (d * d + d + (anchor_of_[v] >= 0 ? w2 : 0.0));
  }
  std::vector<double> r(m), p(m), q(m), t(m);
  double* x = shape_.data();
  // q = (L^T L + w^2 S) x; r = w^2 S c - q.
  auto product = [&](const std::vector<double>& in, std::vector<double>* out) {
    laplacian(in, &t);
    laplacian(t, out);
    for (size_t i = 0; i < anchors_.size(); ++i) {
      const size_t a = 3 * static_cast<size_t>(anchors_[i]);
      for (int c = 0; c < 3; ++c) (*out)[a + c] += w2 * in[a + c];
    }
  };
  product(shape_, &q);
  for (size_t k = 0; k < m; ++k) r[k] = -q[k];
  for (size_t i = 0; i < anchors_.size(); ++i) {
    const size_t a = 3 * static_cast<size_t>(anchors_[i]);
    for (int c = 0; c < 3; ++c) r[a + c] += w2 * coefficients_[3 * i + c];
  }
  double rz[3];
  blocked_sum(n_, [&](int32_t v, double s[3]) {
    for (int c = 0; c < 3; ++c) {
      const size_t k = 3 * static_cast<size_t>(v) + c;
      p[k] = inv_diag[v] * r[k];
      s[c] += r[k] * p[k];
    }
  }, rz);
  for (int32_t step = 0; step < steps; ++step) {
    product(p, &q);
    double pq[3];
    blocked_sum(n_, [&](int32_t v, double s[3]) {
      for (int c = 0; c < 3; ++c) s[c] += p[3 * static_cast<size_t>(v) + c] * q[3 * static_cast<size_t>(v) + c];
    }, pq);
    // A column already solved exactly (rz or pq zero) stays as it is.
    double alpha[3];
    for (int c = 0; c < 3; ++c) alpha[c] = (pq[c] > 0.0 && rz[c] > 0.0) ? rz[c] / pq[c] : 0.0;
    double rz_next[3];
    blocked_sum(n_, [&](int32_t v, double s[3]) {
      for (int c = 0; c < 3; ++c) {
        const size_t k = 3 * static_cast<size_t>(v) + c;
        x[k] += alpha[c] * p[k];
        r[k] -= alpha[c] * q[k];
        s[c] += inv_diag[v] * r[k] * r[k];
      }
    }, rz_next);
    double beta[3];
    for (int c = 0; c < 3; ++c) {
      beta[c] = rz[c] > 0.0 ? rz_next[c] / rz[c] : 0.0;
      rz[c] = rz_next[c];
    }
    for (int32_t v = 0; v < n_; ++v) {
      for (int c = 0; c < 3; ++c) {
        const size_t k = 3 * static_cast<size_t>(v) + c;
        p[k] = inv_diag[v] * r[k] + beta[c] * p[k];
      }
    }
  }
  *positions = shape_;
  return Status::Ok();
}

}  // namespace gab
