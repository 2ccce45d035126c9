// Interpolatory reconstruction (Sorkine et al. 2005, section 3: anchors as
// hard constraints). The matrix is the principal submatrix of the relaxed
// system's L^T L on the free vertices; the right-hand side uses L = L^T (the
// uniform Laplacian D - A is symmetric): -(L^T L)_FA c = -(L (L c~))_F with
// c~ the anchors' values scattered into a zero vector.
#include "gab/mesh/interpolatory_system.h"

#include <string>

#include "gab/mesh/normal_matrix.h"

namespace gab {

namespace {

// y = L x for the uniform Laplacian, y_k = deg(k) x_k - sum of x over the neighbours.
void apply_laplacian(const EdgeGraph& graph, const std::vector<double>& x, std::vector<double>* y) {
  const int32_t n = graph.num_vertices();
  y->assign(n, 0.0);
  for (int32_t k = 0; k < n; ++k) {
    double s = graph.degree(k) * x[k];
    for (int32_t p = graph.offsets[k]; p < graph.offsets[k + 1]; ++p) s -= x[graph.neighbors[p]];
    (*y)[k] = s;
  }
}

}  // namespace

Status assemble_interpolatory_matrix(const EdgeGraph& graph, const std::vector<int32_t>& anchors,
                                     InterpolatorySystem* system) {
  const int32_t n = graph.num_vertices();
  InterpolatorySystem s;
  s.free_index.assign(n, 0);
  for (int32_t a : anchors) {
    if (a < 0 || a >= n) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "anchor " + std::to_string(a) + " is not a vertex (n = " + std::to_string(n) + ")");
    }
    if (s.free_index[a] == -1) return Status::Error(StatusCode::kInvalidArgument, "anchor " + std::to_string(a) + " given twice");
    s.free_index[a] = -1;
  }
  CscMatrix full;
  GAB_RETURN_IF_ERROR(assemble_normal_matrix(graph, {}, 0.0, &full));
  for (int32_t v = 0; v < n; ++v) {
    if (s.free_index[v] == 0) {
      s.free_index[v] = static_cast<int32_t>(s.free_vertices.size());
      s.free_vertices.push_back(v);
    }
  }
  // Keep the rows and columns of free vertices; renumbering is monotone, so
  // rows stay sorted within each column.
  const int32_t nf = static_cast<int32_t>(s.free_vertices.size());
  CscMatrix& m = s.lower;
  m.nrows = m.ncols = nf;
  m.colptr.assign(nf + 1, 0);
  for (int32_t j = 0; j < nf; ++j) {
    const int32_t col = s.free_vertices[j];
    for (int32_t p = full.colptr[col]; p < full.colptr[col + 1]; ++p) {
      const int32_t row = s.free_index[full.rowind[p]];
      if (row < 0) continue;
      m.rowind.push_back(row);
      m.values.push_back(full.values[p]);
    }
    m.colptr[j + 1] = static_cast<int32_t>(m.rowind.size());
  }
  *system = std::move(s);
  return Status::Ok();
}

Status interpolatory_right_hand_sides(const EdgeGraph& graph, const InterpolatorySystem& system,
                                      const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                                      std::vector<double>* rhs) {
  const int32_t n = graph.num_vertices();
  if (static_cast<int32_t>(system.free_index.size()) != n ||
      system.free_vertices.size() + anchors.size() != static_cast<size_t>(n)) {
    return Status::Error(StatusCode::kInvalidArgument, "the system was not built for this graph and these anchors");
  }
  if (coefficients.size() != anchors.size() * 3) {
    return Status::Error(StatusCode::kInvalidArgument, "expected " + std::to_string(anchors.size() * 3) +
                                                           " coefficients (x y z per anchor), got " +
                                                           std::to_string(coefficients.size()));
  }
  for (int32_t a : anchors) {
    if (a < 0 || a >= n || system.free_index[a] != -1) {
      return Status::Error(StatusCode::kInvalidArgument, "vertex " + std::to_string(a) + " is not an anchor of the system");
    }
  }
  const size_t nf = system.free_vertices.size();
  std::vector<double> c(n), lc, llc;
  rhs->assign(nf * 3, 0.0);
  for (int axis = 0; axis < 3; ++axis) {
    std::fill(c.begin(), c.end(), 0.0);
    for (size_t i = 0; i < anchors.size(); ++i) c[anchors[i]] = coefficients[3 * i + axis];
    apply_laplacian(graph, c, &lc);
    apply_laplacian(graph, lc, &llc);
    for (size_t i = 0; i < nf; ++i) (*rhs)[axis * nf + i] = -llc[system.free_vertices[i]];
  }
  return Status::Ok();
}

std::vector<double> interpolatory_positions(const InterpolatorySystem& system, const std::vector<int32_t>& anchors,
                                            const std::vector<double>& coefficients,
                                            const std::vector<double>& free_solution) {
  const size_t n = system.free_index.size(), nf = system.free_vertices.size();
  std::vector<double> positions(n * 3, 0.0);
  for (size_t i = 0; i < nf; ++i) {
    for (int axis = 0; axis < 3; ++axis) positions[3 * static_cast<size_t>(system.free_vertices[i]) + axis] = free_solution[axis * nf + i];
  }
  for (size_t i = 0; i < anchors.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) positions[3 * static_cast<size_t>(anchors[i]) + axis] = coefficients[3 * i + axis];
  }
  return positions;
}

}  // namespace gab
