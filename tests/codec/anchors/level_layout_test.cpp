// The level layout (format flag bit 2, anchor_levels.h): level sizes and
// farthest-point order, round trips to the encoder's anchors, every level
// prefix and partial level, the local correction of the predictions, the
// plan's checks, the dense-regime grid, and what the layout saves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "anchors/anchor_chunk.h"
#include "anchors/anchor_levels.h"
#include "connectivity/connectivity_section.h"
#include "common/gab_files.h"
#include "container/byte_io.h"
#include "container/framing.h"
#include "container/gab_header.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/graph_distance.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/relaxed_reconstruction.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::decode_or_die;
using testing_util::encode_or_die;
using testing_util::in_decoded_numbering;
using testing_util::relative_rms;
using testing_util::rough_torus;

TEST(LevelLayout, LevelSizesGrowByTheFactorAndCoverTheRest) {
  LevelPlan plan;
  plan.spread = 3;
  plan.rest = 40;
  plan.growth16 = 32;  // doubling, at least 8 a level: 3 -> 11 -> 22 -> the remaining 21
  EXPECT_EQ(plan.level_sizes(), (std::vector<int32_t>{8, 11, 21}));
  plan.spread = 100;
  plan.rest = 30;
  plan.growth16 = 17;  // 1.0625: 8 a level while that is more
  EXPECT_EQ(plan.level_sizes(), (std::vector<int32_t>{8, 8, 8, 6}));
  plan.spread = 200;  // 212 = 200 * 17 / 16, then 225
  EXPECT_EQ(plan.level_sizes(), (std::vector<int32_t>{12, 13, 5}));
  plan.rest = 0;
  EXPECT_TRUE(plan.level_sizes().empty());
  EXPECT_EQ(level_growth16(2.0), 32u);
  EXPECT_EQ(level_growth16(1.01), kMinLevelGrowth16);
  EXPECT_EQ(level_growth16(1e9), kMaxLevelGrowth16);
}

TEST(LevelLayout, LevelOrderIsFarthestFirstTiesToTheSmallerIndex) {
  // A path 0 - 1 - ... - 9 and a separate triangle 10 11 12.
  Mesh m;
  m.positions.assign(13 * 3, 0.0);
  for (int32_t v = 0; v + 2 < 10; ++v) m.triangles.insert(m.triangles.end(), {v, v + 1, v + 1});  // edges v, v + 1
  m.triangles.insert(m.triangles.end(), {8, 9, 9, 10, 11, 12});
  const EdgeGraph graph = build_edge_graph(m);
  std::vector<int32_t> order;
  // From {0}: the unreached triangle first (smallest index), then 9, then
  // 5 (4 hops from 9 and 5 from 0: beats 2 and 12, now 1 hop from 11).
  ASSERT_TRUE(level_order(graph, {0}, {2, 5, 9, 11, 12}, 5, &order).ok());
  EXPECT_EQ(order, (std::vector<int32_t>{11, 9, 5, 2, 12}));
  ASSERT_TRUE(level_order(graph, {0}, {2, 5, 9, 11, 12}, 2, &order).ok());
  EXPECT_EQ(order, (std::vector<int32_t>{11, 9}));
  EXPECT_FALSE(level_order(graph, {0}, {2, 2}, 1, &order).ok());
  EXPECT_FALSE(level_order(graph, {0}, {2}, 2, &order).ok());
}

