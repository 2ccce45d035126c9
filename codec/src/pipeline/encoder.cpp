#include "gab/codec/encoder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <string>

#include "anchors/anchor_chunk.h"
#include "anchors/anchor_levels.h"
#include "anchors/refinement_chunk.h"
#include "connectivity/connectivity_coder.h"
#include "container/framing.h"
#include "container/gab_header.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/graph_distance.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/optimal_coefficients.h"
#include "gab/mesh/relaxed_reconstruction.h"

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
  return Status::Ok();
}

// Anchors to add in the next greedy step: the batch fraction of those so
// far, but near an RMS target (0: none) only as many as the error curve's
// last two points (rms ~ k^-alpha) say are still needed.
int32_t next_batch(double target_rms_rel, double fraction, const std::vector<GreedyStep>& curve, int32_t cap) {
  const int32_t k = curve.back().anchors;
  int64_t wanted = fraction > 0 ? static_cast<int64_t>(std::ceil(fraction * k)) : 1;
  if (target_rms_rel > 0 && curve.size() >= 2) {
    const GreedyStep& a = curve[curve.size() - 2];
    const GreedyStep& b = curve.back();
    if (b.anchors > a.anchors && a.rms_rel > b.rms_rel && b.rms_rel > target_rms_rel) {
      const double alpha = std::log(a.rms_rel / b.rms_rel) / std::log(static_cast<double>(b.anchors) / a.anchors);
      const double needed = b.anchors * std::pow(b.rms_rel / target_rms_rel, 1.0 / alpha) - b.anchors;
      if (std::isfinite(needed)) wanted = std::min<int64_t>(wanted, static_cast<int64_t>(std::ceil(needed)));
    }
  }
  return static_cast<int32_t>(std::min<int64_t>(std::max<int64_t>(wanted, 1), cap - k));
}

// The refined coefficients of the current anchor set, as grid indices (3 per
// anchor, in rec->anchors() order), and the errors of their reconstruction.
struct Refinement {
  std::vector<int32_t> grid;
  double rms_rel = 0, linf_rel = 0;
};

// Least-squares coefficients from the quantized positions `rec` holds,
// rounded to the grid (the decoder gets exactly these), and their shape's
// errors; `rec` keeps its coefficients. Cost: 2 * iterations + 1 solves.
Status refine_coefficients(RelaxedReconstruction* rec, const Mesh& mesh, const Quantizer& quantizer, int iterations,
                           double scale, Refinement* out) {
  const std::vector<double> positions = rec->coefficients();
  std::vector<double> c = positions;
  OptimalCoefficientsReport report;
  GAB_RETURN_IF_ERROR(optimal_coefficients(rec, mesh, iterations, 0.0, &c, &report));
  out->grid.resize(c.size());
  for (size_t i = 0; i < c.size(); ++i) {
    const int axis = static_cast<int>(i % 3);
    out->grid[i] = quantizer.quantize(c[i], axis);
    c[i] = quantizer.dequantize(out->grid[i], axis);
  }
  GAB_RETURN_IF_ERROR(rec->set_coefficients(0, c));
  std::vector<double> shape, error2;
  const Status solved = rec->reconstruct(&shape);
  GAB_RETURN_IF_ERROR(rec->set_coefficients(0, positions));
  GAB_RETURN_IF_ERROR(solved);
  VertexDistance d;
  squared_vertex_errors(mesh, shape, &error2, &d);
  out->rms_rel = d.rms * scale;
  out->linf_rel = d.linf * scale;
  return Status::Ok();
}

// Refinement with an RMS target: the greedy loop first aims the unrefined
// shape this much above the target (refinement bought 11-25% at q = 9 on
// the shared meshes), then at what the last try measured.
constexpr double kExpectedRefinementGain = 1.25;

// The dense regime (see encode_mesh): past this fraction of the vertices as
// anchors the encoder also tries the grid whose error alone is
// kDenseGridShare of the RMS target, and keeps the smaller file. bunny-small
// at 1e-3 (82% anchors at q = 9, whose grid errs 0.61 of the target), level
// layout without its local correction: grid shares 0.8 / 0.9 / 0.95 / 0.98
// gave 10.87 / 10.63 / 10.53 / 10.51 bits per vertex against 11.72, with
// 86-94% anchors. The other shared meshes end at 2-35% anchors, where such a
// grid costs (0.9 of the target: +1 to +4% on horse, max-planck, bunny,
// feline and nefertiti; their best shares, 0.7-0.9, gain under 2%).
constexpr double kDenseAnchorFraction = 0.5;
constexpr double kDenseGridShare = 0.95;

