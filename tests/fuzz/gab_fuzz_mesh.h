// The mesh the .gab fuzzer's geometry-only seeds were made from (and that
// tests/codec replays them with): a 10 x 6 torus, built in code (the tests'
// own torus, tests/common/test_meshes.h; make_gab_seeds.sh writes the same);
// and that torus with one attribute of each kind, as make_gab_seeds.sh's PLY
// holds them (float32 values read back as doubles).
#pragma once

#include <cmath>
#include <cstdint>

#include "../common/test_meshes.h"
#include "gab/mesh/mesh.h"

namespace gab_fuzz {

inline gab::Mesh seed_torus() { return gab::testing_util::torus(10, 6); }
// torus-iterative-large's: past 2^14 vertices.
inline gab::Mesh large_seed_torus() { return gab::testing_util::torus(192, 180); }

// seed_torus with, per vertex (i, j) of its 10 x 6 grid: the torus's normal,
// a byte colour (25 i, 40 j, 128), a float property "quality" (i + j / 4);
// per corner: texture coordinates (i / 10, j / 6) of the corner's grid point,
// with seams where the grid wraps (u = 1 and v = 1 on the last row, column).
inline gab::Mesh attributed_seed_torus() {
  const int n = 10, m = 6;
  const double kPi = 3.14159265358979323846;
  gab::Mesh t = seed_torus();
  gab::MeshAttribute normals, colors, quality, uvs;
  normals.kind = gab::AttributeKind::kNormal;
  normals.components = 3;
  colors.kind = gab::AttributeKind::kColor;
  colors.type = gab::ValueType::kUint8;
  colors.components = 3;
  quality.name = "quality";
  uvs.kind = gab::AttributeKind::kTexCoord;
  uvs.components = 2;
  auto f = [](double x) { return static_cast<double>(static_cast<float>(x)); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      normals.values.insert(normals.values.end(), {f(std::cos(v) * std::cos(u)), f(std::cos(v) * std::sin(u)), f(std::sin(v))});
      colors.values.insert(colors.values.end(), {25.0 * i, 40.0 * j, 128.0});
      quality.values.push_back(f(i + j / 4.0));
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double a[2] = {f(i / 10.0), f(j / 6.0)}, b[2] = {f((i + 1) / 10.0), f(j / 6.0)};
      const double c[2] = {f((i + 1) / 10.0), f((j + 1) / 6.0)}, d[2] = {f(i / 10.0), f((j + 1) / 6.0)};
      for (const double* p : {a, b, c, a, c, d}) {
        uvs.corners.push_back(static_cast<int32_t>(uvs.values.size() / 2));
        uvs.values.insert(uvs.values.end(), {p[0], p[1]});
      }
    }
  }
  t.attributes = {normals, uvs, colors, quality};  // the PLY reader's order
  return t;
}

}  // namespace gab_fuzz
