// What a mesh file held that a Mesh (positions, triangles and the attributes
// the readers keep: mesh_io.h) does not carry, counted by the readers, and
// what they forgave in the file. The readers fill it on success; the CLI
// prints it as one warning line per input and compress --json's "dropped"
// object (docs/cli.md).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gab {

// One kind of data the reader saw and did not keep.
struct DroppedData {
  // Stable name, one vocabulary for every format: "polygons", "groups",
  // "normals" (when not carried: an OBJ's vn no face refers to), ...;
  // PLY data with no common name is "vertex.NAME", "face.NAME" (properties)
  // or "element.NAME" (whole elements).
  std::string key;
  // For people, in the format's own spelling: "groups (g)",
  // "normals (nx ny nz; vertex 12: a value that is not finite)".
  std::string label;
  // How many: records (OBJ lines), faces, or the vertices or elements that
  // carry it (PLY, OFF).
  int64_t count = 0;
};

struct MeshReadNotes {
  // At most this many kinds are named; the rest are summed under "other".
  static constexpr size_t kMaxNamedKinds = 32;
  // At most this many warnings are kept; the rest are counted.
  static constexpr size_t kMaxWarnings = 8;

  std::vector<DroppedData> dropped;   // one entry per key, in the order first met
  std::vector<std::string> warnings;  // what was forgiven, "<name>:<line>: ..."
  int64_t warnings_not_listed = 0;    // warnings past kMaxWarnings

  bool empty() const { return dropped.empty() && warnings.empty() && warnings_not_listed == 0; }
  // Adds `count` (> 0) to the entry `key`, made with `label` when new.
  // O(kMaxNamedKinds).
  void drop(std::string_view key, std::string_view label, int64_t count);
  // Keeps `warning` (or counts it, past kMaxWarnings). O(1).
  void warn(std::string warning);
  // "19 groups (g), 1 material libraries (mtllib)": every entry, in order;
  // "" when nothing was dropped. O(entries).
  std::string dropped_summary() const;
};

}  // namespace gab
