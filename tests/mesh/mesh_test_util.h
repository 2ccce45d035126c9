// Temp files and the shared meshes for the mesh-layer tests; small meshes
// generated in code come from common/test_meshes.h.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

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

}  // namespace testing_util
}  // namespace gab
