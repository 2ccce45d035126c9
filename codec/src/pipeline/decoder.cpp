// The decoder: a short driver over the codec's layers, in the order the
// encoder wrote them (encoder.cpp):
//   header (container/gab_header.h) -> connectivity section (connectivity/)
//   -> the anchor chunks of the file's layout (anchors/anchor_chunk.h, anchor_levels.h),
//      each joining the reconstruction as it arrives
//   -> the refinement chunk (anchors/refinement_chunk.h) -> the anchors' shape
//   -> the detail chunk (detail/detail_chunk.h), predicted from that shape
//   -> the trailing sections (container/trailing_sections.h): the attributes
//      (attributes/attribute_section.h), decoded for any level of detail.
#include "gab/codec/decoder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "anchors/anchor_chunk.h"
#include "anchors/anchor_levels.h"
#include "anchors/quantizer.h"
#include "anchors/refinement_chunk.h"
#include "attributes/attribute_section.h"
#include "attributes/corner_table.h"
#include "connectivity/connectivity_section.h"
#include "container/framing.h"
#include "container/gab_header.h"
#include "container/trailing_sections.h"
#include "detail/detail_chunk.h"
#include "gab/mesh/edge_graph.h"
#include "pipeline/ordering_choice.h"
#include "reconstruction/iterative_tuning.h"
#include "reconstruction/shape_operator.h"