// Header, connectivity block (or its hash), chunks; sets the byte counts.
std::vector<uint8_t> assemble_file(const GabHeader& header, const Mesh& mesh,
                                   const std::vector<std::vector<uint8_t>>& chunks, EncodeStats* stats) {
  ByteWriter out;
  write_gab_header(header, &out);
  const size_t before_connectivity = out.size();
  if (header.geometry_only()) {
    out.u64(connectivity_hash(mesh.num_vertices(), mesh.triangles));
  } else {
    const std::vector<uint8_t> block = encode_connectivity(mesh.num_vertices(), mesh.triangles);
    write_framed(block.data(), block.size(), &out);
  }
  stats->connectivity_bytes = out.size() - before_connectivity;
  for (const std::vector<uint8_t>& chunk : chunks) write_framed(chunk.data(), chunk.size(), &out);
  stats->bytes = out.size();
  stats->geometry_bytes = stats->bytes - stats->connectivity_bytes;
  return out.take();
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

  size_t bytes() const {
    size_t total = 0;
    for (const std::vector<uint8_t>& c : chunks) total += c.size() + kGabFrameBytes;
    return total;
  }
};

// The level layout (anchor_levels.h) of the anchors `rec` holds, the first
// `spread_count` of them the spread set; `spread_shape` is the
// reconstruction from the spread set alone (level 1's prediction). Cost:
// the decoder's, less one factorization and one solve: levels - 1 solves
// and updates (or refactorizations).
Status encode_levels(const RelaxedReconstruction& rec, const EdgeGraph& graph, int32_t spread_count, double growth,
                     int32_t threads, const std::vector<double>& spread_shape, const Quantizer& quantizer,
                     const std::vector<int32_t>& grid,
                     const std::function<std::vector<double>(const std::vector<int32_t>&)>& coefficients_of,
                     ChunkLayout* out) {
  const std::vector<int32_t>& all = rec.anchors();
  std::vector<int32_t> spread(all.begin(), all.begin() + spread_count);
  std::vector<int32_t> rest(all.begin() + spread_count, all.end());
  std::sort(spread.begin(), spread.end());
  std::sort(rest.begin(), rest.end());
  LevelPlan plan;
  plan.spread = spread_count;
  plan.rest = static_cast<int32_t>(rest.size());
  plan.growth16 = level_growth16(growth);
  const std::vector<int32_t> sizes = plan.level_sizes();
  std::vector<int32_t> order;
  GAB_RETURN_IF_ERROR(level_order(graph, spread, rest, plan.rest - (sizes.empty() ? 0 : sizes.back()), &order));
  AnchorModels models;
  AnchorChunkCoder coder(quantizer, &models);
  out->chunks.push_back(coder.encode_level_head(plan, spread, rest, grid));
  out->file_order = spread;
  out->chunk_anchors.push_back(spread_count);

  LevelMembers members(order, rest, graph.num_vertices());
  RelaxedReconstruction levels;  // the decoder's reconstructions from level 2 on
  levels.set_threads(threads);
  std::vector<double> shape;
  std::vector<int32_t> before = spread, previous;  // before level 2: the spread set and level 1
  for (size_t k = 0; k < sizes.size(); ++k) {
    std::vector<int32_t> level = members.next(sizes, k);
    if (k == 1) {
      before.insert(before.end(), previous.begin(), previous.end());
      GAB_RETURN_IF_ERROR(levels.init(graph, rec.weight(), before, coefficients_of(before)));
    } else if (k > 1) {
      GAB_RETURN_IF_ERROR(levels.add_anchors_cheapest(previous, coefficients_of(previous)));
    }
    if (k > 0) GAB_RETURN_IF_ERROR(levels.reconstruct(&shape));
    out->chunks.push_back(coder.encode_level(level, grid, k == 0 ? spread_shape.data() : shape.data(), graph));
    out->file_order.insert(out->file_order.end(), level.begin(), level.end());
    out->chunk_anchors.push_back(sizes[k]);
    previous = std::move(level);
  }
  return Status::Ok();
}

}  // namespace