TEST(LevelLayout, LevelOrderAgreesWithABruteForceFarthestPointSearch) {
  // Every pick recomputed from scratch: breadth-first hops from the spread
  // set and the picks so far, the farthest vertex of the rest left, ties to
  // the smaller index, the unreached infinitely far. Spread sets of one
  // vertex to hundreds on a torus, so picks tie often and distances shrink
  // many times; beside it a strip of 120 vertices no spread vertex reaches,
  // whose hops from its first pick run past the torus's farthest.
  Mesh mesh = rough_torus(24, 16, 0.02);
  const int32_t torus = mesh.num_vertices();
  for (int32_t i = 0; i < 60; ++i) {
    mesh.positions.insert(mesh.positions.end(), {i * 1.0, 5.0, 0.0, i * 1.0, 6.0, 0.0});
    const int32_t a = torus + 2 * i;
    if (i + 1 < 60) mesh.triangles.insert(mesh.triangles.end(), {a, a + 2, a + 1, a + 1, a + 2, a + 3});
  }
  const EdgeGraph graph = build_edge_graph(mesh);
  const int32_t n = graph.num_vertices();
  for (int32_t stride : {torus, 37, 5}) {
    std::vector<int32_t> spread, rest;
    for (int32_t v = 0; v < n; ++v) (v < torus && v % stride == 3 ? spread : rest).push_back(v);
    std::vector<int32_t> expected, sources = spread;
    std::vector<char> picked(n, 0);
    const int32_t count = static_cast<int32_t>(rest.size()) * 3 / 4;
    for (int32_t pick = 0; pick < count; ++pick) {
      std::vector<int32_t> hops(n, -1), queue = sources;
      for (int32_t v : sources) hops[v] = 0;
      for (size_t head = 0; head < queue.size(); ++head) {
        const int32_t u = queue[head];
        for (int32_t p = graph.offsets[u]; p < graph.offsets[u + 1]; ++p) {
          if (hops[graph.neighbors[p]] < 0) {
            hops[graph.neighbors[p]] = hops[u] + 1;
            queue.push_back(graph.neighbors[p]);
          }
        }
      }
      for (int32_t& h : hops) h = h < 0 ? n : h;  // unreached: farther than any hops
      int32_t best = -1;
      for (int32_t v : rest) {
        if (!picked[v] && (best < 0 || hops[v] > hops[best])) best = v;  // rest is increasing: ties keep the smaller
      }
      picked[best] = 1;
      expected.push_back(best);
      sources.push_back(best);
    }
    std::vector<int32_t> order;
    ASSERT_TRUE(level_order(graph, spread, rest, count, &order).ok());
    EXPECT_EQ(order, expected) << "spread every " << stride << " vertices";
  }
}

TEST(LevelLayout, LevelPicksHandOverTheNearestMapBeforeEachLevel) {
  // The picks level by level, here or on a thread: level_order's picks,
  // and before each level (and after the last) the nearest-anchor map of
  // the spread set and the levels so far, as one sampler run gives it. A
  // map asked for out of turn is refused; a caller that takes no maps
  // still gets every pick (the thread gives the maps up, not the picks).
  const Mesh mesh = rough_torus(40, 20, 0.02);
  const EdgeGraph graph = build_edge_graph(mesh);
  std::vector<int32_t> spread, rest;
  for (int32_t v = 0; v < mesh.num_vertices(); ++v) (v % 97 == 5 ? spread : rest).push_back(v);
  const std::vector<int32_t> levels = {8, 24, 70, 200};
  std::vector<int32_t> expected_order;
  ASSERT_TRUE(level_order(graph, spread, rest, 302, &expected_order).ok());
  std::vector<std::vector<uint64_t>> expected_maps;
  FarthestPointSampler sampler;
  ASSERT_TRUE(sampler.start(graph, spread, &rest).ok());
  std::vector<int32_t> chosen;
  sampler.next(static_cast<int32_t>(spread.size()), &chosen);
  expected_maps.push_back(sampler.nearest());
  for (int32_t size : levels) {
    sampler.next(size, &chosen);
    expected_maps.push_back(sampler.nearest());
  }
  for (bool background : {false, true}) {
    LevelPicks picks;
    ASSERT_TRUE(picks.start(graph, spread, rest, levels, background).ok());
    std::vector<uint64_t> map;
    EXPECT_FALSE(picks.nearest_before(1, &map)) << background;  // out of turn
    EXPECT_TRUE(map.empty());
    for (size_t k = 0; k <= levels.size(); ++k) {
      ASSERT_TRUE(picks.nearest_before(k, &map)) << background << " " << k;
      EXPECT_EQ(map, expected_maps[k]) << background << " " << k;
      if (k < levels.size()) {
        ASSERT_TRUE(picks.wait(k));
      }
    }
    EXPECT_FALSE(picks.wait(levels.size()));  // no such level
    EXPECT_EQ(picks.order(), expected_order) << background;
    LevelPicks no_maps;
    ASSERT_TRUE(no_maps.start(graph, spread, rest, levels, background).ok());
    ASSERT_TRUE(no_maps.wait(levels.size() - 1));
    EXPECT_EQ(no_maps.order(), expected_order) << background;
  }
  LevelPicks picks;
  EXPECT_EQ(picks.start(graph, spread, rest, {2000, 2000}, false).message(),
            "level order: more picks than vertices to pick from");
}