namespace gab {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

Status corrupt(const std::string& what) { return Status::Error(StatusCode::kParseError, what); }

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

// What a decode holds at its peak, per factor entry (values, supernode
// structure, update workspace), matrix entry, vertex (positions, graph,
// right-hand sides, solutions) and triangle: measured peaks of igea, horse
// and a 90,000-vertex torus lie 0-17% under it (docs/tuning-codec.md).
constexpr int64_t kBytesPerFactorEntry = 11;
constexpr int64_t kBytesPerMatrixEntry = 12;
constexpr int64_t kBytesPerVertex = 150;
constexpr int64_t kBytesPerTriangle = 12;
// The iterative operator's vectors (IterativeReconstruction: five of 3
// doubles per vertex and its bookkeeping), instead of a matrix and a factor.
constexpr int64_t kBytesPerIterativeVertex = 160;

// The budget options give a file of `size` bytes (INT64_MAX: none).
int64_t memory_budget(const DecodeOptions& options, size_t size) {
  if (options.max_memory < 0) return INT64_MAX;
  if (options.max_memory > 0) return options.max_memory;
  const int64_t by_size = static_cast<int64_t>(std::min<size_t>(size, size_t{1} << 40)) * kDecodeMemoryPerFileByte;
  return std::max(kMinDecodeMemory, by_size);
}

int64_t mebibytes(int64_t bytes) { return (bytes + (int64_t{1} << 20) - 1) >> 20; }

// kResourceExhausted when `needed` bytes exceed the budget.
Status check_memory(int64_t needed, int64_t budget, const std::string& what) {
  if (needed <= budget) return Status::Ok();
  return Status::Error(StatusCode::kResourceExhausted,
                       "decoding needs about " + std::to_string(mebibytes(needed)) + " MiB (" + what +
                           "), over its memory limit of " + std::to_string(mebibytes(budget)) +
                           " MiB: raise it (DecodeOptions::max_memory, gab decompress --max-memory)");
}

// What the chunk loops build: the reconstruction, the shape that predicts
// the next chunk, every decoded anchor's grid indices in file order.
struct ChunkDecoding {
  ChunkDecoding(const GabHeader& h, const EdgeGraph& g, const DecodeOptions& o, DecodeStats* s)
      : header(h), quantizer(Quantizer::from_grid(h.box_min, h.step, h.bits)), graph(g), options(o), stats(s),
        rec(h.reconstruction) {
    wanted = o.max_anchors >= 0 ? std::min(o.max_anchors, h.anchors) : h.anchors;
  }
  const GabHeader& header;
  const Quantizer quantizer;
  const EdgeGraph& graph;
  const DecodeOptions& options;
  DecodeStats* stats;
  int32_t wanted = 0;  // anchors to decode (level of detail)
  ShapeOperator rec;
  std::vector<double> shape;
  std::vector<int32_t> file_grid;
  int32_t decoded = 0;
};

// Reads chunk `chunk`'s frame: kOk, or a truncation past chunk 0 (sets
// stats->truncated, *payload null); an error otherwise.
Status read_chunk_frame(ByteReader* in, int32_t chunk, ChunkDecoding* st, const uint8_t** payload, size_t* size) {
  if (st->options.progress) st->options.progress(chunk, st->header.chunks);
  *payload = nullptr;
  const FrameRead frame = read_framed(in, payload, size);
  if (frame == FrameRead::kTruncated) {
    if (chunk == 0) return corrupt("file ends inside chunk 0: no shape to show");
    st->stats->truncated = true;
    *payload = nullptr;
    return Status::Ok();
  }
  if (frame == FrameRead::kCorrupt) return corrupt("chunk " + std::to_string(chunk) + " is corrupt (checksum mismatch)");
  return Status::Ok();
}

// Operator 3's parameters at the head of chunk 0's payload: set on the
// reconstruction, the payload advanced past them.
Status read_operator_tuning(ChunkDecoding* st, const uint8_t** payload, size_t* size) {
  if (st->header.reconstruction != kGabReconstructionIterativeTuned) return Status::Ok();
  IterativeTuning tuning;
  size_t offset = 0;
  const Status s = parse_iterative_tuning(*payload, *size, &tuning, &offset);
  if (!s.ok()) return corrupt("chunk 0: " + s.message());
  GAB_RETURN_IF_ERROR(st->rec.set_tuning(tuning));
  *payload += offset;
  *size -= offset;
  return Status::Ok();
}

// Anchors `anchors` of chunk `chunk` at grid indices `grid` (3 each) join
// the reconstruction (chunk 0 factors it); then, if `predict` (the
// selection layout, another chunk following), the prediction at every
// vertex (that chunk's are not known before it is decoded; the level layout
// predicts each level at its own vertices). `nearest`, when given, is the
// nearest-anchor map after these anchors (ShapeOperator::init).
Status add_chunk(int32_t chunk, const std::vector<int32_t>& anchors, const std::vector<int32_t>& grid, bool predict,
                 ChunkDecoding* st, const std::vector<uint64_t>* nearest = nullptr) {
  const Quantizer& q = st->quantizer;
  std::vector<double> coefficients(grid.size());
  for (size_t i = 0; i < anchors.size(); ++i) {
    for (int c = 0; c < 3; ++c) coefficients[3 * i + c] = q.dequantize(grid[3 * i + c], c);
  }
  const auto t = std::chrono::steady_clock::now();
  if (chunk == 0) {
    const Status s = st->rec.init(st->graph, st->header.weight, anchors, coefficients, nearest);
    // The factor is over max_factor_entries (kResourceExhausted), or its
    // memory cannot be had (kOutOfMemory): the caller's limits, not the
    // file's fault, so the code goes through unchanged.
    if (s.code() == StatusCode::kResourceExhausted || s.code() == StatusCode::kOutOfMemory) return s;
    if (!s.ok()) return corrupt("chunk 0: " + s.message());
    st->stats->factor_s += seconds_since(t);
    if (st->rec.relaxed()) st->stats->factor_entries = st->rec.relaxed()->cholesky().symbolic().stored_L;
  } else {
    bool refactor = false;
    const Status s = st->rec.add_anchors(anchors, coefficients, &refactor, nearest);
    if (!s.ok()) return corrupt("chunk " + std::to_string(chunk) + ": " + s.message());
    (refactor ? st->stats->factor_s : st->stats->update_s) += seconds_since(t);
    st->stats->refactorizations += refactor ? 1 : 0;
  }
  st->file_grid.insert(st->file_grid.end(), grid.begin(), grid.end());
  st->decoded += static_cast<int32_t>(anchors.size());
  st->stats->chunks = chunk + 1;
  if (predict) {
    const auto t_solve = std::chrono::steady_clock::now();
    GAB_RETURN_IF_ERROR(st->rec.prediction(nullptr, &st->shape));
    st->stats->solve_s += seconds_since(t_solve);
  }
  return Status::Ok();
}

// The first layout: each chunk its anchors' subset and positions.
Status decode_selection_chunks(ByteReader* in, AnchorChunkCoder* coder, ChunkDecoding* st) {
  const GabHeader& header = st->header;
  const int32_t anchor_chunks = header.anchor_chunks();
  std::vector<char> anchored(header.num_vertices, 0);
  for (int32_t chunk = 0; chunk < anchor_chunks && (chunk == 0 || st->decoded < st->wanted); ++chunk) {
    const uint8_t* payload = nullptr;
    size_t payload_size = 0;
    GAB_RETURN_IF_ERROR(read_chunk_frame(in, chunk, st, &payload, &payload_size));
    if (!payload) break;
    if (chunk == 0) GAB_RETURN_IF_ERROR(read_operator_tuning(st, &payload, &payload_size));
    // Chunk 0 is decoded whole (it anchors every component); later ones up
    // to the anchors wanted.
    std::vector<int32_t> anchors, grid;
    int32_t in_chunk = 0;
    const Status s = coder->decode(payload, payload_size, anchored, chunk == 0 ? nullptr : st->shape.data(),
                                   chunk == 0 ? -1 : st->wanted - st->decoded, &anchors, &grid, &in_chunk);
    if (!s.ok()) return corrupt("chunk " + std::to_string(chunk) + ": " + s.message());
    if (in_chunk > header.anchors - st->decoded ||
        (chunk + 1 == anchor_chunks && in_chunk != header.anchors - st->decoded)) {
      return corrupt("chunk " + std::to_string(chunk) + " holds " + std::to_string(in_chunk) +
                     " anchors, which does not add up to the header's " + std::to_string(header.anchors));
    }
    for (int32_t v : anchors) anchored[v] = 1;
    const bool more = chunk + 1 < anchor_chunks && st->decoded + static_cast<int32_t>(anchors.size()) < st->wanted;
    GAB_RETURN_IF_ERROR(add_chunk(chunk, anchors, grid, more, st));
  }
  return Status::Ok();
}

// The level layout: chunk 0 the spread set and the rest's subset, then one
// level's positions per chunk, the levels worked out here (anchor_levels.h).
Status decode_level_chunks(ByteReader* in, AnchorChunkCoder* coder, ChunkDecoding* st) {
  const GabHeader& header = st->header;
  const uint8_t* payload = nullptr;
  size_t payload_size = 0;
  GAB_RETURN_IF_ERROR(read_chunk_frame(in, 0, st, &payload, &payload_size));
  GAB_RETURN_IF_ERROR(read_operator_tuning(st, &payload, &payload_size));
  LevelPlan plan;
  size_t offset = 0;
  Status s = parse_level_plan(payload, payload_size, header.anchors, header.anchor_chunks(), &plan, &offset);
  if (!s.ok()) return corrupt("chunk 0: " + s.message());
  std::vector<int32_t> spread, grid, rest;
  s = coder->decode_level_head(payload + offset, payload_size - offset, header.num_vertices, plan, &spread, &grid,
                               &rest);
  if (!s.ok()) return corrupt("chunk 0: " + s.message());
  const std::vector<int32_t> sizes = plan.level_sizes();
  // The levels a level of detail reaches, and those of them that need
  // farthest-point picks (the last level is what the picks leave).
  size_t needed = 0;
  int64_t end = plan.spread;
  while (needed < sizes.size() && end < st->wanted) end += sizes[needed++];
  const size_t picked = std::min(needed, sizes.empty() ? 0 : sizes.size() - 1);
  // With a second thread the picks are made beside chunk 0's set-up and the
  // first levels' decoding. Either way the picks' search hands the
  // reconstruction its nearest anchors (no search of its own).
  LevelPicks level_picks;
  const std::vector<int32_t> picked_sizes(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(picked));
  GAB_RETURN_IF_ERROR(level_picks.start(st->graph, spread, rest, picked_sizes, st->options.threads > 1));
  std::vector<uint64_t> nearest;
  GAB_RETURN_IF_ERROR(add_chunk(0, spread, grid, false, st, level_picks.nearest_before(0, &nearest) ? &nearest : nullptr));
  LevelMembers members(level_picks.order(), rest, header.num_vertices);
  for (size_t k = 0; k < needed; ++k) {
    const int32_t chunk = static_cast<int32_t>(k + 1);
    GAB_RETURN_IF_ERROR(read_chunk_frame(in, chunk, st, &payload, &payload_size));
    if (!payload) break;
    if (k < picked && !level_picks.wait(k)) {
      return corrupt("chunk " + std::to_string(chunk) + ": the level's farthest-point picks fell short");
    }
    std::vector<int32_t> level = members.next(sizes, k);
    const bool whole = static_cast<int32_t>(level.size()) <= st->wanted - st->decoded;
    if (!whole) level.resize(st->wanted - st->decoded);
    const auto t_solve = std::chrono::steady_clock::now();
    GAB_RETURN_IF_ERROR(st->rec.prediction(&level, &st->shape));
    st->stats->solve_s += seconds_since(t_solve);
    s = coder->decode_level(payload, payload_size, level, st->shape.data(), st->graph, &grid);
    if (!s.ok()) return corrupt("chunk " + std::to_string(chunk) + ": " + s.message());
    const bool map = k < picked && whole && level_picks.nearest_before(k + 1, &nearest);
    GAB_RETURN_IF_ERROR(add_chunk(chunk, level, grid, false, st, map ? &nearest : nullptr));
  }
  return Status::Ok();
}

// The refinement chunk (the whole anchor set decoded): moves every anchor's
// coefficient; a file cut inside it leaves the unrefined shape (truncated).
Status apply_refinement(ByteReader* in, ChunkDecoding* st) {
  const int32_t chunk = st->header.refinement_chunk();
  const std::string name = "refinement (chunk " + std::to_string(chunk) + ")";
  const uint8_t* payload = nullptr;
  size_t payload_size = 0;
  const FrameRead frame = read_framed(in, &payload, &payload_size);
  if (frame == FrameRead::kCorrupt) return corrupt(name + " is corrupt (checksum mismatch)");
  if (frame == FrameRead::kTruncated) {
    st->stats->truncated = true;
    return Status::Ok();
  }
  std::vector<double> coefficients;
  const Status s = decode_refinement_chunk(payload, payload_size, st->file_grid, st->quantizer, &coefficients);
  if (!s.ok()) return corrupt(name + ": " + s.message());
  GAB_RETURN_IF_ERROR(st->rec.set_coefficients(0, coefficients));
  st->stats->refined = true;
  st->stats->chunks = chunk + 1;
  return Status::Ok();
}

// The detail chunk over the anchors' shape `smooth`: *positions the
// detailed shape (stats->detail set), or left alone when the file ends
// inside the chunk (truncated).
Status apply_detail(ByteReader* in, const GabHeader& header, const Mesh& mesh, const EdgeGraph& graph,
                    const std::vector<double>& smooth, std::vector<double>* positions, DecodeStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const std::string name = "detail (chunk " + std::to_string(header.detail_chunk()) + ")";
  const uint8_t* payload = nullptr;
  size_t payload_size = 0;
  const FrameRead frame = read_framed(in, &payload, &payload_size);
  if (frame == FrameRead::kCorrupt) return corrupt(name + " is corrupt (checksum mismatch)");
  if (frame == FrameRead::kTruncated) {
    stats->truncated = true;
    return Status::Ok();
  }
  const DetailTopology topo = build_detail_topology(header.num_vertices, mesh.triangles, graph);
  const Status s = decode_detail_chunk(payload, payload_size, topo, detail_frame_of(header), smooth, positions);
  if (s.code() == StatusCode::kUnsupported) return s;
  if (!s.ok()) return corrupt(name + ": " + s.message());
  stats->detail = true;
  stats->chunks = header.detail_chunk() + 1;
  stats->detail_s = seconds_since(start);
  return Status::Ok();
}

// The trailing sections of a file whose chunks start at `chunks_start`:
// every chunk frame is walked again (a level of detail stops reading them
// early) to reach them, and each attribute section decoded onto `mesh`
// (normals predicted from the surface only when `whole_shape`: skipped
// otherwise, as sections this build cannot decode). A file that ends (or is
// damaged, for a level of detail that did not need the chunk) before them
// has no attributes.
Status decode_sections(const uint8_t* data, size_t size, size_t chunks_start, const GabHeader& header,
                       bool whole_shape, Mesh* mesh, DecodeStats* stats) {
  ByteReader in(data + chunks_start, size - chunks_start);
  for (int32_t i = 0; i < header.chunks; ++i) {
    const uint8_t* payload = nullptr;
    size_t payload_size = 0;
    // A chunk a level of detail did not need may be cut off or damaged: the
    // shape stands (as before the sections existed), without attributes.
    if (read_framed(&in, &payload, &payload_size) != FrameRead::kOk) return Status::Ok();
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<TrailingSection> sections;
  GAB_RETURN_IF_ERROR(read_trailing_sections(&in, header.sections, &sections, &stats->truncated));
  CornerTable table;
  for (size_t i = 0; i < sections.size(); ++i) {
    const TrailingSection& section = sections[i];
    const int32_t index = static_cast<int32_t>(i);
    if (section.kind != kGabSectionAttribute) {
      GAB_RETURN_IF_ERROR(check_unknown_section(section, index));
      ++stats->skipped_sections;
      continue;
    }
    if (mesh->attributes.size() >= static_cast<size_t>(kMaxMeshAttributes)) {
      return corrupt("more than " + std::to_string(kMaxMeshAttributes) + " attribute sections");
    }
    if (table.triangles == nullptr) table = build_corner_table(header.num_vertices, mesh->triangles);
    MeshAttribute attribute;
    const Status s = decode_attribute_section(section.payload, section.size, table,
                                              whole_shape ? &mesh->positions : nullptr, &attribute);
    if (s.code() == StatusCode::kUnsupported) {
      GAB_RETURN_IF_ERROR(check_unknown_section(section, index));
      ++stats->skipped_sections;
      continue;
    }
    if (!s.ok()) return corrupt("section " + std::to_string(i) + ": " + s.message());
    mesh->attributes.push_back(std::move(attribute));
  }
  stats->attributes_s = seconds_since(start);
  return Status::Ok();
}

}  // namespace

Status decode_mesh(const uint8_t* data, size_t size, const DecodeOptions& options, Mesh* mesh, DecodeStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  *stats = DecodeStats();
  GAB_RETURN_IF_ERROR(check_codec_ordering(options.ordering));
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
  stats->reordered = header.reordered();
  const int64_t budget = memory_budget(options, size);
  stats->memory_limit = budget == INT64_MAX ? 0 : budget;
  int64_t held = kBytesPerVertex * n + kBytesPerTriangle * header.num_triangles;
  const std::string mesh_size =
      std::to_string(n) + " vertices, " + std::to_string(header.num_triangles) + " triangles";
  GAB_RETURN_IF_ERROR(check_memory(held, budget, mesh_size));

  Mesh out;
  ConnectivitySection connectivity;
  GAB_RETURN_IF_ERROR(read_connectivity_section(&in, header, &connectivity));
  const size_t chunks_start = in.offset();
  const auto connectivity_start = std::chrono::steady_clock::now();
  GAB_RETURN_IF_ERROR(decode_connectivity_section(connectivity, header, options.connectivity, &out.triangles));
  stats->connectivity_s = seconds_since(connectivity_start);
  // The positions come with the final shape: not zero-filled through the
  // decode beside its work (the decode's peak).
  const EdgeGraph graph = build_edge_graph(n, out.triangles);
  const bool factored = header.reconstruction == kGabReconstructionGlobal;
  stats->solver = solver_of_header(header.reconstruction);
  if (!factored) {
    held += kBytesPerIterativeVertex * n;
    GAB_RETURN_IF_ERROR(check_memory(held, budget, mesh_size));
  }
  stats->matrix_entries = factored ? matrix_entries_bound(graph) : 0;
  if (stats->matrix_entries > options.max_matrix_entries) {
    return Status::Error(StatusCode::kResourceExhausted,
                         "connectivity is too irregular: its least-squares matrix would exceed " +
                             std::to_string(options.max_matrix_entries) + " entries");
  }
  held += kBytesPerMatrixEntry * stats->matrix_entries;
  GAB_RETURN_IF_ERROR(check_memory(held, budget,
                                   std::to_string(n) + " vertices and a matrix of " +
                                       std::to_string(stats->matrix_entries) + " entries"));
  // What is left of the budget bounds the factor, checked by its symbolic
  // analysis before any of it is allocated.
  const int64_t factor_entries =
      budget == INT64_MAX ? options.max_factor_entries
                          : std::min(options.max_factor_entries, (budget - held) / kBytesPerFactorEntry);

  AnchorModels models;
  ChunkDecoding state(header, graph, options, stats);
  AnchorChunkCoder coder(state.quantizer, &models);
  state.rec.set_threads(options.threads);
  state.rec.set_max_factor_entries(factor_entries);
  stats->ordering = decoder_ordering(options.ordering, header.ordering);
  state.rec.apply(OrderingPlan(stats->ordering));
  const Status chunks =
      header.levels() ? decode_level_chunks(&in, &coder, &state) : decode_selection_chunks(&in, &coder, &state);
  // Analysed, even when refused.
  const int64_t wanted = factored ? state.rec.relaxed()->cholesky().symbolic().stored_L : 0;
  if (chunks.code() == StatusCode::kResourceExhausted && wanted > factor_entries &&
      factor_entries < options.max_factor_entries) {
    // The budget, not the caller's factor limit, refused the factor.
    return check_memory(held + kBytesPerFactorEntry * wanted, budget,
                        "a factor of " + std::to_string(wanted) + " entries");
  }
  GAB_RETURN_IF_ERROR(chunks);
  // The refinement and the detail belong to the whole anchor set: skipped for a level of detail.
  const bool whole = state.decoded == header.anchors;
  if (header.refined() && !stats->truncated && whole) {
    GAB_RETURN_IF_ERROR(apply_refinement(&in, &state));
  }
  std::vector<double>().swap(state.shape);  // the last prediction: not beside the final shape's work
  const auto t_solve = std::chrono::steady_clock::now();
  GAB_RETURN_IF_ERROR(state.rec.shape(&out.positions));
  stats->solve_s += seconds_since(t_solve);
  const bool detail = header.detail() && options.detail && !stats->truncated && whole;
  if (detail) {
    std::vector<double> detailed;
    GAB_RETURN_IF_ERROR(apply_detail(&in, header, out, graph, out.positions, &detailed, stats));
    if (stats->detail) out.positions.swap(detailed);
  }
  // Normals predicted from the surface need the shape the encoder had: every anchor, refined and detailed
  // as the file says.
  const bool whole_shape = whole && !stats->truncated && (!header.detail() || detail) &&
                           (!header.refined() || stats->refined);
  if (!stats->truncated) GAB_RETURN_IF_ERROR(decode_sections(data, size, chunks_start, header, whole_shape, &out, stats));
  // The header bounds the grid and the weight so that every file a writer
  // makes decodes to finite coordinates; a forged one must not hand out
  // others either.
  for (double x : out.positions) {
    if (!std::isfinite(x)) return corrupt("decoded coordinates are not finite");
  }
  *mesh = std::move(out);
  stats->anchors = state.decoded;
  stats->decode_s = seconds_since(start);
  return Status::Ok();
}

}  // namespace gab
