// The connectivity fuzzer's input format (connectivity_fuzzer.cpp), shared
// with the test that replays its regressions: flags u8 (bit 0: the
// header's kGabFlagReordered; the other bits are ignored), vertex count - 1 u16, triangle count u16, valence
// block length u16, the valence block, then the vertex order block.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "connectivity/connectivity_section.h"
#include "gab/codec/gab_format.h"

namespace gab_fuzz {

// False if the input is too short to hold the fixed fields.
inline bool parse_connectivity_input(const uint8_t* data, size_t size, gab::GabHeader* header,
                                     gab::ConnectivitySection* section) {
  if (size < 7) return false;
  auto u16 = [&](size_t at) { return static_cast<int32_t>(data[at] | (data[at + 1] << 8)); };
  *header = gab::GabHeader();
  header->flags = (data[0] & 1) ? gab::kGabFlagReordered : 0;
  header->num_vertices = u16(1) + 1;
  header->num_triangles = u16(3);
  const size_t valence = std::min<size_t>(static_cast<size_t>(u16(5)), size - 7);
  *section = gab::ConnectivitySection();
  section->block = data + 7;
  section->size = valence;
  section->order = data + 7 + valence;
  section->order_size = size - 7 - valence;
  return true;
}

}  // namespace gab_fuzz
