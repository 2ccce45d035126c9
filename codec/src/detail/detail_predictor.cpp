#include "detail/detail_predictor.h"

#include <cmath>

namespace gab {

namespace {

// (x_b - x_a) x (x_c - x_a) for the points at offsets a, b, c of x (3 per point).
void cross_at(const std::vector<double>& x, size_t a, size_t b, size_t c, double out[3]) {
  const double e1[3] = {x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]};
  const double e2[3] = {x[c] - x[a], x[c + 1] - x[a + 1], x[c + 2] - x[a + 2]};
  out[0] = e1[1] * e2[2] - e1[2] * e2[1];
  out[1] = e1[2] * e2[0] - e1[0] * e2[2];
  out[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

}  // namespace

void smooth_normals(const DetailTopology& topo, const std::vector<double>& smooth, std::vector<double>* out) {
  out->assign(3 * static_cast<size_t>(topo.num_vertices), 0.0);
  std::vector<double>& normals = *out;
  const std::vector<int32_t>& tri = *topo.triangles;
  for (size_t t3 = 0; t3 + 2 < tri.size(); t3 += 3) {
    const size_t i0 = 3 * static_cast<size_t>(tri[t3]), i1 = 3 * static_cast<size_t>(tri[t3 + 1]),
                 i2 = 3 * static_cast<size_t>(tri[t3 + 2]);
    double nrm[3];
    cross_at(smooth, i0, i1, i2, nrm);
    for (size_t corner : {i0, i1, i2}) {
      // A degenerate triangle names a vertex twice: it adds its (zero-ish) normal twice, on both sides alike.
      for (int j = 0; j < 3; ++j) normals[corner + j] += nrm[j];
    }
  }
}

void predict_detail(const DetailTopology& topo, const std::vector<double>& smooth,
                    const std::vector<double>& normals, const std::vector<double>& decoded, int alpha_normal16,
                    int alpha_tangent16, size_t i, DetailPrediction* out) {
  const int32_t v = topo.order[i];
  const size_t v3 = 3 * static_cast<size_t>(v);
  double* n = out->frame[0];
  double* t1 = out->frame[1];
  double* t2 = out->frame[2];
  // The smooth shape's normal: the fallback, and the side the fan's normal is turned to.
  const double nl = std::sqrt(normals[v3] * normals[v3] + normals[v3 + 1] * normals[v3 + 1] +
                              normals[v3 + 2] * normals[v3 + 2]);
  if (nl > 0) {
    for (int j = 0; j < 3; ++j) n[j] = normals[v3 + j] / nl;
  } else {
    n[0] = 0;
    n[1] = 0;
    n[2] = 1;
  }
  // Per parallelogram (a, b, c): the rule's a + b - c, and the decoded
  // triangle's normal. The decoded triangles across the parallelograms'
  // edges know the surface at the vertex's own scale, which the smooth shape
  // has lost: their area-weighted normal, each turned to the smooth normal's
  // side, is the frame's.
  double par[3] = {0, 0, 0}, gate[3] = {0, 0, 0}, fan[3] = {0, 0, 0};
  const int32_t first = topo.parallelogram_offsets[i], last = topo.parallelogram_offsets[i + 1];
  for (int32_t p = first; p < last; ++p) {
    const size_t a3 = 3 * static_cast<size_t>(topo.parallelograms[3 * static_cast<size_t>(p)]);
    const size_t b3 = 3 * static_cast<size_t>(topo.parallelograms[3 * static_cast<size_t>(p) + 1]);
    const size_t c3 = 3 * static_cast<size_t>(topo.parallelograms[3 * static_cast<size_t>(p) + 2]);
    for (int j = 0; j < 3; ++j) par[j] += decoded[a3 + j] + decoded[b3 + j] - decoded[c3 + j];
    if (p == first) {
      for (int j = 0; j < 3; ++j) gate[j] = decoded[b3 + j] - decoded[a3 + j];
    }
    double cross[3];
    cross_at(decoded, a3, b3, c3, cross);
    const double side = cross[0] * n[0] + cross[1] * n[1] + cross[2] * n[2] < 0 ? -1.0 : 1.0;
    for (int j = 0; j < 3; ++j) fan[j] += side * cross[j];
  }
  const double fl = std::sqrt(fan[0] * fan[0] + fan[1] * fan[1] + fan[2] * fan[2]);
  if (fl > 0) {
    for (int j = 0; j < 3; ++j) n[j] = fan[j] / fl;
  }
  const int32_t parallelograms = last - first;
  // pB: the smooth shape moved by the decoded neighbours' mean offset from it.
  double offset[3] = {0, 0, 0};
  const int32_t known = topo.known_offsets[i + 1] - topo.known_offsets[i];
  for (int32_t p = topo.known_offsets[i]; p < topo.known_offsets[i + 1]; ++p) {
    const size_t u3 = 3 * static_cast<size_t>(topo.known[p]);
    for (int j = 0; j < 3; ++j) offset[j] += decoded[u3 + j] - smooth[u3 + j];
  }
  double pb[3], pa[3];
  for (int j = 0; j < 3; ++j) {
    pb[j] = smooth[v3 + j] + (known > 0 ? offset[j] / known : 0.0);
    pa[j] = parallelograms > 0 ? par[j] / parallelograms : pb[j];
  }
  const double d[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
  const double dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
  const double an = alpha_normal16 / static_cast<double>(kDetailAlphaOne);
  const double at = alpha_tangent16 / static_cast<double>(kDetailAlphaOne);
  for (int j = 0; j < 3; ++j) out->p[j] = pa[j] + an * dn * n[j] + at * (d[j] - dn * n[j]);

  // t1: the gate edge in the tangent plane, else an axis-free choice from n.
  const double gn = gate[0] * n[0] + gate[1] * n[1] + gate[2] * n[2];
  for (int j = 0; j < 3; ++j) t1[j] = gate[j] - gn * n[j];
  double len = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  if (!(len > 0)) {
    if (std::fabs(n[0]) < 0.6) {
      t1[0] = 0;
      t1[1] = n[2];
      t1[2] = -n[1];
    } else {
      t1[0] = -n[2];
      t1[1] = 0;
      t1[2] = n[0];
    }
    len = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  }
  for (int j = 0; j < 3; ++j) t1[j] /= len;
  t2[0] = n[1] * t1[2] - n[2] * t1[1];
  t2[1] = n[2] * t1[0] - n[0] * t1[2];
  t2[2] = n[0] * t1[1] - n[1] * t1[0];
}

void place_detail(const DetailPrediction& pred, double step, const int32_t k[3], double out[3]) {
  for (int j = 0; j < 3; ++j) {
    out[j] = pred.p[j] + step * (k[0] * pred.frame[0][j] + k[1] * pred.frame[1][j] + k[2] * pred.frame[2][j]);
  }
}

}  // namespace gab
