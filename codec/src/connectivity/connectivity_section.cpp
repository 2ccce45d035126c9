#include "connectivity/connectivity_section.h"

#include <string>

#include "connectivity/connectivity_coder.h"
#include "connectivity/valence_section.h"
#include "container/framing.h"

namespace gab {

namespace {

Status corrupt(const std::string& what) { return Status::Error(StatusCode::kParseError, what); }

}  // namespace

void write_connectivity_section(const Mesh& mesh, const GabHeader& header, const std::vector<uint8_t>& valence_block,
                                ByteWriter* out) {
  if (header.geometry_only()) {
    out->u64(connectivity_hash(mesh.num_vertices(), mesh.triangles));
    return;
  }
  if (header.reordered()) {
    write_framed(valence_block.data(), valence_block.size(), out);
    return;
  }
  const std::vector<uint8_t> block = encode_connectivity(mesh.num_vertices(), mesh.triangles);
  write_framed(block.data(), block.size(), out);
}

Status read_connectivity_section(ByteReader* in, const GabHeader& header, ConnectivitySection* section) {
  *section = ConnectivitySection();
  if (header.geometry_only()) {
    if (!in->u64(&section->hash)) return corrupt("file ends inside the connectivity hash");
    return Status::Ok();
  }
  switch (read_framed(in, &section->block, &section->size)) {
    case FrameRead::kTruncated: return corrupt("file ends inside the connectivity block");
    case FrameRead::kCorrupt: return corrupt("connectivity block is corrupt (checksum mismatch)");
    case FrameRead::kOk: break;
  }
  return Status::Ok();
}

Status decode_connectivity_section(const ConnectivitySection& section, const GabHeader& header, const Mesh* given,
                                   std::vector<int32_t>* triangles) {
  if (header.geometry_only()) {
    if (!given) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "this file holds geometry only: give the mesh it was made from (--connectivity MESH)");
    }
    const Mesh& m = *given;
    if (m.num_vertices() != header.num_vertices || m.num_triangles() != header.num_triangles ||
        connectivity_hash(m.num_vertices(), m.triangles) != section.hash) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "the connectivity mesh is not the one this file was made from (" +
                               std::to_string(m.num_vertices()) + " vertices, " + std::to_string(m.num_triangles()) +
                               " triangles; the file expects " + std::to_string(header.num_vertices) + " and " +
                               std::to_string(header.num_triangles) + ", and a matching hash)");
    }
    *triangles = m.triangles;
    return Status::Ok();
  }
  const Status s = header.reordered() ? decode_valence_section(section.block, section.size, header.num_vertices,
                                                              header.num_triangles, triangles, 1)
                                      : decode_connectivity(section.block, section.size, header.num_vertices,
                                                            header.num_triangles, triangles);
  if (!s.ok()) return corrupt("connectivity block: " + s.message());
  return Status::Ok();
}

}  // namespace gab
