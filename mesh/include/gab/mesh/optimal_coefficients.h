// Least-squares optimal anchor coefficients (Sorkine et al. 2005, sec. IV:
// "perhaps the best way"): for fixed anchors, the coefficients c whose
// relaxed reconstruction B c (B = w^2 M^-1 E^T, the geometry-aware basis)
// is closest to the original shape, instead of the anchors' own positions.
// B is never formed: conjugate gradients on the normal equations
// B^T B c = B^T p, each iteration two solves with the factor of M for the
// three coordinates together.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "gab/status.h"

namespace gab {

struct OptimalCoefficientsReport {
  int32_t iterations = 0;
  double relative_gradient = 0;  // ||B^T (p - B c)|| / ||B^T p|| at the end, worst coordinate
};

// Replaces *coefficients (3 per anchor of `rec`, in rec.anchors() order; on
// entry the starting guess, e.g. the anchors' positions) by the least-squares
// optimal ones for `mesh`'s positions. Stops after `max_iterations` or when
// the relative gradient is below `tolerance`. `rec` keeps its factor (its
// right-hand side is not changed: reconstruct() still uses the coefficients
// it was given). Cost per iteration: two three-column solves and O(n).
// With `first_free` > 0 only the coefficients of anchors first_free.. are
// optimized, the earlier ones held fixed (what a progressive encoder needs:
// the earlier chunks are already sent).
Status optimal_coefficients(RelaxedReconstruction* rec, const Mesh& mesh, int32_t max_iterations, double tolerance,
                            std::vector<double>* coefficients, OptimalCoefficientsReport* report,
                            int32_t first_free = 0);

}  // namespace gab
