// The generated input the benchmarks share: a triangulated nx x ny grid as a
// mesh, so it goes through the same matrix assembly as the real meshes (and
// its straight cuts are a known optimum for separators).
#pragma once

#include <cstdint>

#include "gab/mesh/mesh.h"

namespace gab_bench {

inline gab::Mesh grid_mesh(int32_t nx, int32_t ny) {
  gab::Mesh m;
  for (int32_t y = 0; y < ny; ++y)
    for (int32_t x = 0; x < nx; ++x) m.positions.insert(m.positions.end(), {double(x), double(y), 0.0});
  for (int32_t y = 0; y + 1 < ny; ++y) {
    for (int32_t x = 0; x + 1 < nx; ++x) {
      const int32_t v = y * nx + x;
      m.triangles.insert(m.triangles.end(), {v, v + 1, v + nx + 1, v, v + nx + 1, v + nx});
    }
  }
  return m;
}

}  // namespace gab_bench
