// Internal to the mesh layer: the PLY header (everything up to end_header),
// parsed and checked on its own so the body decoder can trust it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gab/mesh/mesh_read_notes.h"
#include "gab/mesh/ply_io.h"
#include "gab/status.h"

namespace gab {
namespace mesh_detail {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

int ply_type_size(PlyType type);
bool ply_type_is_integral(PlyType type);

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;  // lists only
  PlyType type = PlyType::kFloat32;      // the scalar, or the list's items
};

struct PlyElement {
  std::string name;
  int64_t count = 0;
  std::vector<PlyProperty> properties;
  int64_t line = 0;  // header line of "element ..."

  // Index of the property called `name`, or -1.
  int find(std::string_view property) const;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::kAscii;
  std::vector<PlyElement> elements;
  size_t body_offset = 0;  // first byte after the end_header line
  int64_t body_line = 0;   // line number of that byte (ASCII bodies)
  MeshReadNotes notes;     // warnings: the unknown lines skipped
};

// Parses the header of `bytes`; messages are "<name>:<line>: ...". Checks
// the magic, the format line, the keywords (an unknown one is skipped with a
// warning in header->notes) and the property types; element
// counts are checked against the body's size by the reader. O(header).
Status parse_ply_header(std::string_view bytes, const std::string& name, PlyHeader* header);

}  // namespace mesh_detail
}  // namespace gab
