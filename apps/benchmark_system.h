// The matrix that `gab factor` and `gab study` work on: a Matrix Market
// file as given, or a mesh's L^T L + w^2 E^T E by the benchmark anchor rule
// (docs/cli.md, "gab factor"), with three right-hand sides.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gab/mesh/mesh_read_notes.h"
#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {
namespace cli {

struct BenchmarkSystem {
  CscMatrix lower;            // lower triangle incl. diagonal
  std::vector<double> rhs;    // n x 3 column-major
  std::vector<int32_t> anchors;  // mesh input only: initial anchors
  bool from_mesh = false;
  int32_t faces = 0;             // mesh input only
  MeshReadNotes read_notes;      // mesh input only: what the file held that the mesh does not carry
};

// k0: number of initial anchors for a mesh; subdivide: levels of 1:4
// midpoint subdivision applied to a mesh first (both ignored for .mtx).
Status load_benchmark_system(const std::string& path, int32_t k0, BenchmarkSystem* out,
                             int subdivide = 0);

}  // namespace cli
}  // namespace gab
