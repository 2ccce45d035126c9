// Median-split AABB tree (object median along the longest axis of the
// centroids' box; leaves of at most 4 triangles), and a depth-first
// nearest-point query that visits the nearer child first and prunes every
// box farther than the best distance so far (branch and bound, as in the
// AABB-tree distance queries of Metro-like tools: Cignoni, Rocchini and
// Scopigno, "Metro: measuring error on simplified surfaces", 1998).
#include "gab/mesh/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gab/mesh/point_triangle.h"

namespace gab {

namespace {

constexpr int32_t kLeafSize = 4;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Squared distance from p to the box [lo, hi] (0 inside), in double.
inline double box_distance2(const double p[3], const float lo[3], const float hi[3]) {
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double l = lo[i], h = hi[i];
    const double d = p[i] < l ? l - p[i] : p[i] > h ? p[i] - h : 0.0;
    d2 += d * d;
  }
  return d2;
}

// Floats at or below / above a double, so float boxes contain their
// contents (values beyond float's range clamp to +-FLT_MAX or infinity).
constexpr double kFloatMax = std::numeric_limits<float>::max();
inline float round_down(double x) {
  if (x > kFloatMax) return std::numeric_limits<float>::max();
  if (x < -kFloatMax) return -std::numeric_limits<float>::infinity();
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
inline float round_up(double x) {
  if (x < -kFloatMax) return -std::numeric_limits<float>::max();
  if (x > kFloatMax) return std::numeric_limits<float>::infinity();
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

}  // namespace

TriangleBvh::TriangleBvh(const Mesh& mesh) {
  const int32_t nt = mesh.num_triangles();
  // Per triangle: float box (rounded outwards) and centroid, kept in one
  // array that the median splits permute in place, so the build streams
  // through memory instead of chasing indices.
  struct Prim {
    float lo[3], hi[3], centroid[3];
    int32_t id;
  };
  std::vector<Prim> prims(nt);
  for (int32_t t = 0; t < nt; ++t) {
    double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
    for (int c = 0; c < 3; ++c) {
      const double* v = &mesh.positions[3 * static_cast<size_t>(mesh.triangles[3 * static_cast<size_t>(t) + c])];
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], v[i]);
        hi[i] = std::max(hi[i], v[i]);
      }
    }
    Prim& p = prims[t];
    for (int i = 0; i < 3; ++i) {
      p.lo[i] = round_down(lo[i]);
      p.hi[i] = round_up(hi[i]);
      p.centroid[i] = 0.5f * p.lo[i] + 0.5f * p.hi[i];
    }
    p.id = t;
  }
  if (nt > 0) {
    nodes_.reserve(2 * static_cast<size_t>(nt / kLeafSize + 1));
    nodes_.push_back(Node{{0, 0, 0}, {0, 0, 0}, 0, nt});
  }
  // Work list of nodes to split; a node covers prims[first, first + count).
  std::vector<int32_t> work;
  if (nt > 0) work.push_back(0);
  while (!work.empty()) {
    const int32_t id = work.back();
    work.pop_back();
    const int32_t first = nodes_[id].first, count = nodes_[id].count;
    float clo[3], chi[3];
    for (int i = 0; i < 3; ++i) {
      nodes_[id].lo[i] = clo[i] = std::numeric_limits<float>::infinity();
      nodes_[id].hi[i] = chi[i] = -std::numeric_limits<float>::infinity();
    }
    for (int32_t s = first; s < first + count; ++s) {
      const Prim& p = prims[s];
      for (int i = 0; i < 3; ++i) {
        nodes_[id].lo[i] = std::min(nodes_[id].lo[i], p.lo[i]);
        nodes_[id].hi[i] = std::max(nodes_[id].hi[i], p.hi[i]);
        clo[i] = std::min(clo[i], p.centroid[i]);
        chi[i] = std::max(chi[i], p.centroid[i]);
      }
    }
    if (count <= kLeafSize) continue;
    int axis = 0;
    for (int i = 1; i < 3; ++i) {
      if (chi[i] - clo[i] > chi[axis] - clo[axis]) axis = i;
    }
    // Object median: halves of equal size, so the depth is log2(T / 4) even
    // when centroids coincide; ties broken by index for determinism.
    const int32_t half = count / 2;
    std::nth_element(prims.begin() + first, prims.begin() + first + half, prims.begin() + first + count,
                     [axis](const Prim& x, const Prim& y) {
                       return x.centroid[axis] < y.centroid[axis] ||
                              (x.centroid[axis] == y.centroid[axis] && x.id < y.id);
                     });
    const int32_t left = static_cast<int32_t>(nodes_.size());
    nodes_[id].first = left;
    nodes_[id].count = 0;
    nodes_.push_back(Node{{0, 0, 0}, {0, 0, 0}, first, half});
    nodes_.push_back(Node{{0, 0, 0}, {0, 0, 0}, first + half, count - half});
    work.push_back(left + 1);
    work.push_back(left);
  }
  // Corners in slot order, so a leaf's triangles are contiguous in memory.
  order_.resize(nt);
  slot_of_.resize(nt);
  corners_.resize(static_cast<size_t>(nt) * 9);
  for (int32_t s = 0; s < nt; ++s) {
    const int32_t t = prims[s].id;
    order_[s] = t;
    slot_of_[t] = s;
    for (int c = 0; c < 3; ++c) {
      const double* v = &mesh.positions[3 * static_cast<size_t>(mesh.triangles[3 * static_cast<size_t>(t) + c])];
      for (int i = 0; i < 3; ++i) corners_[9 * static_cast<size_t>(s) + 3 * c + i] = v[i];
    }
  }
}

