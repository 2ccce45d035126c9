#include "demo_mesh.h"

#include <cmath>

#include "gab/mesh/subdivide.h"

namespace gab {
namespace cli {

Mesh bumpy_sphere(int levels) {
  // The icosahedron: vertices (0, +-1, +-t) and their cyclic shifts.
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  m.positions = {-1, t,  0, 1, t,  0, -1, -t, 0, 1, -t, 0, 0, -1, t,  0, 1, t,
                 0,  -1, -t, 0, 1, -t, t,  0, -1, t, 0,  1, -t, 0,  -1, -t, 0, 1};
  m.triangles = {0, 11, 5, 0, 5,  1,  0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11, 4,  11, 10, 2,  10, 7, 6, 7, 1, 8,
                 3, 9,  4, 3, 4,  2,  3, 2, 6, 3, 6,  8,  3, 8,  9,  4, 9, 5, 2, 4,  11, 6,  2,  10, 8,  6, 7, 9, 8, 1};
  m = subdivide_midpoint(m, levels);
  for (int32_t v = 0; v < m.num_vertices(); ++v) {
    double* p = &m.positions[3 * static_cast<size_t>(v)];
    const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double x = p[0] / len, y = p[1] / len, z = p[2] / len;
    const double r = 1.0 + 0.12 * std::sin(5 * x) * std::cos(4 * y) + 0.06 * std::sin(9 * z + 2 * x) +
                     0.03 * std::cos(17 * y - 5 * z);
    p[0] = r * x;
    p[1] = r * y;
    p[2] = r * z;
  }
  return m;
}

}  // namespace cli
}  // namespace gab
