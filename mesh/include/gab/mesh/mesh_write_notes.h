// What a mesh writer could not put in its format, and how it reshaped the
// mesh to fit: the writers' counterpart of MeshReadNotes, filled on success
// when the caller asks (write_mesh and the format functions' last argument).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gab/mesh/mesh_read_notes.h"

namespace gab {

struct MeshWriteNotes {
  // One entry per key, in the order met, keyed as the attribute's label
  // (attribute_label: "normals", "texture_coordinates", "vertex_colors",
  // "generic:NAME"), or for a part of one "vertex_colors.alpha",
  // "texture_coordinates.w"; counted in the attribute's elements.
  std::vector<DroppedData> not_written;
  // Vertices the writer added where per-corner attributes have seams
  // (split_attribute_seams): the file has this many more vertices than the
  // mesh.
  int64_t split_vertices = 0;

  bool empty() const { return not_written.empty() && split_vertices == 0; }
  // Adds `count` (> 0) to the entry `key`, made with `label` when new. O(entries).
  void drop(std::string_view key, std::string_view label, int64_t count);
  // "4 generic attribute 'quality' (OBJ has no place for it), ...": every
  // entry, in order; "" when every attribute was written. O(entries).
  std::string not_written_summary() const;
};

}  // namespace gab