double TriangleBvh::test(int32_t slot, const double p[3], Hit* best) const {
  const double* v = &corners_[9 * static_cast<size_t>(slot)];
  double q[3];
  const double d2 = closest_point_on_triangle(p, v, v + 3, v + 6, q);
  if (d2 < best->distance_squared) {
    best->distance_squared = d2;
    best->triangle = order_[slot];
    for (int i = 0; i < 3; ++i) best->point[i] = q[i];
  }
  return d2;
}

TriangleBvh::Hit TriangleBvh::closest(const double p[3]) const { return closest(p, -1); }

TriangleBvh::Hit TriangleBvh::closest(const double p[3], int32_t hint) const {
  Hit best;
  best.distance_squared = kInf;
  if (nodes_.empty()) return best;
  if (hint >= 0 && hint < num_triangles()) test(slot_of_[hint], p, &best);
  // Explicit stack of (node, its box distance). The depth is at most
  // log2(T) + 1 < 32 levels and each level leaves at most one entry behind.
  struct Entry {
    int32_t node;
    double d2;
  };
  Entry stack[64];
  int top = 0;
  stack[top++] = {0, box_distance2(p, nodes_[0].lo, nodes_[0].hi)};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.d2 >= best.distance_squared) continue;
    const Node& node = nodes_[e.node];
    if (node.count > 0) {
      for (int32_t s = node.first; s < node.first + node.count; ++s) test(s, p, &best);
      continue;
    }
    const int32_t l = node.first, r = node.first + 1;
    const double dl = box_distance2(p, nodes_[l].lo, nodes_[l].hi);
    const double dr = box_distance2(p, nodes_[r].lo, nodes_[r].hi);
    // Push the farther child first so the nearer one is searched first.
    if (dl <= dr) {
      if (dr < best.distance_squared) stack[top++] = {r, dr};
      if (dl < best.distance_squared) stack[top++] = {l, dl};
    } else {
      if (dl < best.distance_squared) stack[top++] = {l, dl};
      if (dr < best.distance_squared) stack[top++] = {r, dr};
    }
  }
  return best;
}

}  // namespace gab
