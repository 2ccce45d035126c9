// gab_read_mesh and gab_read_mesh_with_attributes: the mesh layer's readers
// (gab/mesh/mesh_io.h) behind the C door.
#include <cstdlib>
#include <string>

#include "attribute_arrays.h"
#include "boundary.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/mesh_read_notes.h"

namespace gab {
namespace capi {

namespace {

// Both doors: the file read, the mesh into the caller's arrays, the
// attributes too for the door `with_attributes`. What the file held beyond
// what the door returns is said in the message of a success, not silently
// lost: what gab does not carry (the CLI's warning) and, for the door
// without attribute outputs, the attributes it read.
int read(const char* function, const char* path, double** positions, int32_t* n, int32_t** triangles, int32_t* t,
         bool with_attributes, gab_attribute** attributes, int32_t* num_attributes, char* message,
         size_t message_size) {
  MeshReadNotes notes;
  std::string not_returned;
  const int code = guarded(function, message, message_size, [&]() -> Status {
    GAB_RETURN_IF_ERROR(clear_mesh_outputs(positions, n, triangles, t));
    if (with_attributes) GAB_RETURN_IF_ERROR(clear_attribute_outputs(attributes, num_attributes));
    GAB_RETURN_IF_ERROR(require(path != nullptr, "path is NULL"));
    Mesh mesh;
    GAB_RETURN_IF_ERROR(read_mesh(path, &mesh, &notes));
    if (!with_attributes) {
      not_returned = describe_attributes(mesh.attributes);
      return export_mesh(mesh, positions, n, triangles, t);
    }
    gab_attribute* read = nullptr;
    int32_t count = 0;
    GAB_RETURN_IF_ERROR(export_attributes(mesh.attributes, &read, &count));
    const Status exported = export_mesh(mesh, positions, n, triangles, t);
    if (!exported.ok()) {
      std::free(read);
      return exported;
    }
    *attributes = read;
    *num_attributes = count;
    return Status::Ok();
  });
  if (code != GAB_OK || (notes.dropped.empty() && not_returned.empty())) return code;
  std::string text = std::string(path) + ":";
  if (!notes.dropped.empty()) text += " not carried: " + notes.dropped_summary();
  if (!not_returned.empty()) {
    text += std::string(notes.dropped.empty() ? "" : ";") + " not returned: " + not_returned +
            "; gab_read_mesh_with_attributes returns them";
  }
  write_message(function, text.c_str(), message, message_size);
  return code;
}

}  // namespace

}  // namespace capi
}  // namespace gab

extern "C" int gab_read_mesh(const char* path, double** positions, int32_t* n, int32_t** triangles, int32_t* t,
                             char* message, size_t message_size) {
  return gab::capi::read("gab_read_mesh", path, positions, n, triangles, t, false, nullptr, nullptr, message,
                         message_size);
}

extern "C" int gab_read_mesh_with_attributes(const char* path, double** positions, int32_t* n, int32_t** triangles,
                                             int32_t* t, gab_attribute** attributes, int32_t* num_attributes,
                                             char* message, size_t message_size) {
  return gab::capi::read("gab_read_mesh_with_attributes", path, positions, n, triangles, t, true, attributes,
                         num_attributes, message, message_size);
}
