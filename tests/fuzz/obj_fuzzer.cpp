// libFuzzer target: the OBJ reader (line scan + tinyobjloader), plus an OBJ
// round trip of what it accepts (tinyobjloader's number parsing is not
// correctly rounded, hence the tolerance).
#include "fuzz_check.h"
#include "gab/mesh/obj_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string name = "fuzz.obj";
  gab::Mesh mesh;
  const gab::Status status = gab::parse_obj(gab_fuzz::as_text(data, size), name, &mesh);
  gab_fuzz::check_result(status, mesh, name);
  if (status.ok()) {
    gab::Mesh again;
    gab_fuzz::require(gab::parse_obj(gab::format_obj(mesh), name, &again).ok(), "written OBJ does not read");
    gab_fuzz::require(gab_fuzz::same_mesh(mesh, again, 1e-14), "OBJ round trip changed the mesh");
    gab_fuzz::require(gab_fuzz::same_attributes(mesh, again), "OBJ round trip changed the attributes");
  }
  return 0;
}