int32_t default_initial_anchors(int32_t n) {
  const double scale = std::max(1.0, static_cast<double>(n) / 50000.0);
  return static_cast<int32_t>(std::max(1.0, std::min(n / 1000.0 * scale * scale * scale, n / 50.0)));
}

double default_batch_fraction(double flops) {
  return std::min(0.12, 0.05 * std::pow(std::max(1.0, flops / 2e9), 0.8));
}

double default_chunk_growth(double flops) { return 4.0 * std::pow(std::max(1.0, flops / 2e9), 0.6); }

double default_level_growth(double flops) { return 2.0 * std::pow(std::max(1.0, flops / 2e9), 0.6); }

int default_bits(double extent_over_diagonal, double target_rms_rel, double target_linf_rel) {
  if (!(target_rms_rel > 0) && !(target_linf_rel > 0)) return 12;
  for (int q = kGabMinBits; q < kGabMaxBits; ++q) {
    const double step = extent_over_diagonal / static_cast<double>((int64_t{1} << q) - 1);
    const bool rms_ok = !(target_rms_rel > 0) || step / 2 <= 0.8 * target_rms_rel;
    const bool linf_ok = !(target_linf_rel > 0) || step * std::sqrt(3.0) / 2 <= 0.5 * target_linf_rel;
    if (rms_ok && linf_ok) return q;
  }
  return kGabMaxBits;
}

namespace {

// Everything after the grid: greedy anchors, chunks, file. Sets every stat
// but encode_s.
Status encode_on_grid(const Mesh& mesh, const EncodeOptions& options, const Box& box, const Quantizer& quantizer,
                      int bits, std::vector<uint8_t>* file, EncodeStats* stats) {
  const int32_t n = mesh.num_vertices();
  *stats = EncodeStats();
  stats->num_vertices = n;
  stats->num_triangles = mesh.num_triangles();
  stats->bits = bits;
  // Every vertex's quantized position: what an anchor sends.
  std::vector<int32_t> grid(static_cast<size_t>(n) * 3);
  for (int32_t v = 0; v < n; ++v) {
    for (int c = 0; c < 3; ++c) grid[3 * static_cast<size_t>(v) + c] = quantizer.quantize(mesh.positions[3 * static_cast<size_t>(v) + c], c);
  }
  auto coefficients_of = [&](const std::vector<int32_t>& anchors) {
    std::vector<double> coefficients(anchors.size() * 3);
    for (size_t i = 0; i < anchors.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        coefficients[3 * i + c] = quantizer.dequantize(grid[3 * static_cast<size_t>(anchors[i]) + c], c);
      }
    }
    return coefficients;
  };

  EdgeGraph graph = build_edge_graph(mesh);
  int32_t components = 0;
  connected_components(graph, &components);
  const int32_t cap = options.max_anchors > 0 ? std::min(options.max_anchors, n) : n;
  // By default at most half the anchors are spread ones (measured best on
  // igea, horse and feline at 1-10% of n): the greedy steps choose the rest.
  int32_t initial = options.initial_anchors > 0 ? options.initial_anchors
                                                : std::min(default_initial_anchors(n), std::max(1, cap / 2));
  initial = std::min(std::max(initial, components), std::max(cap, components));
  std::vector<int32_t> chosen;
  GAB_RETURN_IF_ERROR(farthest_point_sampling(graph, initial, {}, &chosen));

  RelaxedReconstruction rec;
  rec.set_threads(options.threads);
  GAB_RETURN_IF_ERROR(rec.init(graph, options.weight, chosen, coefficients_of(chosen)));
  const double fraction = options.batch_fraction >= 0 ? options.batch_fraction
                                                      : default_batch_fraction(rec.cholesky().symbolic().flops);
  const double flops = rec.cholesky().symbolic().flops;
  const double growth = options.chunk_growth > 0 ? options.chunk_growth : default_chunk_growth(flops);
  const double level_growth = options.chunk_growth > 0 ? options.chunk_growth : default_level_growth(flops);

