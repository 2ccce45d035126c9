#include "gab/mesh/mesh_read_notes.h"

#include <utility>

namespace gab {

void MeshReadNotes::drop(std::string_view key, std::string_view label, int64_t count) {
  if (count <= 0) return;
  for (DroppedData& d : dropped) {
    if (d.key == key) {
      d.count += count;
      return;
    }
  }
  // A hostile PLY header may name thousands of properties: past the cap
  // they share one entry, so the notes (and the warning line) stay small.
  if (dropped.size() >= kMaxNamedKinds) {
    key = "other";
    label = "other properties and elements";
    for (DroppedData& d : dropped) {
      if (d.key == key) {
        d.count += count;
        return;
      }
    }
  }
  dropped.push_back(DroppedData{std::string(key), std::string(label), count});
}

void MeshReadNotes::warn(std::string warning) {
  if (warnings.size() < kMaxWarnings) {
    warnings.push_back(std::move(warning));
  } else {
    ++warnings_not_listed;
  }
}

std::string MeshReadNotes::dropped_summary() const {
  std::string out;
  for (const DroppedData& d : dropped) {
    if (!out.empty()) out += ", ";
    out += std::to_string(d.count) + " " + d.label;
  }
  return out;
}

}  // namespace gab
