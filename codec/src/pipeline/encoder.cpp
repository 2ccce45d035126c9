// The encoder: a short driver over the codec's layers. The connectivity is
// coded once, first (connectivity/connectivity_section.h): the geometry is
// coded on the mesh as its decoder will return it. Then, per candidate file
// (encode_candidates.h: which ones, and what each costs):
//   select anchors (anchor_selection.h: greedy loop and refinement search, no bytes)
//   -> code the anchor chunks in each layout (anchor_layouts.h), keep the smaller
//   -> the refinement chunk (anchors/refinement_chunk.h)
//   -> the detail chunk over the anchors' shape, fitted (detail_search.h, detail/detail_chunk.h)
// and, for the candidates that can still win, in the order of that estimate:
//   -> the rest of the detail search
//   -> header (container/gab_header.h), connectivity section, chunks, framed.
#include "gab/codec/encoder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "anchors/refinement_chunk.h"
#include "attributes/attribute_quantizer.h"
#include "attributes/attribute_section.h"
#include "attributes/corner_correspondence.h"
#include "attributes/corner_table.h"
#include "connectivity/connectivity_section.h"
#include "container/framing.h"
#include "container/gab_header.h"
#include "gab/codec/decoder.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "gab/mesh/renumber.h"
#include "gab/mesh/weld.h"
#include "pipeline/anchor_layouts.h"
#include "pipeline/anchor_selection.h"
#include "pipeline/detail_search.h"
#include "pipeline/encode_candidates.h"
#include "pipeline/encoder_tuning.h"
#include "pipeline/ordering_choice.h"
#include "reconstruction/iterative_tuning.h"
#include "reconstruction/shape_operator.h"

