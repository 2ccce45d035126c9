// What every reader fuzzer asserts beyond "no crash": a failure carries a
// message naming the input, and a success is a valid mesh that survives a
// write -> read round trip unchanged, its attributes too (split at their
// seams where the format holds one value per vertex).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"

namespace gab_fuzz {

inline void require(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "fuzz check failed: %s\n", what);
    std::abort();
  }
}

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return std::string_view(reinterpret_cast<const char*>(data), size);
}

inline void check_result(const gab::Status& status, const gab::Mesh& mesh, const std::string& name) {
  if (!status.ok()) {
    require(status.message().rfind(name, 0) == 0, "error message does not start with the file name");
    require(status.message().find('\n') == std::string::npos, "error message spans lines");
    return;
  }
  require(gab::validate_mesh(mesh, name).ok(), "reader returned an invalid mesh");
}

// Same connectivity; positions equal, or within a relative `tolerance`.
inline bool same_mesh(const gab::Mesh& a, const gab::Mesh& b, double tolerance) {
  if (a.triangles != b.triangles || a.positions.size() != b.positions.size()) return false;
  for (size_t i = 0; i < a.positions.size(); ++i) {
    const double slack = tolerance * std::fabs(a.positions[i]) + (tolerance > 0 ? 1e-300 : 0.0);
    if (!(std::fabs(a.positions[i] - b.positions[i]) <= slack)) return false;
  }
  return true;
}

// The same attributes, value for value, in the same order.
inline bool same_attributes(const gab::Mesh& a, const gab::Mesh& b) {
  if (a.attributes.size() != b.attributes.size()) return false;
  for (size_t i = 0; i < a.attributes.size(); ++i) {
    const gab::MeshAttribute& x = a.attributes[i];
    const gab::MeshAttribute& y = b.attributes[i];
    if (x.kind != y.kind || x.type != y.type || x.name != y.name || x.components != y.components ||
        x.values != y.values || x.corners != y.corners) {
      return false;
    }
  }
  return true;
}

}  // namespace gab_fuzz
