// CGNR (conjugate gradients on the normal equations; Hestenes and Stiefel
// 1952, Saad "Iterative Methods for Sparse Linear Systems" sec. 8.3) for
// min ||B c - p||, one independent iteration per coordinate run in lockstep.
#include "gab/mesh/optimal_coefficients.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace gab {

namespace {

// y = B c = M^-1 (w^2 E^T c): n x 3 column-major.
Status apply_basis(RelaxedReconstruction* rec, const std::vector<int32_t>& anchors, const std::vector<double>& c,
                   std::vector<double>* y) {
  const size_t n = static_cast<size_t>(rec->num_vertices());
  const double w2 = rec->weight() * rec->weight();
  y->assign(3 * n, 0.0);
  for (size_t i = 0; i < anchors.size(); ++i) {
    for (int k = 0; k < 3; ++k) (*y)[anchors[i] + k * n] = w2 * c[3 * i + k];
  }
  return rec->solve_system(y->data());
}

// z = B^T r = w^2 E M^-1 r (M symmetric): 3 per anchor. Overwrites r.
Status apply_basis_transposed(RelaxedReconstruction* rec, const std::vector<int32_t>& anchors, std::vector<double>* r,
                              std::vector<double>* z) {
  const size_t n = static_cast<size_t>(rec->num_vertices());
  const double w2 = rec->weight() * rec->weight();
  GAB_RETURN_IF_ERROR(rec->solve_system(r->data()));
  z->resize(3 * anchors.size());
  for (size_t i = 0; i < anchors.size(); ++i) {
    for (int k = 0; k < 3; ++k) (*z)[3 * i + k] = w2 * (*r)[anchors[i] + k * n];
  }
  return Status::Ok();
}

// Sum over anchors of a[3i + j] b[3i + j]: one coordinate's dot product.
double coordinate_dot(const std::vector<double>& a, const std::vector<double>& b, int j, size_t anchors) {
  double s = 0;
  for (size_t i = 0; i < anchors; ++i) s += a[3 * i + j] * b[3 * i + j];
  return s;
}

}  // namespace

Status optimal_coefficients(RelaxedReconstruction* rec, const Mesh& mesh, int32_t max_iterations, double tolerance,
                            std::vector<double>* coefficients, OptimalCoefficientsReport* report,
                            int32_t first_free) {
  const std::vector<int32_t>& anchors = rec->anchors();
  const size_t n = static_cast<size_t>(rec->num_vertices());
  const size_t k = anchors.size();
  if (mesh.num_vertices() != rec->num_vertices()) {
    return Status::Error(StatusCode::kInvalidArgument, "mesh and reconstruction have different vertex counts");
  }
  if (coefficients->size() != 3 * k) {
    return Status::Error(StatusCode::kInvalidArgument, "need 3 starting coefficients per anchor: got " +
                                                           std::to_string(coefficients->size()) + " for " +
                                                           std::to_string(k) + " anchors");
  }
  if (first_free < 0 || static_cast<size_t>(first_free) > k) {
    return Status::Error(StatusCode::kInvalidArgument, "first free anchor out of range");
  }
  const size_t fixed = static_cast<size_t>(first_free);
  // The gradient restricted to the free coefficients: CG then never moves
  // the fixed ones.
  auto restrict = [fixed](std::vector<double>* g) { std::fill(g->begin(), g->begin() + 3 * fixed, 0.0); };
  *report = OptimalCoefficientsReport();
  std::vector<double>& c = *coefficients;
  // r = p - B c (n x 3 column-major), z = B^T r, d = z.
  std::vector<double> r, z, d, q, scratch;
  GAB_RETURN_IF_ERROR(apply_basis(rec, anchors, c, &r));
  for (size_t v = 0; v < n; ++v) {
    for (int j = 0; j < 3; ++j) r[v + j * n] = mesh.positions[3 * v + j] - r[v + j * n];
  }
  scratch = r;
  GAB_RETURN_IF_ERROR(apply_basis_transposed(rec, anchors, &scratch, &z));
  restrict(&z);
  // ||B^T p|| for the relative stopping test.
  std::vector<double> p_cols(3 * n), btp;
  for (size_t v = 0; v < n; ++v) {
    for (int j = 0; j < 3; ++j) p_cols[v + j * n] = mesh.positions[3 * v + j];
  }
  GAB_RETURN_IF_ERROR(apply_basis_transposed(rec, anchors, &p_cols, &btp));
  restrict(&btp);
  double zz[3], scale[3];
  for (int j = 0; j < 3; ++j) {
    zz[j] = coordinate_dot(z, z, j, k);
    scale[j] = std::sqrt(coordinate_dot(btp, btp, j, k));
  }
  auto relative_gradient = [&] {
    double worst = 0;
    for (int j = 0; j < 3; ++j) worst = std::max(worst, scale[j] > 0 ? std::sqrt(zz[j]) / scale[j] : 0.0);
    return worst;
  };
  d = z;
  for (int32_t it = 0; it < max_iterations && relative_gradient() > tolerance; ++it) {
    GAB_RETURN_IF_ERROR(apply_basis(rec, anchors, d, &q));
    for (int j = 0; j < 3; ++j) {
      double qq = 0;
      for (size_t v = 0; v < n; ++v) qq += q[v + j * n] * q[v + j * n];
      const double alpha = qq > 0 ? zz[j] / qq : 0.0;
      for (size_t i = 0; i < k; ++i) c[3 * i + j] += alpha * d[3 * i + j];
      for (size_t v = 0; v < n; ++v) r[v + j * n] -= alpha * q[v + j * n];
    }
    scratch = r;
    GAB_RETURN_IF_ERROR(apply_basis_transposed(rec, anchors, &scratch, &z));
    restrict(&z);
    for (int j = 0; j < 3; ++j) {
      const double zz_new = coordinate_dot(z, z, j, k);
      const double beta = zz[j] > 0 ? zz_new / zz[j] : 0.0;
      zz[j] = zz_new;
      for (size_t i = 0; i < k; ++i) d[3 * i + j] = z[3 * i + j] + beta * d[3 * i + j];
    }
    report->iterations = it + 1;
  }
  report->relative_gradient = relative_gradient();
  return Status::Ok();
}

}  // namespace gab