TEST(LevelLayout, DecodesToTheEncodersAnchorsAndSavesTheSelectionOrder) {
  const Mesh mesh = rough_torus(60, 30, 0.02);
  EncodeOptions options;
  options.target_rms_rel = 1e-3;
  EncodeStats levels_stats, selection_stats;
  const std::vector<uint8_t> levels = encode_or_die(mesh, options, &levels_stats);  // the default: the smaller
  options.layout = FileLayout::kSelectionOrder;
  const std::vector<uint8_t> selection = encode_or_die(mesh, options, &selection_stats);
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(levels.data(), levels.size(), &info).ok());
  EXPECT_TRUE(info.levels);
  EXPECT_EQ(levels[9], kGabFlagLevels | kGabFlagReordered);  // the default numbering: the traversal's
  EXPECT_EQ(info.chunk_anchors, levels_stats.chunk_anchors);
  EXPECT_EQ(info.chunks_present, levels_stats.chunks);
  EXPECT_GT(levels_stats.chunks, 3);
  ASSERT_TRUE(read_gab_info(selection.data(), selection.size(), &info).ok());
  EXPECT_FALSE(info.levels);
  // The same anchors and coefficients in both layouts: the same shape, the
  // encoder's, whatever order the anchors arrived in.
  DecodeStats ds;
  const Mesh a = decode_or_die(levels, DecodeOptions(), &ds);
  EXPECT_EQ(ds.anchors, levels_stats.anchors);
  EXPECT_EQ(ds.chunks, levels_stats.chunks);
  const Mesh b = decode_or_die(selection, DecodeOptions(), &ds);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (size_t i = 0; i < a.positions.size(); ++i) ASSERT_NEAR(a.positions[i], b.positions[i], 1e-9) << i;
  EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, levels_stats), a), levels_stats.rms_rel, 1e-12);
  EXPECT_EQ(levels_stats.rms_rel, selection_stats.rms_rel);
  EXPECT_EQ(levels_stats.anchors, selection_stats.anchors);
  // What the layout is for: the selection order is no longer paid for.
  EXPECT_LT(levels_stats.geometry_bytes, 0.97 * selection_stats.geometry_bytes);
}

TEST(LevelLayout, TheSelectionOrderStaysWhereItCodesSmaller) {
  // A small smooth torus: the greedy batches predict well enough to pay
  // for their order, and the two extra levels' frames weigh.
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeOptions options;
  options.max_anchors = 150;
  options.solver = Solver::kGlobal;
  EncodeStats smaller, forced, selection;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &smaller);
  options.layout = FileLayout::kLevels;
  encode_or_die(mesh, options, &forced);
  options.layout = FileLayout::kSelectionOrder;
  EXPECT_EQ(encode_or_die(mesh, options, &selection), file);
  EXPECT_LT(selection.bytes, forced.bytes);
  EXPECT_NE(file[9] & kGabFlagLevels, kGabFlagLevels);
}

// Chunk 0 of a level file, read through the codec's internals.
struct LevelHead {
  GabHeader header;
  Quantizer quantizer;
  LevelPlan plan;
  std::vector<int32_t> spread, spread_grid, rest;
};

