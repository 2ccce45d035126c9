// gab_read_mesh: the mesh layer's readers (gab/mesh/mesh_io.h) behind the C door.
#include <string>

#include "boundary.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/mesh_read_notes.h"

extern "C" int gab_read_mesh(const char* path, double** positions, int32_t* n, int32_t** triangles, int32_t* t,
                             char* message, size_t message_size) {
  using namespace gab;
  using capi::require;
  MeshReadNotes notes;
  const int code = capi::guarded("gab_read_mesh", message, message_size, [&]() -> Status {
    GAB_RETURN_IF_ERROR(capi::clear_mesh_outputs(positions, n, triangles, t));
    GAB_RETURN_IF_ERROR(require(path != nullptr, "path is NULL"));
    Mesh mesh;
    GAB_RETURN_IF_ERROR(read_mesh(path, &mesh, &notes));
    return capi::export_mesh(mesh, positions, n, triangles, t);
  });
  // The mesh is whole as gab knows meshes; what the file held beyond it is
  // said, not silently lost (the CLI's warning line, in the message).
  if (code == GAB_OK && !notes.dropped.empty()) {
    const std::string text = std::string(path) + ": not carried: " + notes.dropped_summary() +
                             "; gab keeps positions and triangles only";
    capi::write_message("gab_read_mesh", text.c_str(), message, message_size);
  }
  return code;
}
