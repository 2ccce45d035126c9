#include "gab/mesh/mesh_write_notes.h"

namespace gab {

void MeshWriteNotes::drop(std::string_view key, std::string_view label, int64_t count) {
  if (count <= 0) return;
  for (DroppedData& d : not_written) {
    if (d.key == key) {
      d.count += count;
      return;
    }
  }
  not_written.push_back(DroppedData{std::string(key), std::string(label), count});
}

std::string MeshWriteNotes::not_written_summary() const {
  std::string out;
  for (const DroppedData& d : not_written) {
    if (!out.empty()) out += ", ";
    out += std::to_string(d.count) + " " + d.label;
  }
  return out;
}

}  // namespace gab