namespace gab {

namespace {

Status check_options(const EncodeOptions& o) {
  auto bad = [](const std::string& m) { return Status::Error(StatusCode::kInvalidArgument, m); };
  if (o.max_anchors <= 0 && !(o.target_rms_rel > 0) && !(o.target_linf_rel > 0)) {
    return bad("set a stopping rule: an anchor count, an RMS or an L-inf target");
  }
  if (o.max_anchors < 0) return bad("anchor count must be positive");
  if (o.target_rms_rel < 0 || o.target_linf_rel < 0 || !std::isfinite(o.target_rms_rel) ||
      !std::isfinite(o.target_linf_rel)) {
    return bad("error targets must be finite and non-negative");
  }
  if (o.bits != 0 && (o.bits < kGabMinBits || o.bits > kGabMaxBits)) {
    return bad("bits must be in " + std::to_string(kGabMinBits) + ".." + std::to_string(kGabMaxBits));
  }
  if (!(o.weight > 0) || !(o.weight <= kGabMaxMagnitude)) return bad("anchor weight must be in (0, 1e100]");
  if (!(o.batch_fraction <= 1)) return bad("batch fraction must be at most 1");
  if (o.chunk_growth > 0 && !(o.chunk_growth > 1)) return bad("chunk growth must be above 1");
  if (!std::isfinite(o.chunk_growth)) return bad("chunk growth must be finite");
  if (o.refine_iterations < 1) return bad("refinement iterations must be positive");
  if (o.solver != Solver::kAuto && o.solver != Solver::kGlobal && o.solver != Solver::kIterative) {
    return bad("unknown reconstruction operator");
  }
  if (o.solver == Solver::kIterative && o.refine) {
    return bad("the refinement chunk needs the global reconstruction operator");
  }
  const int32_t most_sweeps = IterativeReconstruction::kMostStartSweeps;
  if (o.prediction_sweeps < -1 || o.prediction_sweeps > most_sweeps || o.final_sweeps < -1 ||
      o.final_sweeps > most_sweeps) {
    return bad("sweeps must be in 0.." + std::to_string(most_sweeps) + " (or -1: the encoder's)");
  }
  if (o.final_steps16 < -1 || o.final_steps16 > kMostFinalSteps || o.final_most_steps < -1 ||
      o.final_most_steps > kMostFinalSteps) {
    return bad("final steps must be in 0.." + std::to_string(kMostFinalSteps) + " (or -1: the encoder's)");
  }
  if (o.normal_bits < 2 || o.normal_bits > kMaxNormalBits) {
    return bad("normal bits must be in 2.." + std::to_string(kMaxNormalBits));
  }
  for (int bits : {o.texcoord_bits, o.color_bits, o.generic_bits}) {
    if (bits < 1 || bits > kMaxGridBits) {
      return bad("texture coordinate, colour and generic bits must be in 1.." + std::to_string(kMaxGridBits));
    }
  }
  return check_codec_ordering(o.ordering);
}

// The mesh's box: its low and high corners, longest side and diagonal.
struct Box {
  double lo[3], hi[3];
  double extent = 0.0, diagonal = 0.0;
};

Box box_of(const Mesh& mesh) {
  Box b;
  for (int c = 0; c < 3; ++c) b.lo[c] = b.hi[c] = mesh.positions[c];
  for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
    for (int c = 0; c < 3; ++c) {
      b.lo[c] = std::min(b.lo[c], mesh.positions[3 * static_cast<size_t>(v) + c]);
      b.hi[c] = std::max(b.hi[c], mesh.positions[3 * static_cast<size_t>(v) + c]);
    }
  }
  double d2 = 0.0;
  for (int c = 0; c < 3; ++c) {
    b.extent = std::max(b.extent, b.hi[c] - b.lo[c]);
    d2 += (b.hi[c] - b.lo[c]) * (b.hi[c] - b.lo[c]);
  }
  b.diagonal = std::sqrt(d2);
  return b;
}

// Header, connectivity section, chunks; sets the byte counts.
std::vector<uint8_t> assemble_file(const GabHeader& header, const Mesh& mesh, const CodedConnectivity& coded,
                                   const std::vector<std::vector<uint8_t>>& chunks, EncodeStats* stats) {
  ByteWriter out;
  write_gab_header(header, &out);
  const size_t before_connectivity = out.size();
  write_connectivity_section(mesh, header, coded, &out);
  stats->order_bytes = header.keeps_coded_order() ? coded.order.size() + kGabFrameBytes : 0;
  stats->connectivity_bytes = out.size() - before_connectivity - stats->order_bytes;
  for (const std::vector<uint8_t>& chunk : chunks) write_framed(chunk.data(), chunk.size(), &out);
  stats->bytes = out.size();
  stats->geometry_bytes = stats->bytes - stats->connectivity_bytes - stats->order_bytes;
  return out.take();
}

// The header's operator code for o.solver (encoder.h: kAuto is the
// iterative operator unless the refinement chunk needs the global one).
uint8_t reconstruction_of(const EncodeOptions& o) {
  const bool global = o.solver == Solver::kGlobal || (o.solver == Solver::kAuto && o.refine);
  return global ? kGabReconstructionGlobal : kGabReconstructionIterativeTuned;
}

// The iterative operator's parameters: the options', else the encoder's for n vertices.
IterativeTuning tuning_of(const EncodeOptions& o, int32_t n) {
  IterativeTuning t = default_iterative_tuning(n);
  if (o.prediction_sweeps >= 0) t.prediction_sweeps = o.prediction_sweeps;
  if (o.final_sweeps >= 0) t.final_sweeps = o.final_sweeps;
  if (o.final_steps16 >= 0) t.final_steps16 = o.final_steps16;
  if (o.final_most_steps >= 0) t.final_most = o.final_most_steps;
  return t;
}

// What every candidate of one encode shares, built once.
struct EncodeContext {
  EncodeContext(const Mesh& m, const EncodeOptions& o, const CodedConnectivity& c)
      : mesh(m), options(o), coded(c), box(box_of(m)), graph(build_edge_graph(m)),
        ordering(encoder_ordering(o.ordering, m.num_vertices())), reconstruction(reconstruction_of(o)),
        tuning(tuning_of(o, m.num_vertices())) {}

