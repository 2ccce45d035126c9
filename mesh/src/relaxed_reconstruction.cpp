#include "gab/mesh/relaxed_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "anchor_checks.h"
#include "gab/mesh/normal_matrix.h"

namespace gab {

Status RelaxedReconstruction::check_new(const std::vector<int32_t>& anchors,
                                        const std::vector<double>& coefficients) {
  return check_new_anchors<char>(anchors, coefficients, &anchored_, 0, 2);
}

void RelaxedReconstruction::add_to_matrix(const std::vector<int32_t>& anchors) {
  for (int32_t a : anchors) values_[diagonal_[a]] += weight_ * weight_;
}

void RelaxedReconstruction::record(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients) {
  for (size_t i = 0; i < anchors.size(); ++i) {
    anchored_[anchors[i]] = 1;
    anchors_.push_back(anchors[i]);
    coefficients_.insert(coefficients_.end(), &coefficients[3 * i], &coefficients[3 * i] + 3);
  }
}

Status RelaxedReconstruction::init(const EdgeGraph& graph, double weight,
                                   const std::vector<int32_t>& anchors,
                                   const std::vector<double>& coefficients) {
  if (!(weight > 0.0) || !std::isfinite(weight)) {
    return Status::Error(StatusCode::kInvalidArgument, "anchor weight must be positive and finite");
  }
  n_ = graph.num_vertices();
  weight_ = weight;
  anchors_.clear();
  coefficients_.clear();
  anchored_.assign(n_, 0);
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  // Every component needs an anchor, or L^T L + w^2 E^T E is singular there.
  GAB_RETURN_IF_ERROR(check_components_anchored(graph, anchors));
  CscMatrix matrix;
  GAB_RETURN_IF_ERROR(assemble_normal_matrix(graph, anchors, weight, &matrix, threads_));
  AnalyzeOptions options;
  options.ordering = ordering_;
  options.given_perm = given_perm_;
  options.threads = threads_;
  options.max_factor_entries = max_factor_entries_;
  GAB_RETURN_IF_ERROR(chol_.analyze(matrix, options));
  // The diagonal entry leads each column of the lower triangle
  // (assemble_normal_matrix keeps it). The pattern goes before the factor
  // is formed: the factorization's peak is the whole job's.
  diagonal_.assign(matrix.colptr.begin(), matrix.colptr.begin() + n_);
  values_ = std::move(matrix.values);
  matrix = CscMatrix();
  GAB_RETURN_IF_ERROR(chol_.factorize_values(values_.data(), static_cast<int64_t>(values_.size())));
  record(anchors, coefficients);
  return Status::Ok();
}

Status RelaxedReconstruction::add_anchors(const std::vector<int32_t>& anchors,
                                          const std::vector<double>& coefficients) {
  if (!chol_.factorized()) return Status::Error(StatusCode::kInvalidArgument, "add_anchors before init");
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  GAB_RETURN_IF_ERROR(chol_.add_anchors(anchors.data(), static_cast<int32_t>(anchors.size()), weight_));
  add_to_matrix(anchors);
  record(anchors, coefficients);
  return Status::Ok();
}

Status RelaxedReconstruction::add_anchors_refactoring(const std::vector<int32_t>& anchors,
                                                      const std::vector<double>& coefficients) {
  if (!chol_.factorized()) return Status::Error(StatusCode::kInvalidArgument, "add_anchors before init");
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  add_to_matrix(anchors);
  const Status s = chol_.factorize_values(values_.data(), static_cast<int64_t>(values_.size()));
  if (!s.ok()) {
    // Leave the object as it was: the matrix without these anchors (the
    // factor is lost; a later refactorization restores it).
    for (int32_t a : anchors) values_[diagonal_[a]] -= weight_ * weight_;
    return s;
  }
  record(anchors, coefficients);
  return Status::Ok();
}

double RelaxedReconstruction::update_cost_ratio(const std::vector<int32_t>& anchors) const {
  const SymbolicFactor& f = chol_.symbolic();
  // Calibrated on this engine (AVX-512) by timing batches of 8, 32 and 128
  // anchors against a refactorization: the true update/refactor time ratio
  // over this entry count times 6 flops was ~2.3 on igea, 1.2-1.4 on feline
  // and 1.0-1.2 on camel-head; 12 flops per entry errs towards refactoring,
  // which is never badly wrong.
  constexpr double kFlopsPerPathEntry = 12.0;
  double entries = 0.0;
  for (int32_t j : anchors) {
    if (j < 0 || j >= n_) continue;
    for (int32_t c = f.inverse_perm[j]; c != -1;) {
      // A chain of panels counts as the supernode it was cut from, as the
      // calibration below measured it.
      const int32_t first = f.chain_first(f.supernode_of[c]);
      const int32_t last = f.first_col[f.chain_last(f.supernode_of[c]) + 1] - 1;
      entries += static_cast<double>(last - c + 1) * f.rows(first);
      c = f.etree.parent[last];
    }
  }
  return entries * kFlopsPerPathEntry / (f.flops > 0 ? f.flops : 1.0);
}

Status RelaxedReconstruction::add_anchors_cheapest(const std::vector<int32_t>& anchors,
                                                   const std::vector<double>& coefficients, bool* refactored) {
  if (!chol_.factorized()) return Status::Error(StatusCode::kInvalidArgument, "add_anchors before init");
  const bool refactor = update_cost_ratio(anchors) > 1.0;
  if (refactored != nullptr) *refactored = refactor;
  return refactor ? add_anchors_refactoring(anchors, coefficients) : add_anchors(anchors, coefficients);
}

Status RelaxedReconstruction::set_coefficients(int32_t first, const std::vector<double>& coefficients) {
  if (first < 0 || first > num_anchors() || coefficients.size() != 3 * static_cast<size_t>(num_anchors() - first)) {
    return Status::Error(StatusCode::kInvalidArgument, "set_coefficients: need 3 coefficients per anchor from " +
                                                           std::to_string(first) + " on");
  }
  GAB_RETURN_IF_ERROR(check_anchor_coefficients(coefficients.size() / 3, coefficients));  // finite
  std::copy(coefficients.begin(), coefficients.end(), coefficients_.begin() + 3 * static_cast<size_t>(first));
  return Status::Ok();
}

Status RelaxedReconstruction::solve_system(double* b) {
  if (!chol_.factorized()) return Status::Error(StatusCode::kInvalidArgument, "solve before init");
  return chol_.solve(b, 3, n_);
}

Status RelaxedReconstruction::reconstruct(std::vector<double>* positions) {
  if (!chol_.factorized()) return Status::Error(StatusCode::kInvalidArgument, "reconstruct before init");
  // The right-hand sides w^2 E^T c (n x 3 column-major), from the coefficients.
  const double w2 = weight_ * weight_;
  std::vector<double> x(static_cast<size_t>(n_) * 3, 0.0);
  for (size_t i = 0; i < anchors_.size(); ++i) {
    for (int c = 0; c < 3; ++c) x[anchors_[i] + static_cast<size_t>(c) * n_] = w2 * coefficients_[3 * i + c];
  }
  GAB_RETURN_IF_ERROR(chol_.solve(x.data(), 3, n_));
  positions->resize(static_cast<size_t>(n_) * 3);
  for (int32_t v = 0; v < n_; ++v) {
    for (int c = 0; c < 3; ++c) (*positions)[3 * static_cast<size_t>(v) + c] = x[v + static_cast<size_t>(c) * n_];
  }
  return Status::Ok();
}

}  // namespace gab
