// The encoder: a short driver over the codec's layers, in the order the
// decoder reads them back (decoder.cpp):
//   (the connectivity coded first, connectivity/connectivity_section.h: the
//   geometry is coded on the mesh as its decoder will return it)
//   select anchors (anchor_selection.h: greedy loop and refinement search, no bytes)
//   -> code the anchor chunks in each layout (anchors/anchor_chunk.h, anchor_levels.h), keep one
//   -> the refinement chunk (anchors/refinement_chunk.h)
//   -> the detail chunk over the anchors' shape (detail_search.h, detail/detail_chunk.h)
//   -> header (container/gab_header.h), connectivity section (connectivity/), chunks, framed.
#include "gab/codec/encoder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "anchors/anchor_chunk.h"
#include "anchors/anchor_levels.h"
#include "anchors/refinement_chunk.h"
#include "connectivity/connectivity_section.h"
#include "container/framing.h"
#include "container/gab_header.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "gab/mesh/renumber.h"
#include "pipeline/anchor_selection.h"
#include "pipeline/detail_search.h"
#include "pipeline/encoder_tuning.h"
#include "pipeline/ordering_choice.h"

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
  if (!(o.weight > 0) || !std::isfinite(o.weight)) return bad("anchor weight must be positive and finite");
  if (!(o.batch_fraction <= 1)) return bad("batch fraction must be at most 1");
  if (o.chunk_growth > 0 && !(o.chunk_growth > 1)) return bad("chunk growth must be above 1");
  if (!std::isfinite(o.chunk_growth)) return bad("chunk growth must be finite");
  if (o.refine_iterations < 1) return bad("refinement iterations must be positive");
  if (o.reorder && o.geometry_only) return bad("a reordered file codes its connectivity: not with geometry only");
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

// One layout's anchor chunks, the anchors in the order the file lists them
// (chunk by chunk, each in vertex order: the refinement's order) and per chunk.
struct ChunkLayout {
  std::vector<std::vector<uint8_t>> chunks;
  std::vector<int32_t> file_order;
  std::vector<int32_t> chunk_anchors;

  void add(std::vector<uint8_t> chunk, const std::vector<int32_t>& anchors) {
    chunks.push_back(std::move(chunk));
    file_order.insert(file_order.end(), anchors.begin(), anchors.end());
    chunk_anchors.push_back(static_cast<int32_t>(anchors.size()));
  }
  size_t bytes() const {
    size_t total = 0;
    for (const std::vector<uint8_t>& c : chunks) total += c.size() + kGabFrameBytes;
    return total;
  }
};

// The selection-order layout: chunk k the schedule's k-th cut, its anchors
// a subset of the vertices the chunks before left free, predicted by the
// reconstruction from those chunks (chunk 0: by the previous anchor). O(n)
// per chunk plus the positions.
ChunkLayout encode_selection_layout(const AnchorSchedule& schedule, const GridPositions& grid) {
  ChunkLayout out;
  AnchorModels models;
  AnchorChunkCoder coder(grid.quantizer, &models);
  std::vector<char> coded(grid.index.size() / 3, 0);  // anchored by the chunks written so far
  int32_t begin = 0;
  for (size_t k = 0; k < schedule.cuts.size(); ++k) {
    std::vector<int32_t> anchors(schedule.order.begin() + begin, schedule.order.begin() + schedule.cuts[k]);
    std::sort(anchors.begin(), anchors.end());
    const double* prediction = k == 0 ? nullptr : schedule.shapes[k - 1].data();
    out.add(coder.encode(anchors, coded, grid.index, prediction), anchors);
    for (int32_t v : anchors) coded[v] = 1;
    begin = schedule.cuts[k];
  }
  return out;
}