  double scale() const { return box.diagonal > 0 ? 1.0 / box.diagonal : 1.0; }
  // Built for the first detail candidate.
  const DetailTopology& detail_topology() {
    if (!has_detail_topology_) detail_topology_ = build_detail_topology(mesh.num_vertices(), mesh.triangles, graph);
    has_detail_topology_ = true;
    return detail_topology_;
  }

  const Mesh& mesh;
  const EncodeOptions& options;
  const CodedConnectivity& coded;
  const Box box;
  const EdgeGraph graph;
  OrderingPlan ordering;  // its permutation remembered after the first factorization
  const uint8_t reconstruction;  // kGabReconstruction*: the operator options.solver names
  const IterativeTuning tuning;  // its parameters (operator 3)

 private:
  DetailTopology detail_topology_;
  bool has_detail_topology_ = false;
};

// The header's grid fields, ordering and reconstruction operator; the rest is set when the file is assembled.
GabHeader grid_header(const Quantizer& quantizer, int bits, Ordering ordering, uint8_t reconstruction) {
  GabHeader header;
  header.bits = bits;
  header.ordering = ordering_code(ordering);
  header.reconstruction = reconstruction;
  for (int c = 0; c < 3; ++c) header.box_min[c] = quantizer.min[c];
  header.step = quantizer.step;
  return header;
}

// A candidate after its greedy loop, its anchor chunks in the layout that
// codes smaller and its fitted detail chunk: all of the file but the rest
// of the detail search.
struct Estimate {
  EncodeCandidate candidate;
  Quantizer quantizer;
  Selection selection;
  int32_t anchors = 0;
  ChunkLayout layout;  // the anchor chunks and the refinement chunk
  bool levels = false;
  DetailChoice detail;  // the fitted detail chunk (candidate.detail)
  bool target_met = false;
  double seconds = 0;

