#include "gab/codec/decoder.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "anchor_chunk.h"
#include "refinement_chunk.h"
#include "gab/codec/connectivity_coder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/relaxed_reconstruction.h"

namespace gab {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

Status corrupt(const std::string& what) { return Status::Error(StatusCode::kParseError, what); }

// The connectivity section, checked but not decoded: the hash of a
// geometry-only file, or the framed block.
Status read_connectivity_section(ByteReader* in, const GabHeader& header, uint64_t* hash, const uint8_t** block,
                                 size_t* size) {
  if (header.geometry_only()) {
    if (!in->u64(hash)) return corrupt("file ends inside the connectivity hash");
    return Status::Ok();
  }
  switch (read_framed(in, block, size)) {
    case FrameRead::kTruncated: return corrupt("file ends inside the connectivity block");
    case FrameRead::kCorrupt: return corrupt("connectivity block is corrupt (checksum mismatch)");
    case FrameRead::kOk: break;
  }
  return Status::Ok();
}

// The connectivity: decoded from the block, or taken from the mesh the
// caller supplies for a geometry-only file (after checking its hash).
Status read_connectivity(ByteReader* in, const GabHeader& header, const DecodeOptions& options,
                         std::vector<int32_t>* triangles) {
  uint64_t hash = 0;
  const uint8_t* block = nullptr;
  size_t size = 0;
  GAB_RETURN_IF_ERROR(read_connectivity_section(in, header, &hash, &block, &size));
  if (header.geometry_only()) {
    if (!options.connectivity) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "this file holds geometry only: give the mesh it was made from (--connectivity MESH)");
    }
    const Mesh& m = *options.connectivity;
    if (m.num_vertices() != header.num_vertices || m.num_triangles() != header.num_triangles ||
        connectivity_hash(m.num_vertices(), m.triangles) != hash) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "the connectivity mesh is not the one this file was made from (" +
                               std::to_string(m.num_vertices()) + " vertices, " + std::to_string(m.num_triangles()) +
                               " triangles; the file expects " + std::to_string(header.num_vertices) + " and " +
                               std::to_string(header.num_triangles) + ", and a matching hash)");
    }
    *triangles = m.triangles;
    return Status::Ok();
  }
  Status s = decode_connectivity(block, size, header.num_vertices, header.num_triangles, triangles);
  if (!s.ok()) return corrupt("connectivity block: " + s.message());
  return Status::Ok();
}

// Entries of the lower triangle of L^T L: at most sum over vertices of
// (2-ring size), bounded by sum (1 + d + sum of neighbour degrees).
int64_t matrix_entries_bound(const EdgeGraph& g) {
  int64_t total = 0;
  for (int32_t v = 0; v < g.num_vertices(); ++v) {
    total += 1;
    for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) {
      const int32_t u = g.neighbors[p];
      total += 1 + (g.offsets[u + 1] - g.offsets[u]);
    }
  }
  return total;
}

}  // namespace