  // The first layout is coded as the greedy loop goes (each chunk is
  // predicted by the shape when it opened); the level layout after it.
  AnchorModels models;
  AnchorChunkCoder coder(quantizer, &models);
  std::vector<char> coded(n, 0);  // anchored by the chunks written so far
  ChunkLayout selection;
  auto close_chunk = [&](std::vector<int32_t> anchors, const double* prediction) {
    std::sort(anchors.begin(), anchors.end());
    selection.file_order.insert(selection.file_order.end(), anchors.begin(), anchors.end());
    selection.chunks.push_back(coder.encode(anchors, coded, grid, prediction));
    for (int32_t v : anchors) coded[v] = 1;
    selection.chunk_anchors.push_back(static_cast<int32_t>(anchors.size()));
  };
  close_chunk(chosen, nullptr);

  const double scale = box.diagonal > 0 ? 1.0 / box.diagonal : 1.0;
  std::vector<double> shape, prediction, spread_shape, error2(n);
  std::vector<int32_t> open;  // anchors of the chunk being gathered
  int32_t chunk_opened_at = rec.num_anchors();
  double rms_rel = 0, linf_rel = 0;
  const double target = options.target_rms_rel;
  const bool refine = options.refine;
  double position_target = refine ? target * kExpectedRefinementGain : target;
  Refinement refinement;
  bool refined = false;
  // Keeps a refinement that lowers the RMS without breaking an L-inf target
  // the unrefined shape meets (least squares may raise the maximum).
  auto acceptable = [&](const Refinement& r) {
    const double linf_bound = std::max(options.target_linf_rel, linf_rel);
    return r.rms_rel < rms_rel && (!(options.target_linf_rel > 0) || r.linf_rel <= linf_bound);
  };
  while (true) {
    GAB_RETURN_IF_ERROR(rec.reconstruct(&shape));
    VertexDistance distance;
    squared_vertex_errors(mesh, shape, &error2, &distance);
    rms_rel = distance.rms * scale;
    linf_rel = distance.linf * scale;
    stats->curve.push_back({rec.num_anchors(), rms_rel, linf_rel});
    if (options.progress) options.progress(rec.num_anchors(), rms_rel);
    if (spread_shape.empty()) spread_shape = shape;  // level 1's prediction
    if (open.empty()) prediction = shape;  // what the decoder will hold when the next chunk starts
    const bool rms_met = target > 0 && rms_rel <= target;
    const bool linf_met = options.target_linf_rel > 0 && linf_rel <= options.target_linf_rel;
    if (rms_met || linf_met) break;
    if (rec.num_anchors() >= cap) {
      // Out of anchors: refinement is the last way to get closer.
      if (refine) {
        GAB_RETURN_IF_ERROR(refine_coefficients(&rec, mesh, quantizer, options.refine_iterations, scale, &refinement));
        refined = acceptable(refinement);
      }
      break;
    }
    if (refine && target > 0 && rms_rel <= position_target) {
      GAB_RETURN_IF_ERROR(refine_coefficients(&rec, mesh, quantizer, options.refine_iterations, scale, &refinement));
      if (acceptable(refinement) && refinement.rms_rel <= target) {
        refined = true;
        break;
      }
      // Aim at what this try says the refinement buys, a little beyond.
      position_target = std::min(position_target, 0.99 * target * rms_rel / std::max(refinement.rms_rel, target));
    }
    const std::vector<int32_t> next =
        pick_error_maxima(graph, error2, rec, next_batch(position_target, fraction, stats->curve, cap));
    GAB_RETURN_IF_ERROR(rec.add_anchors_cheapest(next, coefficients_of(next)));
    open.insert(open.end(), next.begin(), next.end());
    if (rec.num_anchors() >= growth * chunk_opened_at) {
      close_chunk(open, prediction.data());
      open.clear();
      chunk_opened_at = rec.num_anchors();
    }
  }
  if (!open.empty()) close_chunk(open, prediction.data());
  // The level layout unless the selection order codes smaller (it can on
  // small smooth meshes, whose greedy order predicts best and whose extra
  // levels' frames weigh; never on the shared meshes).
  ChunkLayout level_layout;
  const bool try_levels = options.layout != FileLayout::kSelectionOrder;
  if (try_levels) {
    GAB_RETURN_IF_ERROR(encode_levels(rec, graph, static_cast<int32_t>(chosen.size()), level_growth, options.threads,
                                      spread_shape, quantizer, grid, coefficients_of, &level_layout));
  }
  const bool levels = options.layout == FileLayout::kLevels ||
                      (try_levels && level_layout.bytes() <= selection.bytes());
  ChunkLayout& layout = levels ? level_layout : selection;
  std::vector<std::vector<uint8_t>>& chunks = layout.chunks;
  const std::vector<int32_t>& file_order = layout.file_order;
  stats->chunk_anchors = layout.chunk_anchors;
  stats->levels = levels;
  stats->unrefined_rms_rel = rms_rel;
  if (refined) {
    // Corrections in file order: chunk by chunk, each in vertex order.
    std::vector<int32_t> slot(n, -1);
    for (size_t i = 0; i < rec.anchors().size(); ++i) slot[rec.anchors()[i]] = static_cast<int32_t>(i);
    std::vector<int32_t> deltas(file_order.size() * 3);
    for (size_t i = 0; i < file_order.size(); ++i) {
      const size_t v = static_cast<size_t>(file_order[i]), s = static_cast<size_t>(slot[v]);
      for (int c = 0; c < 3; ++c) deltas[3 * i + c] = refinement.grid[3 * s + c] - grid[3 * v + c];
    }
    chunks.push_back(encode_refinement(deltas));
    stats->refinement_bytes = chunks.back().size() + kGabFrameBytes;
    rms_rel = refinement.rms_rel;
    linf_rel = refinement.linf_rel;
  }
  stats->refined = refined;
  stats->target_met = (options.target_rms_rel <= 0 || rms_rel <= options.target_rms_rel) &&
                      (options.target_linf_rel <= 0 || linf_rel <= options.target_linf_rel);
  if (options.max_anchors > 0 && options.target_rms_rel <= 0 && options.target_linf_rel <= 0) stats->target_met = true;