LevelHead read_level_head(const std::vector<uint8_t>& file, int32_t n) {
  LevelHead h;
  ByteReader in(file.data(), file.size());
  EXPECT_TRUE(read_gab_header(&in, file.size(), &h.header).ok());
  h.quantizer = Quantizer::from_grid(h.header.box_min, h.header.step, h.header.bits);
  const uint8_t* payload = nullptr;
  size_t size = 0;
  ConnectivitySection connectivity;
  EXPECT_TRUE(read_connectivity_section(&in, h.header, &connectivity).ok());
  EXPECT_EQ(read_framed(&in, &payload, &size), FrameRead::kOk);  // chunk 0
  size_t offset = 0;
  EXPECT_TRUE(parse_level_plan(payload, size, h.header.anchors, h.header.anchor_chunks(), &h.plan, &offset).ok());
  AnchorModels models;
  AnchorChunkCoder coder(h.quantizer, &models);
  EXPECT_TRUE(
      coder.decode_level_head(payload + offset, size - offset, n, h.plan, &h.spread, &h.spread_grid, &h.rest).ok());
  return h;
}

TEST(LevelLayout, EveryLevelPrefixIsTheReconstructionFromItsAnchors) {
  const Mesh input = bumpy_torus(36, 18);
  EncodeOptions options;
  options.max_anchors = 120;
  options.initial_anchors = 6;
  options.chunk_growth = 1.5;
  options.layout = FileLayout::kLevels;
  options.solver = Solver::kGlobal;  // compared with the factored least squares below
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(input, options, &es);
  const Mesh mesh = in_decoded_numbering(input, es);  // the file's anchors are its vertex numbers
  const LevelHead head = read_level_head(file, mesh.num_vertices());
  ASSERT_EQ(head.plan.spread, 6);
  EXPECT_EQ(head.plan.rest, 114);
  EXPECT_EQ(head.plan.growth16, 24u);
  const std::vector<int32_t> sizes = head.plan.level_sizes();
  ASSERT_EQ(static_cast<int32_t>(sizes.size()) + 1, es.chunks);
  const EdgeGraph graph = build_edge_graph(mesh);
  std::vector<int32_t> order;
  ASSERT_TRUE(level_order(graph, head.spread, head.rest, head.plan.rest - sizes.back(), &order).ok());
  // Level k: the next sizes[k] picks, or for the last what the picks left.
  std::vector<std::vector<int32_t>> level(sizes.size());
  std::vector<char> picked(mesh.num_vertices(), 0);
  for (int32_t v : order) picked[v] = 1;
  size_t start = 0;
  for (size_t k = 0; k < sizes.size(); ++k) {
    if (k + 1 < sizes.size()) {
      level[k].assign(order.begin() + start, order.begin() + start + sizes[k]);
      std::sort(level[k].begin(), level[k].end());
    } else {
      for (int32_t v : head.rest) {
        if (!picked[v]) level[k].push_back(v);
      }
    }
    start += sizes[k];
  }
  auto coefficients = [&](const std::vector<int32_t>& anchors) {
    std::vector<double> c;
    for (int32_t v : anchors) {
      for (int a = 0; a < 3; ++a) {
        const double x = mesh.positions[3 * static_cast<size_t>(v) + a];
        c.push_back(head.quantizer.dequantize(head.quantizer.quantize(x, a), a));
      }
    }
    return c;
  };
  // Whole levels and a level cut after 3 anchors (a prefix in vertex order).
  std::vector<int32_t> anchors = head.spread;
  for (size_t k = 0; k <= sizes.size(); ++k) {
    for (int32_t extra : {0, 3}) {
      if (k == sizes.size() && extra > 0) continue;
      std::vector<int32_t> wanted = anchors;
      if (extra > 0) wanted.insert(wanted.end(), level[k].begin(), level[k].begin() + extra);
      DecodeOptions d;
      d.max_anchors = static_cast<int32_t>(wanted.size());
      DecodeStats ds;
      const Mesh out = decode_or_die(file, d, &ds);
      EXPECT_EQ(ds.anchors, d.max_anchors);
      RelaxedReconstruction rec;
      ASSERT_TRUE(rec.init(graph, head.header.weight, wanted, coefficients(wanted)).ok());
      std::vector<double> shape;
      ASSERT_TRUE(rec.reconstruct(&shape).ok());
      for (size_t i = 0; i < shape.size(); ++i) ASSERT_NEAR(out.positions[i], shape[i], 1e-9) << k << " " << extra;
    }
    if (k < sizes.size()) anchors.insert(anchors.end(), level[k].begin(), level[k].end());
  }
  EXPECT_EQ(static_cast<int32_t>(anchors.size()), es.anchors);
}

