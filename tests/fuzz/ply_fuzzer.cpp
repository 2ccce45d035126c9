// libFuzzer target: the PLY reader (ASCII and both binary byte orders), plus
// a round trip through each encoding of what it accepts.
#include "fuzz_check.h"
#include "gab/mesh/attribute_seams.h"
#include "gab/mesh/ply_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string name = "fuzz.ply";
  gab::Mesh mesh;
  const gab::Status status = gab::parse_ply(gab_fuzz::as_text(data, size), name, &mesh);
  gab_fuzz::check_result(status, mesh, name);
  if (status.ok()) {
    // Per-corner texture coordinates (a face `texcoord` list) are written per vertex.
    const gab::Mesh split = gab::split_attribute_seams(mesh);
    for (gab::PlyEncoding e : {gab::PlyEncoding::kAscii, gab::PlyEncoding::kBinaryLittleEndian,
                               gab::PlyEncoding::kBinaryBigEndian}) {
      gab::PlyWriteOptions options;
      options.encoding = e;
      gab::Mesh again;
      gab_fuzz::require(gab::parse_ply(gab::format_ply(mesh, options), name, &again).ok(), "written PLY does not read");
      gab_fuzz::require(gab_fuzz::same_mesh(split, again, 0.0), "PLY round trip changed the mesh");
      gab_fuzz::require(gab_fuzz::same_attributes(split, again), "PLY round trip changed the attributes");
    }
  }
  return 0;
}
