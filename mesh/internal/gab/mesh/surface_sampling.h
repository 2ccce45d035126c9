// Area-uniform random points on a triangle mesh's surface.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh.h"

namespace gab {

// `count` points (x y z each) spread over the surface with density
// proportional to area: stratified over the cumulative area (point j lies in
// the triangle holding area (j + u_j) / count of the total, u_j uniform in
// [0, 1)), uniform within its triangle. Zero-area triangles get none; a mesh
// of zero total area gets none. `triangle_of`, if given, receives each
// point's triangle. Deterministic for a given seed on every platform.
// O(T + count).
std::vector<double> sample_surface(const Mesh& mesh, int64_t count, uint64_t seed,
                                   std::vector<int32_t>* triangle_of = nullptr);

// Area of each triangle. O(T).
std::vector<double> triangle_areas(const Mesh& mesh);

}  // namespace gab