Status decode_mesh(const uint8_t* data, size_t size, const DecodeOptions& options, Mesh* mesh, DecodeStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  *stats = DecodeStats();
  ByteReader in(data, size);
  GabHeader header;
  GAB_RETURN_IF_ERROR(read_gab_header(&in, size, &header));
  const int32_t n = header.num_vertices;
  stats->num_vertices = n;
  stats->num_triangles = header.num_triangles;
  stats->anchors_in_file = header.anchors;
  stats->chunks_in_file = header.chunks;
  stats->bits = header.bits;
  stats->weight = header.weight;
  stats->geometry_only = header.geometry_only();

  Mesh out;
  GAB_RETURN_IF_ERROR(read_connectivity(&in, header, options, &out.triangles));
  out.positions.assign(static_cast<size_t>(n) * 3, 0.0);
  const EdgeGraph graph = build_edge_graph(out);
  if (matrix_entries_bound(graph) > options.max_matrix_entries) {
    return corrupt("connectivity is too irregular: its least-squares matrix would exceed " +
                   std::to_string(options.max_matrix_entries) + " entries");
  }

  AnchorModels models;
  AnchorChunkCoder coder(header.quantizer, &models);
  std::vector<char> anchored(n, 0);
  RelaxedReconstruction rec;
  rec.set_threads(options.threads);
  std::vector<double> shape;
  const int32_t wanted = options.max_anchors >= 0 ? std::min(options.max_anchors, header.anchors) : header.anchors;
  const int32_t anchor_chunks = header.anchor_chunks();
  std::vector<int32_t> file_grid;  // every decoded anchor's grid indices, in file order
  int32_t decoded = 0;
  for (int32_t chunk = 0; chunk < anchor_chunks && (chunk == 0 || decoded < wanted); ++chunk) {
    if (options.progress) options.progress(chunk, header.chunks);
    const uint8_t* payload = nullptr;
    size_t payload_size = 0;
    const FrameRead frame = read_framed(&in, &payload, &payload_size);
    if (frame == FrameRead::kTruncated) {
      if (chunk == 0) return corrupt("file ends inside chunk 0: no shape to show");
      stats->truncated = true;
      break;
    }
    if (frame == FrameRead::kCorrupt) {
      return corrupt("chunk " + std::to_string(chunk) + " is corrupt (checksum mismatch)");
    }
    // Chunk 0 is decoded whole (it anchors every component); later ones up
    // to the anchors wanted.
    std::vector<int32_t> anchors, grid;
    int32_t in_chunk = 0;
    Status s = coder.decode(payload, payload_size, anchored, chunk == 0 ? nullptr : shape.data(),
                            chunk == 0 ? -1 : wanted - decoded, &anchors, &grid, &in_chunk);
    if (!s.ok()) return corrupt("chunk " + std::to_string(chunk) + ": " + s.message());
    if (in_chunk > header.anchors - decoded || (chunk + 1 == anchor_chunks && in_chunk != header.anchors - decoded)) {
      return corrupt("chunk " + std::to_string(chunk) + " holds " + std::to_string(in_chunk) +
                     " anchors, which does not add up to the header's " + std::to_string(header.anchors));
    }
    std::vector<double> coefficients(grid.size());
    for (size_t i = 0; i < anchors.size(); ++i) {
      for (int c = 0; c < 3; ++c) coefficients[3 * i + c] = header.quantizer.dequantize(grid[3 * i + c], c);
    }
    const auto t = std::chrono::steady_clock::now();
    if (chunk == 0) {
      s = rec.init(graph, header.weight, anchors, coefficients);
      if (!s.ok()) return corrupt("chunk 0: " + s.message());
      if (rec.cholesky().symbolic().stored_L > options.max_factor_entries) {
        return corrupt("the factor would exceed " + std::to_string(options.max_factor_entries) + " entries");
      }
      stats->factor_s += seconds_since(t);
    } else {
      bool refactor = false;
      s = rec.add_anchors_cheapest(anchors, coefficients, &refactor);
      if (!s.ok()) return corrupt("chunk " + std::to_string(chunk) + ": " + s.message());
      (refactor ? stats->factor_s : stats->update_s) += seconds_since(t);
      stats->refactorizations += refactor ? 1 : 0;
    }
    for (int32_t v : anchors) anchored[v] = 1;
    file_grid.insert(file_grid.end(), grid.begin(), grid.end());
    decoded += static_cast<int32_t>(anchors.size());
    stats->chunks = chunk + 1;
    if (chunk + 1 < anchor_chunks && decoded < wanted) {  // the next chunk's prediction
      const auto t_solve = std::chrono::steady_clock::now();
      GAB_RETURN_IF_ERROR(rec.reconstruct(&shape));
      stats->solve_s += seconds_since(t_solve);
    }
  }
  // The refinement belongs to the whole anchor set: skipped for a level of
  // detail; a file cut inside it still gives the unrefined shape.
  if (header.refined() && !stats->truncated && decoded == header.anchors) {
    const uint8_t* payload = nullptr;
    size_t payload_size = 0;
    const FrameRead frame = read_framed(&in, &payload, &payload_size);
    const std::string name = "refinement (chunk " + std::to_string(anchor_chunks) + ")";
    if (frame == FrameRead::kCorrupt) return corrupt(name + " is corrupt (checksum mismatch)");
    if (frame == FrameRead::kTruncated) {
      stats->truncated = true;
    } else {
      std::vector<int32_t> deltas;
      Status s = decode_refinement(payload, payload_size, decoded, header.quantizer.max_index, &deltas);
      if (!s.ok()) return corrupt(name + ": " + s.message());
      std::vector<double> coefficients(deltas.size());
      for (size_t i = 0; i < deltas.size(); ++i) {
        const int64_t value = int64_t{file_grid[i]} + deltas[i];
        if (value < 0 || value > header.quantizer.max_index) {
          return corrupt(name + ": anchor #" + std::to_string(i / 3) + " is moved off the grid");
        }
        coefficients[i] = header.quantizer.dequantize(static_cast<int32_t>(value), static_cast<int>(i % 3));
      }
      GAB_RETURN_IF_ERROR(rec.set_coefficients(0, coefficients));
      stats->refined = true;
      stats->chunks = anchor_chunks + 1;
    }
  }
  const auto t_solve = std::chrono::steady_clock::now();
  GAB_RETURN_IF_ERROR(rec.reconstruct(&shape));
  stats->solve_s += seconds_since(t_solve);
  if (!stats->truncated && decoded == header.anchors && in.remaining() != 0) {
    return corrupt("trailing bytes after the last chunk");
  }
  out.positions = shape;
  *mesh = std::move(out);
  stats->anchors = decoded;
  stats->decode_s = seconds_since(start);
  return Status::Ok();
}

