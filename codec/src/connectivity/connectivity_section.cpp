#include "connectivity/connectivity_section.h"

#include <string>

#include "connectivity/active_lists.h"
#include "connectivity/connectivity_hash.h"
#include "connectivity/order_coder.h"
#include "connectivity/valence_section.h"
#include "container/framing.h"

namespace gab {

namespace {

Status corrupt(const std::string& what) { return Status::Error(StatusCode::kParseError, what); }

}  // namespace

Status code_connectivity(int32_t n, const std::vector<int32_t>& triangles, bool reorder, CodedConnectivity* coded) {
  const int32_t t = static_cast<int32_t>(triangles.size() / 3);
  ValenceSection section = encode_valence_section(n, triangles);
  if (section.walked > walk_budget(4 * static_cast<int64_t>(t))) {
    return Status::Error(StatusCode::kResourceExhausted,
                         "connectivity: the valence coder's traversal would walk " + std::to_string(section.walked) +
                             " list steps, more than a decoder accepts (" +
                             std::to_string(walk_budget(4 * static_cast<int64_t>(t))) + ")");
  }
  coded->valence = section.bytes;
  std::vector<int32_t> traversal;  // the triangles in traversal numbering
  GAB_RETURN_IF_ERROR(decode_valence_section(section.bytes.data(), section.bytes.size(), n, t, &traversal));
  coded->order.clear();
  if (reorder) {
    coded->triangles = std::move(traversal);
    coded->new_index = std::move(section.new_index);
    return Status::Ok();
  }
  std::vector<int32_t> original(static_cast<size_t>(n));
  for (int32_t v = 0; v < n; ++v) original[section.new_index[v]] = v;
  coded->order = encode_vertex_order(n, traversal, original);
  coded->triangles.resize(traversal.size());
  for (size_t i = 0; i < traversal.size(); ++i) coded->triangles[i] = original[traversal[i]];
  coded->new_index.clear();
  return Status::Ok();
}

void write_connectivity_section(const Mesh& mesh, const GabHeader& header, const CodedConnectivity& coded,
                                ByteWriter* out) {
  if (header.geometry_only()) {
    out->u64(connectivity_hash(mesh.num_vertices(), mesh.triangles));
    return;
  }
  write_framed(coded.valence.data(), coded.valence.size(), out);
  if (!header.reordered()) write_framed(coded.order.data(), coded.order.size(), out);
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
  if (header.keeps_coded_order()) {
    const size_t before = in->offset();
    switch (read_framed(in, &section->order, &section->order_size)) {
      case FrameRead::kTruncated: return corrupt("file ends inside the vertex order block");
      case FrameRead::kCorrupt: return corrupt("vertex order block is corrupt (checksum mismatch)");
      case FrameRead::kOk: break;
    }
    section->order_bytes = in->offset() - before;
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
  const int32_t n = header.num_vertices, t = header.num_triangles;
  std::vector<int32_t> traversal;
  const Status s = decode_valence_section(section.block, section.size, n, t, &traversal);
  if (!s.ok()) return corrupt("connectivity block: " + s.message());
  if (!header.keeps_coded_order()) {
    *triangles = std::move(traversal);
    return Status::Ok();
  }
  std::vector<int32_t> original;
  const Status o = decode_vertex_order(section.order, section.order_size, n, traversal, &original);
  if (!o.ok()) return corrupt(o.message());
  triangles->resize(traversal.size());
  for (size_t i = 0; i < traversal.size(); ++i) (*triangles)[i] = original[traversal[i]];
  return Status::Ok();
}

}  // namespace gab
