// libFuzzer target: the format dispatcher's content check in front of each
// reader. The first byte picks the claimed format, the rest is the file.
#include "fuzz_check.h"
#include "gab/mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const gab::MeshFormat kFormats[3] = {gab::MeshFormat::kObj, gab::MeshFormat::kOff, gab::MeshFormat::kPly};
  const std::string name = "fuzz.mesh";
  gab::Mesh mesh;
  const gab::Status status = gab::parse_mesh(gab_fuzz::as_text(data + 1, size - 1), kFormats[data[0] % 3], name, &mesh);
  gab_fuzz::check_result(status, mesh, name);
  return 0;
}