Status read_gab_info(const uint8_t* data, size_t size, GabFileInfo* info) {
  *info = GabFileInfo();
  ByteReader in(data, size);
  GabHeader header;
  GAB_RETURN_IF_ERROR(read_gab_header(&in, size, &header));
  info->version = header.version;
  info->num_vertices = header.num_vertices;
  info->num_triangles = header.num_triangles;
  info->bits = header.bits;
  info->weight = header.weight;
  info->geometry_only = header.geometry_only();
  info->refined = header.refined();
  for (int c = 0; c < 3; ++c) info->box_min[c] = header.quantizer.min[c];
  info->step = header.quantizer.step;
  info->anchors = header.anchors;
  info->chunks = header.chunks;
  info->bytes = size;
  const size_t before = in.offset();
  uint64_t hash = 0;
  const uint8_t* block = nullptr;
  size_t block_size = 0;
  GAB_RETURN_IF_ERROR(read_connectivity_section(&in, header, &hash, &block, &block_size));
  info->connectivity_bytes = in.offset() - before;
  for (int32_t chunk = 0; chunk < header.chunks; ++chunk) {
    const size_t at = in.offset();
    const uint8_t* payload = nullptr;
    size_t payload_size = 0;
    const FrameRead frame = read_framed(&in, &payload, &payload_size);
    if (frame == FrameRead::kTruncated) {
      info->truncated = true;
      break;
    }
    if (frame == FrameRead::kCorrupt) return corrupt("chunk " + std::to_string(chunk) + " is corrupt (checksum mismatch)");
    ByteReader chunk_in(payload, payload_size);
    uint64_t count = 0;
    const bool refinement = chunk == header.anchor_chunks();
    if (!chunk_in.varint(&count) || (refinement ? count != static_cast<uint64_t>(header.anchors)
                                                : count < 1 || count > static_cast<uint64_t>(header.anchors))) {
      return corrupt("chunk " + std::to_string(chunk) + ": anchor count out of range");
    }
    if (refinement) {
      info->refinement_bytes = in.offset() - at;
      info->chunks_present = chunk + 1;
      continue;
    }
    info->chunk_bytes.push_back(in.offset() - at);
    info->chunk_anchors.push_back(static_cast<int32_t>(count));
    info->chunks_present = chunk + 1;
  }
  if (!info->truncated && in.remaining() != 0) return corrupt("trailing bytes after the last chunk");
  info->geometry_bytes = size - info->connectivity_bytes;
  return Status::Ok();
}

}  // namespace gab
