// Small meshes generated in code for the mesh-layer tests, and temp files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>

#include "common/scratch_files.h"
#include "gab/mesh/mesh.h"

namespace gab {
namespace testing_util {

// An nx x ny grid of unit squares in the z = 0 plane, each split in two
// triangles; vertex (i, j) is i + j (nx + 1), at (i, j, 0) * spacing.
inline Mesh grid(int nx, int ny, double spacing = 1.0) {
  Mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.positions.insert(m.positions.end(), {i * spacing, j * spacing, 0.0});
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int32_t v = i + j * (nx + 1), r = v + 1, u = v + nx + 1, ur = u + 1;
      m.triangles.insert(m.triangles.end(), {v, r, ur, v, ur, u});
    }
  }
  return m;
}

// A closed torus (genus 1): n x m quads split in two, radii R and r.
inline Mesh torus(int n, int m, double R = 1.0, double r = 0.3) {
  Mesh t;
  const double kPi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      t.positions.insert(t.positions.end(),
                         {(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const int32_t a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m,
                    d = i * m + (j + 1) % m;
      t.triangles.insert(t.triangles.end(), {a, b, c, a, c, d});
    }
  }
  return t;
}

// A path unique to this call, in the process's scratch folder.
inline std::string temp_path(const std::string& name) {
  static int calls = 0;
  return gab_test::scratch_path(std::to_string(++calls) + "_" + name);
}

inline std::string shared_mesh(const std::string& name) { return std::string(GAB_SHARED_MESHES) + "/" + name; }

inline bool exists(const std::string& path) { return static_cast<bool>(std::ifstream(path)); }

}  // namespace testing_util
}  // namespace gab