  size_t anchor_bytes() const { return layout.bytes(); }
  size_t detail_bytes() const { return candidate.detail ? detail.chunk.size() + kGabFrameBytes : 0; }
  size_t bytes() const { return anchor_bytes() + detail_bytes(); }
};

// Everything of the candidate's file but the rest of the detail search:
// the greedy loop, the anchor chunks in the layout that codes smaller (the
// level layout unless the selection order codes smaller: it can on small
// smooth meshes, whose greedy order predicts best and whose extra levels'
// frames weigh; never on the shared meshes), the refinement chunk, the
// detail chunk at the default blend.
Status estimate(EncodeContext& ctx, const EncodeCandidate& candidate, Estimate* e) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh& mesh = ctx.mesh;
  const EncodeOptions& options = ctx.options;
  e->candidate = candidate;
  e->quantizer = Quantizer::for_box(ctx.box.lo, ctx.box.hi, candidate.anchors.bits);
  if (candidate.anchors.min_step_rel > 0) {
    e->quantizer.step = std::max(e->quantizer.step, candidate.anchors.min_step_rel * ctx.box.diagonal);
  }
  const GridPositions grid(mesh, e->quantizer);
  {
    // The selection's factor goes before the level layout's is made: at
    // 2.4M vertices each is gigabytes.
    ShapeOperator rec(ctx.reconstruction);
    GAB_RETURN_IF_ERROR(tune(ctx.tuning, &rec));
    GAB_RETURN_IF_ERROR(select_anchors(mesh, ctx.graph, candidate.anchors, options, grid, ctx.scale(), ctx.ordering,
                                       &rec, &e->selection));
    if (rec.relaxed()) ctx.ordering.remember(*rec.relaxed());
    e->anchors = rec.num_anchors();
  }
  const Selection& selection = e->selection;
  ChunkLayout in_selection_order, in_levels;
  if (options.layout != FileLayout::kLevels) in_selection_order = encode_selection_layout(selection.schedule, grid);
  const bool try_levels = options.layout != FileLayout::kSelectionOrder;
  if (try_levels) {
    const bool iterative = ctx.reconstruction != kGabReconstructionGlobal;
    const double growth = options.chunk_growth > 0
                              ? options.chunk_growth
                              : default_level_growth(selection.flops, iterative, ctx.mesh.num_vertices());
    GAB_RETURN_IF_ERROR(encode_level_layout(selection.schedule, ctx.graph, options.weight, growth, options.threads,
                                            ctx.ordering, ctx.reconstruction, ctx.tuning, grid, &in_levels));
  }
  e->levels = try_levels &&
              (options.layout == FileLayout::kLevels || in_levels.bytes() <= in_selection_order.bytes());
  e->layout = std::move(e->levels ? in_levels : in_selection_order);
  if (ctx.reconstruction == kGabReconstructionIterativeTuned) {
    prepend_iterative_tuning(ctx.tuning, &e->layout.chunks[0]);  // the head of chunk 0 (format 5.2.3)
  }
  if (selection.refined) {
    e->layout.chunks.push_back(
        encode_refinement_chunk(e->layout.file_order, selection.schedule.order, selection.refined_grid, grid.index));
  }
  if (candidate.detail) {
    // Over the decoder's shape of all the anchors: the selection's last
    // (unrefined: detail candidates never refine).
    const GabHeader header =
        grid_header(e->quantizer, candidate.anchors.bits, ctx.ordering.choice(), ctx.reconstruction);
    GAB_RETURN_IF_ERROR(fit_detail(ctx.detail_topology(), detail_frame_of(header), selection.shape, mesh,
                                   ctx.scale(), options.target_rms_rel, options.target_linf_rel, &e->detail));
    e->target_met = e->detail.met;
  } else {
    // An anchor count alone is always met.
    const double rms = selection.refined ? selection.refined_rms_rel : selection.rms_rel;
    const double linf = selection.refined ? selection.refined_linf_rel : selection.linf_rel;
    e->target_met = (options.target_rms_rel <= 0 || rms <= options.target_rms_rel) &&
                    (options.target_linf_rel <= 0 || linf <= options.target_linf_rel);
  }
  // Finishing needs of the selection its curve, and its last shape under a
  // detail chunk: the chunks' predictions go (at 2.4M vertices 58 MB each).
  std::vector<std::vector<double>>().swap(e->selection.schedule.shapes);
  if (!candidate.detail) std::vector<double>().swap(e->selection.shape);
  e->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

// The estimated candidate's file: the rest of the detail search, the
// header, the chunks. Sets every stat but candidates, encode_s and
// new_index.
Status finish(EncodeContext& ctx, Estimate* e, std::vector<uint8_t>* file, EncodeStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const Mesh& mesh = ctx.mesh;
  const EncodeOptions& options = ctx.options;
  const Selection& selection = e->selection;
  *stats = EncodeStats();
  stats->num_vertices = mesh.num_vertices();
  stats->num_triangles = mesh.num_triangles();
  stats->bits = e->candidate.anchors.bits;
  stats->ordering = ctx.ordering.choice();
  stats->solver = solver_of_header(ctx.reconstruction);
  stats->curve = selection.curve;
  stats->chunk_anchors = e->layout.chunk_anchors;
  stats->levels = e->levels;
  stats->unrefined_rms_rel = selection.rms_rel;
  stats->rms_rel = selection.refined ? selection.refined_rms_rel : selection.rms_rel;
  stats->linf_rel = selection.refined ? selection.refined_linf_rel : selection.linf_rel;
  stats->refined = selection.refined;
  if (selection.refined) stats->refinement_bytes = e->layout.chunks.back().size() + kGabFrameBytes;
  stats->target_met = e->target_met;

  std::vector<std::vector<uint8_t>> chunks = std::move(e->layout.chunks);  // the estimate is spent
  GabHeader header =
      grid_header(e->quantizer, e->candidate.anchors.bits, ctx.ordering.choice(), ctx.reconstruction);
  if (e->candidate.detail) {
    GAB_RETURN_IF_ERROR(improve_detail(ctx.detail_topology(), detail_frame_of(header), selection.shape, mesh,
                                       ctx.scale(), options.target_rms_rel, options.target_linf_rel, &e->detail));
    stats->detail = true;
    stats->detail_bytes = e->detail_bytes();
    chunks.push_back(std::move(e->detail.chunk));
    stats->detail_step_rel = e->detail.params.step / ctx.box.diagonal;
    stats->anchor_rms_rel = stats->rms_rel;
    stats->rms_rel = e->detail.rms_rel;
    stats->linf_rel = e->detail.linf_rel;
    stats->target_met = e->detail.met;
  }

  header.flags = static_cast<uint8_t>((options.geometry_only ? kGabFlagGeometryOnly : 0) |
                                      (selection.refined ? kGabFlagRefined : 0) | (e->levels ? kGabFlagLevels : 0) |
                                      (options.reorder ? kGabFlagReordered : 0) |
                                      (stats->detail ? kGabFlagDetail : 0));
  header.num_vertices = mesh.num_vertices();
  header.num_triangles = mesh.num_triangles();
  header.weight = options.weight;
  header.anchors = e->anchors;
  header.chunks = static_cast<int32_t>(chunks.size());
  *file = assemble_file(header, mesh, ctx.coded, chunks, stats);
  stats->reordered = options.reorder;
  stats->anchors = header.anchors;
  stats->chunks = header.chunks;
  e->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

// Whether candidate b is better than a: meeting the targets first, then smaller.
bool better(bool a_met, double a_bytes, bool b_met, double b_bytes) {
  if (a_met != b_met) return b_met;
  return b_bytes < a_bytes;
}

// encode_mesh after the checks, on the mesh as the decoder will number it:
// every candidate of encode_candidates estimated, then finished from the
// best estimate on while one might still beat the best file
// (encode_candidates.h), the best file kept.
Status encode_numbered(const Mesh& mesh, const EncodeOptions& options, const CodedConnectivity& coded,
                       std::vector<uint8_t>* file, EncodeStats* stats) {
  EncodeContext ctx(mesh, options, coded);
  double magnitude = 0;
  for (int c = 0; c < 3; ++c) magnitude = std::max({magnitude, std::fabs(ctx.box.lo[c]), std::fabs(ctx.box.hi[c])});
  if (!std::isfinite(ctx.box.diagonal) || !(magnitude <= kGabMaxMagnitude)) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "mesh: a coordinate's magnitude is over 1e100 (the format's bound): scale the coordinates "
                         "down");
  }
  MeshSize size;
  size.num_vertices = mesh.num_vertices();
  size.extent = ctx.box.extent;
  size.diagonal = ctx.box.diagonal;
  std::vector<EncodeCandidate> candidates = encode_candidates(options, size);
  std::vector<Estimate> estimates;
  bool met = false;
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].rescue_only && met) continue;
    Estimate e;
    GAB_RETURN_IF_ERROR(estimate(ctx, candidates[i], &e));
    met = met || e.target_met;
    EncodeCandidate retry;
    if (dense_grid_candidate(options, size, candidates[i], e.anchors, &retry)) {
      candidates.insert(candidates.begin() + static_cast<std::ptrdiff_t>(i) + 1, retry);
    }
    estimates.push_back(std::move(e));
  }
  // Finished from the best estimate on.
  std::vector<size_t> order(estimates.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return better(estimates[b].target_met, static_cast<double>(estimates[b].bytes()), estimates[a].target_met,
                  static_cast<double>(estimates[a].bytes()));
  });
  std::vector<EncodeStats::Candidate> report(estimates.size());
  size_t kept = order.front();
  size_t overhead = 0;  // at least the bytes of a file beyond its chunks: header, connectivity
  bool have = false;
  for (size_t i : order) {
    Estimate& e = estimates[i];
    EncodeStats::Candidate& r = report[i];
    r.name = e.candidate.name;
    r.bits = e.candidate.anchors.bits;
    r.anchors = e.anchors;
    r.estimate_bytes = e.bytes();
    r.target_met = e.target_met;
    // The least this candidate's file may come to: the rest of the detail
    // search shrinks a fitted detail chunk to no less than kLeastDetailGain.
    const double least = static_cast<double>(overhead + e.anchor_bytes()) +
                         static_cast<double>(e.detail_bytes()) * kLeastDetailGain;
    if (!have || better(stats->target_met, static_cast<double>(file->size()), e.target_met, least)) {
      std::vector<uint8_t> other;
      EncodeStats other_stats;
      GAB_RETURN_IF_ERROR(finish(ctx, &e, &other, &other_stats));
      r.bytes = other.size();
      r.target_met = other_stats.target_met;
      overhead = other_stats.connectivity_bytes + other_stats.order_bytes + kGabMinHeaderBytes;
      if (!have || better(stats->target_met, static_cast<double>(file->size()), other_stats.target_met,
                          static_cast<double>(other.size()))) {
        *file = std::move(other);
        *stats = std::move(other_stats);
        kept = i;
        have = true;
      }
    }
    r.seconds = e.seconds;
    e = Estimate();  // its selection's shapes are not needed again
  }
  report[kept].kept = true;
  stats->candidates = std::move(report);
  return Status::Ok();
}

}  // namespace