// The level layout (anchor_levels.h) of the schedule's anchors: chunk 0 the
// spread set and the rest's subset, then one level's positions per chunk,
// each predicted by the reconstruction from the levels before it (level 1:
// from the spread set, the schedule's first shape). Cost: the decoder's,
// less one factorization and one solve: levels - 1 solves and updates (or
// refactorizations).
Status encode_level_layout(const AnchorSchedule& schedule, const EdgeGraph& graph, double weight, double growth,
                           int32_t threads, const OrderingPlan& ordering, const GridPositions& grid,
                           ChunkLayout* out) {
  std::vector<int32_t> spread(schedule.order.begin(), schedule.order.begin() + schedule.spread);
  std::vector<int32_t> rest(schedule.order.begin() + schedule.spread, schedule.order.end());
  std::sort(spread.begin(), spread.end());
  std::sort(rest.begin(), rest.end());
  LevelPlan plan;
  plan.spread = schedule.spread;
  plan.rest = static_cast<int32_t>(rest.size());
  plan.growth16 = level_growth16(growth);
  const std::vector<int32_t> sizes = plan.level_sizes();
  std::vector<int32_t> order;
  GAB_RETURN_IF_ERROR(level_order(graph, spread, rest, plan.rest - (sizes.empty() ? 0 : sizes.back()), &order));
  AnchorModels models;
  AnchorChunkCoder coder(grid.quantizer, &models);
  out->add(coder.encode_level_head(plan, spread, rest, grid.index), spread);

  LevelMembers members(order, rest, graph.num_vertices());
  RelaxedReconstruction levels;  // the decoder's reconstructions from level 2 on
  levels.set_threads(threads);
  ordering.apply(&levels);
  std::vector<double> shape;
  std::vector<int32_t> before = spread, previous;  // before level 2: the spread set and level 1
  for (size_t k = 0; k < sizes.size(); ++k) {
    std::vector<int32_t> level = members.next(sizes, k);
    if (k == 1) {
      before.insert(before.end(), previous.begin(), previous.end());
      GAB_RETURN_IF_ERROR(levels.init(graph, weight, before, grid.coefficients_of(before)));
    } else if (k > 1) {
      GAB_RETURN_IF_ERROR(levels.add_anchors_cheapest(previous, grid.coefficients_of(previous)));
    }
    if (k > 0) GAB_RETURN_IF_ERROR(levels.reconstruct(&shape));
    const double* prediction = k == 0 ? schedule.shapes[0].data() : shape.data();
    out->add(coder.encode_level(level, grid.index, prediction, graph), level);
    previous = std::move(level);
  }
  return Status::Ok();
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

// The targets a detail chunk must meet (both 0: no detail chunk).
struct DetailTargets {
  double rms_rel = 0, linf_rel = 0;
  bool wanted() const { return rms_rel > 0 || linf_rel > 0; }
};

// Everything after the grid: anchors, chunks, file. Sets every stat but
// encode_s and new_index. `coded`: the connectivity (unless geometry only).
// With `detail` wanted, the anchors stop at options' rules and a detail
// chunk over their shape meets `detail`'s targets.
Status encode_on_grid(const Mesh& mesh, const EncodeOptions& options, const Box& box, const Quantizer& quantizer,
                      int bits, const CodedConnectivity& coded, OrderingPlan* ordering, const DetailTargets& detail,
                      std::vector<uint8_t>* file, EncodeStats* stats) {
  *stats = EncodeStats();
  stats->num_vertices = mesh.num_vertices();
  stats->num_triangles = mesh.num_triangles();
  stats->bits = bits;
  stats->ordering = ordering->choice();
  const GridPositions grid(mesh, quantizer);
  const EdgeGraph graph = build_edge_graph(mesh);
  Selection selection;
  int32_t anchors = 0;
  {
    // The selection's factor goes before the level layout's is made: at
    // 2.4M vertices each is gigabytes.
    RelaxedReconstruction rec;
    GAB_RETURN_IF_ERROR(select_anchors(mesh, graph, options, grid, box.diagonal > 0 ? 1.0 / box.diagonal : 1.0,
                                       ordering, &rec, &selection));
    anchors = rec.num_anchors();
  }
  stats->curve = std::move(selection.curve);

  // The level layout unless the selection order codes smaller (it can on
  // small smooth meshes, whose greedy order predicts best and whose extra
  // levels' frames weigh; never on the shared meshes).
  ChunkLayout in_selection_order, in_levels;
  if (options.layout != FileLayout::kLevels) in_selection_order = encode_selection_layout(selection.schedule, grid);
  const bool try_levels = options.layout != FileLayout::kSelectionOrder;
  if (try_levels) {
    const double growth = options.chunk_growth > 0 ? options.chunk_growth : default_level_growth(selection.flops);
    GAB_RETURN_IF_ERROR(encode_level_layout(selection.schedule, graph, options.weight, growth, options.threads,
                                            *ordering, grid, &in_levels));
  }
  const bool levels = try_levels && (options.layout == FileLayout::kLevels ||
                                     in_levels.bytes() <= in_selection_order.bytes());
  ChunkLayout& layout = levels ? in_levels : in_selection_order;
  stats->chunk_anchors = layout.chunk_anchors;
  stats->levels = levels;

  stats->unrefined_rms_rel = selection.rms_rel;
  stats->rms_rel = selection.refined ? selection.refined_rms_rel : selection.rms_rel;
  stats->linf_rel = selection.refined ? selection.refined_linf_rel : selection.linf_rel;
  if (selection.refined) {
    layout.chunks.push_back(
        encode_refinement_chunk(layout.file_order, selection.schedule.order, selection.refined_grid, grid.index));
    stats->refinement_bytes = layout.chunks.back().size() + kGabFrameBytes;
  }
  stats->refined = selection.refined;
  // An anchor count alone is always met.
  const bool rms_ok = options.target_rms_rel <= 0 || stats->rms_rel <= options.target_rms_rel;
  const bool linf_ok = options.target_linf_rel <= 0 || stats->linf_rel <= options.target_linf_rel;
  stats->target_met = rms_ok && linf_ok;

  GabHeader header;
  header.bits = bits;
  header.ordering = ordering_code(ordering->choice());
  for (int c = 0; c < 3; ++c) header.box_min[c] = quantizer.min[c];
  header.step = quantizer.step;
  if (detail.wanted()) {
    // The decoder's shape of all the anchors: selection's last (unrefined:
    // the caller asks for no refinement).
    const DetailTopology topo = build_detail_topology(mesh.num_vertices(), mesh.triangles, graph);
    DetailChoice choice;
    GAB_RETURN_IF_ERROR(choose_detail(topo, detail_frame_of(header), selection.shape, mesh, 1.0 / box.diagonal,
                                      detail.rms_rel, detail.linf_rel, &choice));
    layout.chunks.push_back(std::move(choice.chunk));
    stats->detail = true;
    stats->detail_bytes = layout.chunks.back().size() + kGabFrameBytes;
    stats->detail_step_rel = choice.params.step / box.diagonal;
    stats->anchor_rms_rel = stats->rms_rel;
    stats->rms_rel = choice.rms_rel;
    stats->linf_rel = choice.linf_rel;
    stats->target_met = choice.met;
  }

  header.flags = static_cast<uint8_t>((options.geometry_only ? kGabFlagGeometryOnly : 0) |
                                      (selection.refined ? kGabFlagRefined : 0) | (levels ? kGabFlagLevels : 0) |
                                      (options.reorder ? kGabFlagReordered : 0) |
                                      (stats->detail ? kGabFlagDetail : 0));
  header.num_vertices = mesh.num_vertices();
  header.num_triangles = mesh.num_triangles();
  header.weight = options.weight;
  header.anchors = anchors;
  header.chunks = static_cast<int32_t>(layout.chunks.size());
  *file = assemble_file(header, mesh, coded, layout.chunks, stats);
  stats->reordered = options.reorder;
  stats->anchors = header.anchors;
  stats->chunks = header.chunks;
  return Status::Ok();
}

// The grid of the dense regime: its error alone kDenseGridShare of the RMS
// target, at the fewest bits that cover the box (the step is the file's,
// not necessarily the longest side over 2^q - 1).
Quantizer dense_grid(const Box& box, double target_rms_rel, int* bits) {
  // A grid of step s errs s / 2 in RMS (uniform error on three axes).
  const double step = 2 * kDenseGridShare * target_rms_rel * box.diagonal;
  *bits = kGabMinBits;
  while (*bits < kGabMaxBits && static_cast<double>((int64_t{1} << *bits) - 1) * step < box.extent) ++*bits;
  Quantizer q = Quantizer::for_box(box.lo, box.hi, *bits);
  q.step = std::max(q.step, step);
  return q;
}

// The anchors-only file (no detail chunk), with the dense regime's retry.
Status encode_anchors_only(const Mesh& mesh, const EncodeOptions& options, const Box& box,
                           const CodedConnectivity& coded, OrderingPlan* ordering, std::vector<uint8_t>* file,
                           EncodeStats* stats) {
  const int bits = options.bits != 0 ? options.bits
                                     : default_bits(box.diagonal > 0 ? box.extent / box.diagonal : 1.0,
                                                    options.target_rms_rel, options.target_linf_rel);
  const Quantizer quantizer = Quantizer::for_box(box.lo, box.hi, bits);
  GAB_RETURN_IF_ERROR(
      encode_on_grid(mesh, options, box, quantizer, bits, coded, ordering, DetailTargets(), file, stats));
  // Dense regime: most vertices became anchors, so nearly every vertex pays
  // for the grid; a coarser one, with a few more anchors, may cost less.
  const bool dense = stats->anchors > kDenseAnchorFraction * mesh.num_vertices();
  if (dense && options.bits == 0 && options.target_rms_rel > 0 && box.diagonal > 0) {
    int coarse_bits = 0;
    const Quantizer coarse = dense_grid(box, options.target_rms_rel, &coarse_bits);
    if (coarse.step > quantizer.step) {
      std::vector<uint8_t> other;
      EncodeStats other_stats;
      GAB_RETURN_IF_ERROR(
          encode_on_grid(mesh, options, box, coarse, coarse_bits, coded, ordering, DetailTargets(), &other,
                         &other_stats));
      if (other_stats.target_met && other.size() < file->size()) {
        *file = std::move(other);
        *stats = std::move(other_stats);
      }
    }
  }
  return Status::Ok();
}

// A file whose anchors are `anchors` (on their own default grid unless
// options fix q), a detail chunk meeting options' targets after them.
Status encode_with_detail(const Mesh& mesh, const EncodeOptions& options, const Box& box,
                          const CodedConnectivity& coded, OrderingPlan* ordering, const DetailAnchors& anchors,
                          std::vector<uint8_t>* file, EncodeStats* stats) {
  const int bits = options.bits != 0 ? options.bits
                   : anchors.bits != 0 ? anchors.bits
                                       : default_bits(box.extent / box.diagonal, anchors.rms_rel, 0);
  const Quantizer quantizer = Quantizer::for_box(box.lo, box.hi, bits);
  EncodeOptions anchor_options = options;
  // A grid of step s errs s / 2 in RMS: a fixed coarse q cannot take the
  // anchors below about that, and trying would anchor every vertex.
  anchor_options.target_rms_rel =
      std::max(anchors.rms_rel, kAnchorTargetOverGrid * quantizer.step / 2 / box.diagonal);
  anchor_options.target_linf_rel = 0;
  anchor_options.refine = false;  // the detail chunk moves every vertex anyway
  if (anchor_options.initial_anchors <= 0) {
    anchor_options.initial_anchors =
        std::max<int32_t>(1, static_cast<int32_t>(mesh.num_vertices() * kDetailSpreadShare));
  }
  const int32_t cap =
      anchors.spread_only ? anchor_options.initial_anchors
                          : std::max(anchor_options.initial_anchors,
                                     static_cast<int32_t>(mesh.num_vertices() * kDetailMaxAnchorShare));
  anchor_options.max_anchors = options.max_anchors > 0 ? std::min(options.max_anchors, cap) : cap;
  DetailTargets targets;
  targets.rms_rel = options.target_rms_rel;
  targets.linf_rel = options.target_linf_rel;
  return encode_on_grid(mesh, anchor_options, box, quantizer, bits, coded, ordering, targets, file, stats);
}

// Whether candidate b is better than a: meeting the targets first, then smaller.
bool better(const EncodeStats& a, size_t a_bytes, const EncodeStats& b, size_t b_bytes) {
  if (a.target_met != b.target_met) return b.target_met;
  return b_bytes < a_bytes;
}

// encode_mesh after the checks, on the mesh as the decoder will number it:
// the candidate files detail_plan names, the best kept.
Status encode_numbered(const Mesh& mesh, const EncodeOptions& options, const CodedConnectivity& coded,
                       std::vector<uint8_t>* file, EncodeStats* stats) {
  const Box box = box_of(mesh);
  const bool detail_possible = options.detail != DetailMode::kOff && box.diagonal > 0 && box.extent > 0 &&
                               (options.target_rms_rel > 0 || options.target_linf_rel > 0);
  const DetailPlan plan = detail_plan(options.target_rms_rel, options.target_linf_rel);
  OrderingPlan ordering(encoder_ordering(options.ordering, mesh.num_vertices()));
  bool have = false;
  if (!detail_possible || (options.detail == DetailMode::kAuto && plan.try_anchors_only)) {
    GAB_RETURN_IF_ERROR(encode_anchors_only(mesh, options, box, coded, &ordering, file, stats));
    have = true;
  }
  if (!detail_possible) return Status::Ok();
  // Detail candidates: where the plan says they may win, or to rescue a
  // target the anchors alone missed, or because they were asked for.
  const bool try_detail = !have || plan.try_detail || !stats->target_met;
  if (!try_detail) return Status::Ok();
  for (const DetailAnchors& anchors : plan.anchors) {
    // A fixed q puts every candidate's anchors on the same grid: the first is enough.
    if (options.bits != 0 && &anchors != &plan.anchors.front()) break;
    std::vector<uint8_t> other;
    EncodeStats other_stats;
    GAB_RETURN_IF_ERROR(encode_with_detail(mesh, options, box, coded, &ordering, anchors, &other, &other_stats));
    if (!have || better(*stats, file->size(), other_stats, other.size())) {
      *file = std::move(other);
      *stats = std::move(other_stats);
      have = true;
    }
  }
  return Status::Ok();
}

}  // namespace

namespace {

// Both encode_mesh: `owned`, when given, is `mesh` itself, whose arrays
// the encoder may take instead of copying.
Status encode_mesh_from(const Mesh& mesh, Mesh* owned, const EncodeOptions& options, std::vector<uint8_t>* file,
                        EncodeStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  GAB_RETURN_IF_ERROR(check_options(options));
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, "mesh"));
  if (options.geometry_only) {
    GAB_RETURN_IF_ERROR(encode_numbered(mesh, options, {}, file, stats));
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
    } else {
      numbered.positions = mesh.positions;
    }
    if (owned != nullptr) *owned = Mesh();  // nothing of the input is read again
    numbered.triangles = std::move(coded.triangles);
    GAB_RETURN_IF_ERROR(encode_numbered(numbered, options, coded, file, stats));
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
