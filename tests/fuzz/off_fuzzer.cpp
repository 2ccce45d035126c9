// libFuzzer target: the OFF reader, plus an OFF round trip of what it accepts.
#include "fuzz_check.h"
#include "gab/mesh/off_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string name = "fuzz.off";
  gab::Mesh mesh;
  const gab::Status status = gab::parse_off(gab_fuzz::as_text(data, size), name, &mesh);
  gab_fuzz::check_result(status, mesh, name);
  if (status.ok()) {
    gab::Mesh again;
    gab_fuzz::require(gab::parse_off(gab::format_off(mesh), name, &again).ok(), "written OFF does not read");
    gab_fuzz::require(gab_fuzz::same_mesh(mesh, again, 0.0), "OFF round trip changed the mesh");
    gab_fuzz::require(gab_fuzz::same_attributes(mesh, again), "OFF round trip changed the attributes");
  }
  return 0;
}
