// Interpolatory reconstruction with relaxed anchors on top (Sorkine et al.
// 2005, section 3). The free system is the principal submatrix (L^T L)_FF;
// a relaxed anchor at free vertex a makes it (L^T L)_FF + w^2 e_i e_i^T with
// i = free_index[a], which is exactly the engine's single-nonzero-row update
// in the free numbering, so the factor is updated in place.
#include "gab/mesh/interpolatory_reconstruction.h"

#include <cmath>
#include <string>

#include "anchor_checks.h"
namespace gab {

Status InterpolatoryReconstruction::check_new(const std::vector<int32_t>& anchors,
                                              const std::vector<double>& coefficients) {
  return check_new_anchors<char>(anchors, coefficients, &kind_, kFree, kChecking, [](int32_t v, int kind) {
    return "vertex " + std::to_string(v) + (kind == kHard ? " is a hard anchor" : " is already a relaxed anchor");
  });
}

Status InterpolatoryReconstruction::init(const EdgeGraph& graph, const std::vector<int32_t>& hard_anchors,
                                         const std::vector<double>& hard_coefficients) {
  ready_ = false;
  hard_anchors_.clear();
  hard_coefficients_.clear();
  relaxed_anchors_.clear();
  rhs_.clear();
  system_ = InterpolatorySystem();
  const int32_t n = graph.num_vertices();
  kind_.assign(n, kFree);
  Status status = check_new(hard_anchors, hard_coefficients);
  // Every component needs a hard anchor, or (L^T L)_FF is singular there
  // (constants on that component are in the null space of L).
  if (status.ok()) {
    int32_t ncomp = 0;
    const std::vector<int32_t> comp = connected_components(graph, &ncomp);
    std::vector<char> covered(ncomp, 0);
    for (int32_t a : hard_anchors) covered[comp[a]] = 1;
    for (int32_t v = 0; v < n && status.ok(); ++v) {
      if (!covered[comp[v]]) {
        status = Status::Error(StatusCode::kInvalidArgument,
                               "the connected component of vertex " + std::to_string(v) +
                                   " has no hard anchor (every component needs one)");
      }
    }
  }
  if (status.ok()) status = assemble_interpolatory_matrix(graph, hard_anchors, &system_);
  if (status.ok()) status = interpolatory_right_hand_sides(graph, system_, hard_anchors, hard_coefficients, &rhs_);
  // With every vertex a hard anchor there is nothing to factor.
  if (status.ok() && num_free() > 0) status = chol_.analyze(system_.lower);
  if (status.ok() && num_free() > 0) status = chol_.factorize(system_.lower);
  if (!status.ok()) {
    kind_.clear();
    system_ = InterpolatorySystem();
    rhs_.clear();
    return status;
  }
  for (int32_t a : hard_anchors) kind_[a] = kHard;
  hard_anchors_ = hard_anchors;
  hard_coefficients_ = hard_coefficients;
  ready_ = true;
  return Status::Ok();
}

Status InterpolatoryReconstruction::add_relaxed_anchors(const std::vector<int32_t>& anchors,
                                                        const std::vector<double>& coefficients, double weight) {
  if (!ready_) return Status::Error(StatusCode::kInvalidArgument, "add_relaxed_anchors before init");
  if (!(weight > 0.0) || !std::isfinite(weight)) {
    return Status::Error(StatusCode::kInvalidArgument, "anchor weight must be positive and finite");
  }
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  if (anchors.empty()) return Status::Ok();
  std::vector<int32_t> rows(anchors.size());
  for (size_t i = 0; i < anchors.size(); ++i) rows[i] = system_.free_index[anchors[i]];
  GAB_RETURN_IF_ERROR(chol_.add_anchors(rows.data(), static_cast<int32_t>(rows.size()), weight));
  const size_t nf = system_.free_vertices.size();
  const double w2 = weight * weight;
  for (size_t i = 0; i < anchors.size(); ++i) {
    for (int c = 0; c < 3; ++c) rhs_[rows[i] + c * nf] += w2 * coefficients[3 * i + c];
    kind_[anchors[i]] = kRelaxed;
    relaxed_anchors_.push_back(anchors[i]);
  }
  return Status::Ok();
}

Status InterpolatoryReconstruction::reconstruct(std::vector<double>* positions) {
  if (!ready_) return Status::Error(StatusCode::kInvalidArgument, "reconstruct before init");
  std::vector<double> x = rhs_;
  if (num_free() > 0) GAB_RETURN_IF_ERROR(chol_.solve(x.data(), 3, num_free()));
  *positions = interpolatory_positions(system_, hard_anchors_, hard_coefficients_, x);
  return Status::Ok();
}

}  // namespace gab
