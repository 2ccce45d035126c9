// The detail layer's prediction of a vertex and the frame its residual is
// coded in, computed by the same code on both sides from what both hold:
// the smooth shape (the anchors' reconstruction rounded to the detail
// lattice, detail_chunk.h) and the positions decoded so far. Only IEEE
// +, -, *, / and sqrt on the same inputs in the same order: the encoder and
// any decoder get bit-identical predictions (the library builds with
// -ffp-contract=off).
//
// Two predictions, blended:
//  * pA, the parallelogram rule (Touma & Gotsman 1998) averaged over the
//    step's parallelograms (detail_topology.h); without one, pB.
//  * pB, the smooth shape corrected by the decoded neighbours: s_v plus the
//    mean of (decoded_u - s_u) over v's decoded neighbours u; without one,
//    s_v.
// p = pA + alpha_n (d.n) n + alpha_t (d - (d.n) n), d = pB - pA, n the
// normal of the parallelograms' decoded triangles (a, b, c), area-weighted
// and turned to the side of the smooth shape's normal at v (which stands in
// where v has no parallelogram): 1.4-1.8% smaller than the smooth normal on
// horse and igea at 1e-4 and 3e-5, the smooth shape having lost the
// surface's small-scale bends. The
// parallelogram follows the surface's sampling along the walk, the smooth
// shape knows where the surface lies: on the shared meshes at 1e-4 the best
// blends took (alpha_n, alpha_t) = (1/4, 0) for igea and horse, (1/2, 3/4)
// for feline, 9-15% below either prediction alone; the encoder measures a
// few (detail_search.h).
//
// The frame: n, t1 = the first parallelogram's edge b - a (the one decoded
// earliest) made orthogonal to n (or an axis-free choice from n), t2 =
// n x t1. Residuals in it cost 5-10% less than in x, y, z on the shared
// meshes: the normal part is 2-3 times smaller than the tangential part
// (the surface's irregular sampling, which no smooth prediction knows), and
// the tangential part is anisotropic: along the earliest edge it cost igea
// 2.8% less than along the first parallelogram's, and about as little as
// along the main axis of the residuals' running covariance. Internal to
// the codec.
#pragma once

#include <cstdint>
#include <vector>

#include "detail/detail_topology.h"

namespace gab {

// Blend weights in sixteenths (0..16).
constexpr int kDetailAlphaOne = 16;

struct DetailPrediction {
  double p[3];
  double frame[3][3];  // n, t1, t2: orthonormal
};

// Area-weighted vertex normals of `smooth` (3 per vertex), unnormalized,
// summed triangle by triangle in triangle order, into *normals. O(triangles).
void smooth_normals(const DetailTopology& topo, const std::vector<double>& smooth, std::vector<double>* normals);

// Predicts step i of the walk (vertex topo.order[i]). `smooth`, `normals`,
// `decoded`: 3 per vertex (decoded: at least the vertices of steps < i).
// O(the step's parallelograms and neighbours).
void predict_detail(const DetailTopology& topo, const std::vector<double>& smooth,
                    const std::vector<double>& normals, const std::vector<double>& decoded, int alpha_normal16,
                    int alpha_tangent16, size_t i, DetailPrediction* out);

// The decoded position: p + step (k0 n + k1 t1 + k2 t2). The one expression
// both sides evaluate.
void place_detail(const DetailPrediction& pred, double step, const int32_t k[3], double out[3]);

}  // namespace gab