TEST(LevelLayout, RefinementFollowsTheLevelsFileOrder) {
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeOptions options;
  options.max_anchors = 80;
  options.refine = true;
  options.layout = FileLayout::kLevels;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  ASSERT_TRUE(es.refined);
  EXPECT_EQ(es.chunks, static_cast<int32_t>(es.chunk_anchors.size()) + 1);
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  EXPECT_TRUE(ds.refined);
  EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, es), out), es.rms_rel, 1e-12);
  DecodeOptions lod;
  lod.max_anchors = 79;  // a level of detail: unrefined
  decode_or_die(file, lod, &ds);
  EXPECT_FALSE(ds.refined);
  EXPECT_EQ(ds.anchors, 79);
}

TEST(LevelLayout, LocalCorrectionShrinksSpatiallyCorrelatedResiduals) {
  // A prediction off by a smooth field of several grid steps: the level's
  // neighbours decoded first tell the rest, so the level codes smaller than
  // without them (a graph with no edges turns the correction off).
  const Mesh mesh = testing_util::grid(30, 30, 0.1);
  const EdgeGraph graph = build_edge_graph(mesh);
  Mesh edgeless;
  edgeless.positions = mesh.positions;
  const EdgeGraph no_edges = build_edge_graph(edgeless);
  const double lo[3] = {0, 0, -1}, hi[3] = {3, 3, 1};
  const Quantizer q = Quantizer::for_box(lo, hi, 10);
  std::vector<int32_t> grid(mesh.positions.size()), anchors;
  std::vector<double> prediction(mesh.positions.size());
  for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
    const double* p = &mesh.positions[3 * static_cast<size_t>(v)];
    const double z = 0.3 * std::sin(2.0 * p[0]) * std::cos(1.5 * p[1]);
    const double off = 12 * q.step * std::sin(0.9 * p[0] + 0.4) * std::cos(1.1 * p[1]);
    for (int c = 0; c < 3; ++c) {
      const double x = c == 2 ? z : p[c];
      grid[3 * static_cast<size_t>(v) + c] = q.quantize(x, c);
      prediction[3 * static_cast<size_t>(v) + c] = x + off;
    }
    anchors.push_back(v);
  }
  AnchorModels with_models, without_models;
  AnchorChunkCoder with(q, &with_models), without(q, &without_models);
  const std::vector<uint8_t> corrected = with.encode_level(anchors, grid, prediction.data(), graph);
  const std::vector<uint8_t> plain = without.encode_level(anchors, grid, prediction.data(), no_edges);
  EXPECT_LT(corrected.size(), 0.9 * plain.size());
  // And it decodes back.
  AnchorModels models;
  AnchorChunkCoder decoder(q, &models);
  std::vector<int32_t> decoded;
  ASSERT_TRUE(decoder.decode_level(corrected.data(), corrected.size(), anchors, prediction.data(), graph, &decoded).ok());
  EXPECT_EQ(decoded, grid);
}

