// A bounding-volume hierarchy of axis-aligned boxes over a mesh's triangles,
// for exact closest-point (point-to-surface distance) queries.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh.h"

namespace gab {

class TriangleBvh {
 public:
  struct Hit {
    double distance_squared = 0;  // |p - point|^2
    int32_t triangle = -1;        // index in the mesh's triangles
    double point[3] = {0, 0, 0};  // closest point on the surface
  };

  // Builds over the triangles of a valid mesh (degenerate ones included); the
  // mesh may be freed afterwards. O(T log T) time, O(T) memory.
  explicit TriangleBvh(const Mesh& mesh);

  // The closest point of the surface to p. Exact up to rounding; the first
  // triangle found at the minimum distance wins. O(log T) for typical
  // queries, O(T) at worst.
  Hit closest(const double p[3]) const;
  // Same; `hint` (a triangle index, e.g. the previous query's answer) gives
  // a first upper bound, which saves work for nearby queries.
  Hit closest(const double p[3], int32_t hint) const;

  int32_t num_triangles() const { return static_cast<int32_t>(order_.size()); }
  int32_t num_nodes() const { return static_cast<int32_t>(nodes_.size()); }

 private:
  // 32 bytes, so both children of a node share one cache line. The float
  // bounds are rounded outwards: a box never shrinks below its contents.
  struct Node {
    float lo[3], hi[3];
    int32_t first;  // leaf: first slot in order_; inner: index of the left child (right = first + 1)
    int32_t count;  // leaf: number of triangles; inner: 0
  };
  double test(int32_t slot, const double p[3], Hit* best) const;

  std::vector<Node> nodes_;
  std::vector<int32_t> order_;    // slot -> triangle index
  std::vector<double> corners_;   // 9 per slot: the triangle's corners, in slot order
  std::vector<int32_t> slot_of_;  // triangle index -> slot
};

}  // namespace gab
