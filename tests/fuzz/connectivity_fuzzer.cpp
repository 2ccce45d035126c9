// libFuzzer target: the connectivity section's decoders (valence section,
// vertex order, the first triangle list) on untrusted bytes, without the
// checksums that stop most mutations of a whole .gab file before they
// reach them. Input: flags u8 (the header's bits 3 and 4 as bits 0 and 1),
// vertex count - 1 u16, triangle count u16, valence block length u16, the
// valence block, then the vertex order block. Checks beyond "no crash": a
// failure is a one-line message; a success is exactly the declared
// triangles, every index in range.
#include <cstdint>
#include <string>
#include <vector>

#include "connectivity/connectivity_section.h"
#include "fuzz_check.h"
#include "gab/codec/gab_format.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 7) return 0;
  auto u16 = [&](size_t at) { return static_cast<int32_t>(data[at] | (data[at + 1] << 8)); };
  gab::GabHeader header;
  header.flags = static_cast<uint8_t>(((data[0] & 1) ? gab::kGabFlagReordered : 0) |
                                      ((data[0] & 2) ? gab::kGabFlagVersionedValence : 0));
  header.num_vertices = u16(1) + 1;
  header.num_triangles = u16(3);
  const size_t valence = std::min<size_t>(static_cast<size_t>(u16(5)), size - 7);
  gab::ConnectivitySection section;
  section.block = data + 7;
  section.size = valence;
  section.order = data + 7 + valence;
  section.order_size = size - 7 - valence;
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
