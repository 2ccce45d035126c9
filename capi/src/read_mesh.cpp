// gab_read_mesh: the mesh layer's readers (gab/mesh/mesh_io.h) behind the C door.
#include "boundary.h"
#include "gab/mesh/mesh_io.h"

extern "C" int gab_read_mesh(const char* path, double** positions, int32_t* n, int32_t** triangles, int32_t* t,
                             char* message, size_t message_size) {
  using namespace gab;
  using capi::require;
  return capi::guarded("gab_read_mesh", message, message_size, [&]() -> Status {
    GAB_RETURN_IF_ERROR(capi::clear_mesh_outputs(positions, n, triangles, t));
    GAB_RETURN_IF_ERROR(require(path != nullptr, "path is NULL"));
    Mesh mesh;
    GAB_RETURN_IF_ERROR(read_mesh(path, &mesh));
    return capi::export_mesh(mesh, positions, n, triangles, t);
  });
}
