// libFuzzer target: the connectivity section's decoders (valence section,
// vertex order) on untrusted bytes, without the
// checksums that stop most mutations of a whole .gab file before they
// reach them (input format: connectivity_fuzz_input.h; an input that ever
// broke it goes to regressions/connectivity-<what>, replayed by
// tests/codec/connectivity/connectivity_fuzz_regression_test.cpp). Checks
// beyond "no crash": a failure is a one-line message; a success is exactly
// the declared triangles, every index in range.
#include <cstdint>
#include <string>
#include <vector>

#include "connectivity_fuzz_input.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  gab::GabHeader header;
  gab::ConnectivitySection section;
  if (!gab_fuzz::parse_connectivity_input(data, size, &header, &section)) return 0;
  std::vector<int32_t> triangles;
  const gab::Status status = gab::decode_connectivity_section(section, header, nullptr, &triangles);
  if (!status.ok()) {
    gab_fuzz::require(!status.message().empty(), "empty error message");
    gab_fuzz::require(status.message().find('\n') == std::string::npos, "error message spans lines");
    return 0;
  }
  gab_fuzz::require(triangles.size() == 3 * static_cast<size_t>(header.num_triangles), "wrong triangle count");
  for (int32_t v : triangles) gab_fuzz::require(v >= 0 && v < header.num_vertices, "index out of range");
  return 0;
}