TEST(LevelLayout, PlanMustAgreeWithTheHeader) {
  auto plan_bytes = [](uint64_t spread, uint64_t rest, uint64_t growth16) {
    ByteWriter w;
    w.varint(spread);
    w.varint(rest);
    w.varint(growth16);
    return w.take();
  };
  auto message = [](const std::vector<uint8_t>& bytes, int32_t anchors, int32_t chunks) {
    LevelPlan plan;
    size_t offset = 0;
    return parse_level_plan(bytes.data(), bytes.size(), anchors, chunks, &plan, &offset).message();
  };
  EXPECT_EQ(message(plan_bytes(3, 20, 32), 23, 4), "");
  EXPECT_EQ(message(plan_bytes(3, 20, 32), 23, 5), "level plan makes 3 levels; the header declares 4");
  EXPECT_EQ(message(plan_bytes(0, 23, 32), 23, 4), "level plan: 0 + 23 anchors do not add up to the header's 23");
  EXPECT_EQ(message(plan_bytes(3, 19, 32), 23, 4), "level plan: 3 + 19 anchors do not add up to the header's 23");
  EXPECT_EQ(message(plan_bytes(3, 20, 16), 23, 4), "level plan: growth 16/16 out of range");
  EXPECT_EQ(message(plan_bytes(3, 20, 1u << 20), 23, 4), "level plan: growth 1048576/16 out of range");
  EXPECT_EQ(message(std::vector<uint8_t>{3, 20}, 23, 4), "level plan is cut short");
}

TEST(LevelLayout, DenseAnchorSetsTryTheCoarserGrid) {
  // Vertex-scale noise: at 1e-3 most vertices become anchors on the default
  // grid, so the encoder also tries the grid that errs 0.95 of the target
  // and keeps it here, for fewer bits at the target still.
  const Mesh mesh = rough_torus(60, 30, 0.04);
  EncodeOptions options;
  options.target_rms_rel = 1e-3;
  EncodeStats chosen, fixed;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &chosen);
  EncodeOptions default_grid = options;
  default_grid.bits = chosen.bits;  // a given q: no second try
  encode_or_die(mesh, default_grid, &fixed);
  ASSERT_GT(fixed.anchors, mesh.num_vertices() / 2);
  EXPECT_TRUE(chosen.target_met);
  EXPECT_LT(chosen.bytes, fixed.bytes);
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, chosen), out), chosen.rms_rel, 1e-12);
  EXPECT_LE(chosen.rms_rel, 1e-3);
  // The kept grid is coarser than 2^q - 1 steps over the box's longest side.
  double lo[3], hi[3];
  for (int c = 0; c < 3; ++c) lo[c] = hi[c] = mesh.positions[c];
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], mesh.positions[i]);
    hi[i % 3] = std::max(hi[i % 3], mesh.positions[i]);
  }
  EXPECT_GT(info.step, 1.01 * Quantizer::for_box(lo, hi, chosen.bits).step);
}

TEST(LevelLayout, BunnySmallMeetsTheDracoRateAt1e3) {
  // The rate target of issue 6: bunny-small at 1e-3 within Draco's 10.68
  // geometry bits per vertex (10.38 measured; the first layout: 12.27), for
  // the input's numbering. The traversal's (the default, issue 34) costs
  // 10.67 in the geometry and drops the vertex order block, 8.9 bits a
  // vertex here: 5,571 bytes in all against 9,407 kept.
  Mesh mesh;
  const std::string path = std::string(GAB_SHARED_MESHES) + "/bunny-small.off";
  if (!read_mesh(path, &mesh).ok()) GTEST_SKIP() << "no " << path;
  EncodeOptions options;
  options.target_rms_rel = 1e-3;
  options.reorder = false;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  EXPECT_LE(8.0 * es.geometry_bytes / mesh.num_vertices(), 10.6);
  DecodeStats ds;
  EXPECT_NEAR(relative_rms(mesh, decode_or_die(file, DecodeOptions(), &ds)), es.rms_rel, 1e-12);
  EXPECT_LE(es.rms_rel, 1e-3);
}

}  // namespace
}  // namespace gab
