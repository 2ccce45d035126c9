// Temp files and the shared meshes for the mesh-layer tests; small meshes
// generated in code come from common/test_meshes.h.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>

#include "common/scratch_files.h"
#include "common/test_meshes.h"
#include "gab/mesh/mesh.h"

namespace gab {
namespace testing_util {

// A path unique to this call, in the process's scratch folder.
inline std::string temp_path(const std::string& name) {
  static int calls = 0;
  return gab_test::scratch_path(std::to_string(++calls) + "_" + name);
}

inline std::string shared_mesh(const std::string& name) { return std::string(GAB_SHARED_MESHES) + "/" + name; }

inline bool exists(const std::string& path) { return static_cast<bool>(std::ifstream(path)); }

// Whether `a` and `b` have the same attributes, value for value, in the
// same order; the failure says where they differ.
inline ::testing::AssertionResult same_attributes(const Mesh& a, const Mesh& b) {
  if (a.attributes.size() != b.attributes.size()) {
    return ::testing::AssertionFailure() << a.attributes.size() << " attributes against " << b.attributes.size();
  }
  for (size_t i = 0; i < a.attributes.size(); ++i) {
    const MeshAttribute& x = a.attributes[i];
    const MeshAttribute& y = b.attributes[i];
    const std::string what = "attribute " + std::to_string(i) + " (" + attribute_label(x) + ")";
    if (x.kind != y.kind || x.name != y.name) {
      return ::testing::AssertionFailure() << what << ": " << attribute_label(y) << " in its place";
    }
    if (x.type != y.type) {
      return ::testing::AssertionFailure() << what << ": type " << static_cast<int>(x.type) << " against "
                                           << static_cast<int>(y.type);
    }
    if (x.components != y.components) {
      return ::testing::AssertionFailure() << what << ": " << x.components << " components against " << y.components;
    }
    if (x.corners != y.corners) return ::testing::AssertionFailure() << what << ": the corners differ";
    if (x.values.size() != y.values.size()) {
      return ::testing::AssertionFailure() << what << ": " << x.values.size() << " values against " << y.values.size();
    }
    for (size_t k = 0; k < x.values.size(); ++k) {
      // Bit for bit: -0 is not 0 here.
      if (std::signbit(x.values[k]) != std::signbit(y.values[k]) || x.values[k] != y.values[k]) {
        return ::testing::AssertionFailure() << what << ": value " << k << " is " << x.values[k] << " against "
                                             << y.values[k];
      }
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace testing_util
}  // namespace gab