namespace {

int bits_for(const MeshAttribute& a, const EncodeOptions& o) {
  switch (a.kind) {
    case AttributeKind::kNormal:
      return o.normal_bits;
    case AttributeKind::kTexCoord:
      return o.texcoord_bits;
    case AttributeKind::kColor:
      return o.color_bits;
    case AttributeKind::kGeneric:
      break;
  }
  return o.generic_bits;
}

// The attributes of `mesh` (numbered and with its triangles as the decoder
// returns them) coded in sections after the file's chunks: the header's
// section count rewritten, the stats' sizes set. O(attribute values + T).
Status append_attribute_sections(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* file,
                                 EncodeStats* stats) {
  if (mesh.attributes.empty()) return Status::Ok();
  const CornerTable table = build_corner_table(mesh.num_vertices(), mesh.triangles);
  // Normals may be predicted from the decoded surface: the decoder's own
  // shape, bit for bit, from the file as it stands.
  std::vector<double> decoded;
  for (const MeshAttribute& a : mesh.attributes) {
    if (a.kind != AttributeKind::kNormal || !decoded.empty()) continue;
    DecodeOptions d;
    d.connectivity = options.geometry_only ? &mesh : nullptr;
    d.max_memory = -1;
    d.threads = options.threads;
    Mesh shape;
    DecodeStats ds;
    GAB_RETURN_IF_ERROR(decode_mesh(file->data(), file->size(), d, &shape, &ds));
    decoded = std::move(shape.positions);
  }
  std::vector<std::vector<uint8_t>> sections;
  for (const MeshAttribute& a : mesh.attributes) {
    AttributeCoding coding;
    sections.push_back(
        encode_attribute_section(a, table, bits_for(a, options), decoded.empty() ? nullptr : &decoded, &coding));
    AttributeStats as;
    as.label = attribute_label(a);
    as.bits = coding.bits;
    as.per_corner = coding.per_corner;
    as.elements = coding.elements;
    as.bytes = sections.back().size() + kGabFrameBytes;
    as.max_error = coding.max_error;
    as.from_surface = coding.surface;
    stats->attribute_bytes += as.bytes;
    stats->attributes.push_back(std::move(as));
  }
  ByteReader in(file->data(), file->size());
  GabHeader header;
  GAB_RETURN_IF_ERROR(read_gab_header(&in, file->size(), &header));
  header.sections = static_cast<int32_t>(sections.size());
  ByteWriter out;
  write_gab_header(header, &out);
  const size_t grown = out.size() - in.offset();  // the count's varint may take more bytes
  out.bytes(file->data() + in.offset(), file->size() - in.offset());
  for (const std::vector<uint8_t>& section : sections) write_framed(section.data(), section.size(), &out);
  *file = out.take();
  stats->geometry_bytes += grown;
  stats->bytes = file->size();
  return Status::Ok();
}

// Both encode_mesh: `owned`, when given, is `mesh` itself, whose arrays
// the encoder may take instead of copying.
Status encode_mesh_from(const Mesh& mesh, Mesh* owned, const EncodeOptions& given, std::vector<uint8_t>* file,
                        EncodeStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  GAB_RETURN_IF_ERROR(check_options(given));
  // A geometry-only file is numbered as the mesh its decoder is given.
  EncodeOptions options = given;
  if (options.geometry_only) options.reorder = false;
  // In traversal order, copies of a vertex (at the same position) are
  // merged first: the file codes one vertex, their data per corner.
  Mesh welded;
  std::vector<int32_t> weld_index;
  const int32_t merged = options.reorder ? weld_coincident_vertices(mesh, &welded, &weld_index) : 0;
  if (merged > 0) {
    if (owned != nullptr) *owned = Mesh();
    GAB_RETURN_IF_ERROR(encode_mesh_from(welded, &welded, options, file, stats));
    for (int32_t& v : weld_index) v = stats->new_index[v];
    stats->new_index = std::move(weld_index);
    stats->merged_vertices = merged;
    stats->encode_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return Status::Ok();
  }
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, "mesh"));
  if (options.geometry_only) {
    GAB_RETURN_IF_ERROR(encode_numbered(mesh, options, {}, file, stats));
    GAB_RETURN_IF_ERROR(append_attribute_sections(mesh, options, file, stats));
  } else {
    // The geometry is coded on the mesh as the decoder returns it: in the
    // input's numbering unless reordered (the anchors code 0-6% smaller in
    // it than in the traversal's on the shared meshes), with the triangles
    // in the coder's order.
    CodedConnectivity coded;
    GAB_RETURN_IF_ERROR(code_connectivity(mesh.num_vertices(), mesh.triangles, options.reorder, &coded));
    Mesh numbered;
    if (options.reorder) {
      numbered = renumber_vertices(mesh, coded.new_index);
    } else if (owned != nullptr) {
      numbered.positions = std::move(owned->positions);
      numbered.attributes = std::move(owned->attributes);
    } else {
      numbered.positions = mesh.positions;
      numbered.attributes = mesh.attributes;
    }
    // Per-corner attributes follow the triangles into the coder's order.
    bool per_corner = false;
    for (const MeshAttribute& a : numbered.attributes) per_corner = per_corner || a.per_corner();
    if (per_corner) {
      const std::vector<int32_t>& input = options.reorder ? numbered.triangles : mesh.triangles;
      std::vector<int32_t> input_corner;
      GAB_RETURN_IF_ERROR(match_corners(input, coded.triangles, &input_corner));
      for (MeshAttribute& a : numbered.attributes) {
        if (!a.per_corner()) continue;
        std::vector<int32_t> corners(input_corner.size());
        for (size_t c = 0; c < corners.size(); ++c) corners[c] = a.corners[input_corner[c]];
        a.corners = std::move(corners);
      }
    }
    if (owned != nullptr) *owned = Mesh();  // nothing of the input is read again
    numbered.triangles = std::move(coded.triangles);
    GAB_RETURN_IF_ERROR(encode_numbered(numbered, options, coded, file, stats));
    GAB_RETURN_IF_ERROR(append_attribute_sections(numbered, options, file, stats));
    if (options.reorder) stats->new_index = std::move(coded.new_index);
  }
  stats->encode_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace

Status encode_mesh(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* file, EncodeStats* stats) {
  return encode_mesh_from(mesh, nullptr, options, file, stats);
}

Status encode_mesh(Mesh&& mesh, const EncodeOptions& options, std::vector<uint8_t>* file, EncodeStats* stats) {
  return encode_mesh_from(mesh, &mesh, options, file, stats);
}

}  // namespace gab