  GabHeader header;
  header.flags = static_cast<uint8_t>((options.geometry_only ? kGabFlagGeometryOnly : 0) |
                                      (refined ? kGabFlagRefined : 0) | (levels ? kGabFlagLevels : 0));
  header.bits = bits;
  header.num_vertices = n;
  header.num_triangles = mesh.num_triangles();
  header.weight = options.weight;
  for (int c = 0; c < 3; ++c) header.box_min[c] = quantizer.min[c];
  header.step = quantizer.step;
  header.anchors = rec.num_anchors();
  header.chunks = static_cast<int32_t>(chunks.size());
  *file = assemble_file(header, mesh, chunks, stats);
  stats->anchors = rec.num_anchors();
  stats->chunks = header.chunks;
  stats->rms_rel = rms_rel;
  stats->linf_rel = linf_rel;
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

}  // namespace

Status encode_mesh(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* file, EncodeStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  GAB_RETURN_IF_ERROR(check_options(options));
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, "mesh"));
  const Box box = box_of(mesh);
  const int bits = options.bits != 0 ? options.bits
                                     : default_bits(box.diagonal > 0 ? box.extent / box.diagonal : 1.0,
                                                    options.target_rms_rel, options.target_linf_rel);
  const Quantizer quantizer = Quantizer::for_box(box.lo, box.hi, bits);
  GAB_RETURN_IF_ERROR(encode_on_grid(mesh, options, box, quantizer, bits, file, stats));
  // Dense regime: most vertices became anchors, so nearly every vertex pays
  // for the grid; a coarser one, with a few more anchors, may cost less.
  const bool dense = stats->anchors > kDenseAnchorFraction * mesh.num_vertices();
  if (dense && options.bits == 0 && options.target_rms_rel > 0 && box.diagonal > 0) {
    int coarse_bits = 0;
    const Quantizer coarse = dense_grid(box, options.target_rms_rel, &coarse_bits);
    if (coarse.step > quantizer.step) {
      std::vector<uint8_t> other;
      EncodeStats other_stats;
      GAB_RETURN_IF_ERROR(encode_on_grid(mesh, options, box, coarse, coarse_bits, &other, &other_stats));
      if (other_stats.target_met && other.size() < file->size()) {
        *file = std::move(other);
        *stats = std::move(other_stats);
      }
    }
  }
  stats->encode_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace gab
