// gab_write_mesh: the mesh layer's writers (gab/mesh/mesh_io.h) behind the C door.
#include <string>

#include "attribute_arrays.h"
#include "boundary.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/mesh_write_notes.h"

extern "C" int gab_write_mesh(const char* path, const double* positions, int32_t n, const int32_t* triangles,
                              int32_t t, const gab_attribute* attributes, int32_t num_attributes, char* message,
                              size_t message_size) {
  using namespace gab;
  MeshWriteNotes notes;
  const int code = capi::guarded("gab_write_mesh", message, message_size, [&]() -> Status {
    GAB_RETURN_IF_ERROR(capi::require(path != nullptr, "path is NULL"));
    Mesh mesh;
    GAB_RETURN_IF_ERROR(capi::import_mesh(positions, n, triangles, t, &mesh));
    GAB_RETURN_IF_ERROR(capi::import_attributes(attributes, num_attributes, &mesh));
    return write_mesh(path, mesh, PlyWriteOptions(), &notes);
  });
  // What the format could not hold as given: said, not silently lost (the
  // CLI's decompress warnings, in the message).
  if (code != GAB_OK || notes.empty()) return code;
  std::string text = std::string(path) + ":";
  if (notes.split_vertices > 0) {
    text += " " + std::to_string(notes.split_vertices) +
            " vertices added where per-corner attributes have seams (the format holds them per vertex)";
  }
  if (!notes.not_written.empty()) {
    text += std::string(notes.split_vertices > 0 ? ";" : "") + " not written: " + notes.not_written_summary();
  }
  capi::write_message("gab_write_mesh", text.c_str(), message, message_size);
  return code;
}
