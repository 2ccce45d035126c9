// The .gab encoder and decoder together: round trips, levels of detail,
// stopping rules, geometry-only files, odd meshes, option errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/gab_files.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/renumber.h"
#include "gab/mesh/triangle_set.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::decode_or_die;
using testing_util::encode_or_die;
using testing_util::in_decoded_numbering;
using testing_util::relative_rms;

TEST(EncodeDecode, RoundTripKeepsConnectivityAndMatchesTheEncodersShape) {
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeOptions options;
  options.max_anchors = 80;
  options.reorder = false;  // the input's numbering kept, priced by the order block
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  EXPECT_EQ(es.anchors, 80);
  EXPECT_EQ(es.bytes, file.size());
  EXPECT_EQ(es.geometry_bytes + es.connectivity_bytes + es.order_bytes, es.bytes);
  EXPECT_GT(es.order_bytes, 0u);
  EXPECT_GT(es.chunks, 2);
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  // The same oriented triangles on the same vertex numbers; their order and
  // first corners are the connectivity coder's.
  EXPECT_EQ(oriented_triangle_set(out.triangles), oriented_triangle_set(mesh.triangles));
  EXPECT_NE(out.triangles, mesh.triangles);
  ASSERT_EQ(out.num_vertices(), mesh.num_vertices());
  EXPECT_EQ(ds.anchors, 80);
  EXPECT_EQ(ds.chunks, es.chunks);
  EXPECT_FALSE(ds.truncated);
  EXPECT_NEAR(relative_rms(mesh, out), es.rms_rel, 1e-12);
  EXPECT_LT(es.rms_rel, es.curve.front().rms_rel);  // the greedy steps helped
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  EXPECT_EQ(info.chunk_anchors, es.chunk_anchors);
  EXPECT_EQ(info.connectivity_bytes, es.connectivity_bytes);
  EXPECT_EQ(info.order_bytes, es.order_bytes);
  EXPECT_EQ(info.chunks_present, es.chunks);
}

// encode_mesh on a mesh given up takes its arrays: the same file, the mesh
// left empty; with every numbering and the geometry-only form.
TEST(EncodeDecode, EncodingAMeshGivenUpWritesTheSameFile) {
  const Mesh mesh = bumpy_torus(30, 16);
  for (int variant = 0; variant < 3; ++variant) {
    EncodeOptions options;
    options.max_anchors = 40;
    options.reorder = variant == 1;
    options.geometry_only = variant == 2;
    std::vector<uint8_t> copied, moved;
    EncodeStats copied_stats, moved_stats;
    ASSERT_TRUE(encode_mesh(mesh, options, &copied, &copied_stats).ok());
    Mesh given = mesh;
    ASSERT_TRUE(encode_mesh(std::move(given), options, &moved, &moved_stats).ok());
    EXPECT_EQ(moved, copied) << variant;
    EXPECT_EQ(moved_stats.new_index, copied_stats.new_index);
    EXPECT_EQ(given.num_vertices(), variant == 2 ? mesh.num_vertices() : 0) << variant;
  }
}

TEST(EncodeDecode, FilesAndShapesDoNotDependOnTheThreadCount) {
  // The decoder must reproduce the encoder's shapes bit for bit, so the
  // tree-parallel factorization may not change a single rounding: a file
  // written with any thread count is the same bytes, decoded by any count
  // to the same coordinates. A torus big enough to have parallel subtrees,
  // an RMS target so refactorizations and updates both run.
  const Mesh mesh = bumpy_torus(90, 45);
  EncodeOptions options;
  options.target_rms_rel = 2e-3;
  options.batch_fraction = 0.3;
  std::vector<uint8_t> files[3];
  for (int32_t threads = 1; threads <= 3; ++threads) {
    options.threads = threads;
    EncodeStats es;
    files[threads - 1] = encode_or_die(mesh, options, &es);
    EXPECT_GT(es.chunks, 1);
  }
  EXPECT_EQ(files[1], files[0]);
  EXPECT_EQ(files[2], files[0]);
  std::vector<double> first;
  for (int32_t threads = 1; threads <= 3; ++threads) {
    DecodeOptions decode;
    decode.threads = threads;
    DecodeStats ds;
    const Mesh out = decode_or_die(files[0], decode, &ds);
    if (threads == 1) {
      first = out.positions;
    } else {
      EXPECT_EQ(out.positions, first) << threads << " threads";
    }
  }
}

// The largest coordinate difference between two shapes of the same mesh.
double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d;
}

TEST(EncodeDecode, TheFileRecordsItsOrderingAndAnyOrderingDecodesIt) {
  // The ordering is a matter of speed (matrix_ordering.h): the file records
  // the encoder's and the decoder follows it; told to order otherwise it
  // decodes the same anchors and a shape equal up to rounding, and a detail
  // layer's positions bit for bit.
  const Mesh mesh = bumpy_torus(90, 45);
  const double diagonal = bounding_box_diagonal(mesh);
  for (Ordering ordering : {Ordering::kAmd, Ordering::kNestedDissection}) {
    const Ordering other =
        ordering == Ordering::kAmd ? Ordering::kNestedDissection : Ordering::kAmd;
    EncodeOptions options;
    options.solver = Solver::kGlobal;  // the factored operator: the one an ordering is for
    options.target_rms_rel = 2e-3;
    options.ordering = ordering;
    EncodeStats es;
    const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
    EXPECT_EQ(es.ordering, ordering);
    ASSERT_GE(file.size(), kGabMinHeaderBytes);
    EXPECT_EQ(file[11], ordering == Ordering::kAmd ? kGabOrderingAmd : kGabOrderingNestedDissection);
    GabFileInfo info;
    ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
    EXPECT_EQ(info.ordering, ordering);

    DecodeStats ds;
    const Mesh own = decode_or_die(file, DecodeOptions(), &ds);
    EXPECT_EQ(ds.ordering, ordering);
    EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, es), own), es.rms_rel, 1e-12) << ordering_name(ordering);
    DecodeOptions decode;
    decode.ordering = other;
    DecodeStats ds_other;
    const Mesh out = decode_or_die(file, decode, &ds_other);
    EXPECT_EQ(ds_other.ordering, other);
    EXPECT_EQ(ds_other.anchors, ds.anchors);
    EXPECT_NE(out.positions, own.positions) << "the orderings should round differently";
    EXPECT_LT(max_difference(out.positions, own.positions), 1e-11 * diagonal);

    options.target_rms_rel = 1e-4;
    options.detail = DetailMode::kOn;
    const std::vector<uint8_t> detailed = encode_or_die(mesh, options, &es);
    ASSERT_TRUE(es.detail);
    EXPECT_EQ(decode_or_die(detailed, decode, &ds_other).positions,
              decode_or_die(detailed, DecodeOptions(), &ds).positions);
  }
  // Without a choice, small meshes take AMD (encoder_ordering, ordering_choice.cpp).
  EncodeOptions options;
  options.solver = Solver::kGlobal;
  options.max_anchors = 30;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(bumpy_torus(30, 15), options, &es);
  EXPECT_EQ(es.ordering, Ordering::kAmd);
  EXPECT_EQ(file[11], kGabOrderingAmd);
}

TEST(EncodeDecode, EveryChunkPrefixIsTheEncodersShapeAtThatAnchorCount) {
  // In selection order a chunk prefix is a point of the greedy curve (the
  // level layout's prefixes: level_layout_test.cpp).
  const Mesh mesh = bumpy_torus(36, 18);
  EncodeOptions options;
  options.max_anchors = 120;
  options.chunk_growth = 1.5;
  options.layout = FileLayout::kSelectionOrder;
  options.solver = Solver::kGlobal;  // its greedy curve is the decoder's shapes
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  const Mesh numbered = in_decoded_numbering(mesh, es);
  int32_t k = 0;
  for (int32_t in_chunk : es.chunk_anchors) {
    k += in_chunk;
    DecodeOptions d;
    d.max_anchors = k;
    DecodeStats ds;
    const Mesh out = decode_or_die(file, d, &ds);
    EXPECT_EQ(ds.anchors, k);
    bool found = false;
    for (const GreedyStep& step : es.curve) {
      if (step.anchors != k) continue;
      found = true;
      EXPECT_NEAR(relative_rms(numbered, out), step.rms_rel, 1e-12) << k << " anchors";
    }
    EXPECT_TRUE(found) << "no reconstruction at " << k << " anchors";
  }
}

TEST(EncodeDecode, PartialChunkDecodesThatManyAnchorsAndChunkZeroWhole) {
  const Mesh mesh = bumpy_torus(30, 16);
  for (FileLayout layout : {FileLayout::kSelectionOrder, FileLayout::kLevels}) {
    EncodeOptions options;
    options.max_anchors = 60;
    options.initial_anchors = 10;
    options.layout = layout;
    EncodeStats es;
    const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
    ASSERT_EQ(es.chunk_anchors[0], 10);
    DecodeOptions d;
    d.max_anchors = 3;  // below chunk 0: chunk 0 still comes whole
    DecodeStats ds;
    decode_or_die(file, d, &ds);
    EXPECT_EQ(ds.anchors, 10);
    d.max_anchors = 13;
    decode_or_die(file, d, &ds);
    EXPECT_EQ(ds.anchors, 13);
    d.max_anchors = 1000;
    decode_or_die(file, d, &ds);
    EXPECT_EQ(ds.anchors, 60);
  }
}

TEST(EncodeDecode, RmsAndLinfTargetsStopTheLoop) {
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeOptions options;
  options.target_rms_rel = 2e-3;
  EncodeStats es;
  encode_or_die(mesh, options, &es);
  EXPECT_TRUE(es.target_met);
  EXPECT_LE(es.rms_rel, 2e-3);
  ASSERT_GE(es.curve.size(), 2u);
  // It stopped at the first step that met it, then (the iterative
  // operator) took back what of the last batch was not needed.
  size_t first_met = 0;
  while (first_met < es.curve.size() && es.curve[first_met].rms_rel > 2e-3) ++first_met;
  EXPECT_GE(first_met + 2, es.curve.size());
  EXPECT_GT(first_met, 0u);
  EXPECT_LE(es.curve.back().anchors, es.curve[first_met].anchors);
  EXPECT_EQ(es.curve.back().anchors, es.anchors);

  EncodeOptions linf;
  linf.target_linf_rel = 5e-3;
  encode_or_die(mesh, linf, &es);
  EXPECT_TRUE(es.target_met);
  EXPECT_LE(es.linf_rel, 5e-3);
}

TEST(EncodeDecode, UnreachableTargetAnchorsEverythingAndSaysSo) {
  const Mesh mesh = bumpy_torus(12, 8);
  EncodeOptions options;
  options.target_rms_rel = 1e-9;
  options.bits = 6;  // the grid alone is coarser than the target
  options.detail = DetailMode::kOff;  // (the detail layer's own limit: DetailLayer tests)
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  EXPECT_FALSE(es.target_met);
  EXPECT_EQ(es.anchors, mesh.num_vertices());
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  // Every vertex anchored with w = 100: the shape is the grid positions to ~1/w^2.
  EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, es), out), es.rms_rel, 1e-12);
}

TEST(EncodeDecode, GeometryOnlyNeedsTheRightConnectivity) {
  const Mesh mesh = bumpy_torus(24, 12);
  EncodeOptions options;
  options.max_anchors = 40;
  options.geometry_only = true;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  EXPECT_EQ(es.connectivity_bytes, 8u);  // the hash only
  Mesh out;
  DecodeStats ds;
  Status s = decode_mesh(file.data(), file.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(s.message(), "this file holds geometry only: give the mesh it was made from (--connectivity MESH)");
  DecodeOptions d;
  Mesh other = bumpy_torus(24, 12);
  std::swap(other.triangles[0], other.triangles[1]);  // same counts, other connectivity
  d.connectivity = &other;
  s = decode_mesh(file.data(), file.size(), d, &out, &ds);
  EXPECT_EQ(s.message(),
            "the connectivity mesh is not the one this file was made from (288 vertices, 576 triangles; the file "
            "expects 288 and 576, and a matching hash)");
  d.connectivity = &mesh;
  out = decode_or_die(file, d, &ds);
  EXPECT_NEAR(relative_rms(mesh, out), es.rms_rel, 1e-12);
}

TEST(EncodeDecode, ComponentsAndIsolatedVerticesEachGetAnAnchor) {
  Mesh mesh = bumpy_torus(16, 8);
  const Mesh g = testing_util::grid(5, 4, 0.1);
  const int32_t offset = mesh.num_vertices();
  mesh.positions.insert(mesh.positions.end(), g.positions.begin(), g.positions.end());
  for (int32_t i : g.triangles) mesh.triangles.push_back(i + offset);
  mesh.positions.insert(mesh.positions.end(), {3.0, 3.0, 3.0, -2.0, 1.0, 0.5});  // two isolated vertices
  EncodeOptions options;
  options.max_anchors = 30;
  options.initial_anchors = 1;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  EXPECT_EQ(es.chunk_anchors[0], 4);  // one per component
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  // An isolated anchor sits exactly on its grid point, within one step.
  const Mesh numbered = in_decoded_numbering(mesh, es);
  const int32_t last = es.reordered ? es.new_index.back() : mesh.num_vertices() - 1;  // the last isolated vertex
  const size_t iso = 3 * static_cast<size_t>(last);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(out.positions[iso + c], numbered.positions[iso + c], 6.0 / 4095);
  EXPECT_EQ(numbered.positions[iso], -2.0);  // the map found it
  EXPECT_NEAR(relative_rms(numbered, out), es.rms_rel, 1e-12);
}

TEST(EncodeDecode, FlatAndPointLikeMeshes) {
  // z = 0 everywhere: every z index is 0, so the decoded z is exactly 0.
  const Mesh flat = testing_util::grid(12, 9);
  EncodeOptions options;
  options.max_anchors = 20;
  EncodeStats es;
  std::vector<uint8_t> file = encode_or_die(flat, options, &es);
  DecodeStats ds;
  Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  for (int32_t v = 0; v < out.num_vertices(); ++v) EXPECT_EQ(out.positions[3 * static_cast<size_t>(v) + 2], 0.0);
  // Every vertex at one point: a zero-size grid.
  Mesh point = testing_util::grid(3, 3);
  for (size_t i = 0; i < point.positions.size(); ++i) point.positions[i] = 1.5;
  file = encode_or_die(point, options, &es);
  out = decode_or_die(file, DecodeOptions(), &ds);
  for (double x : out.positions) EXPECT_DOUBLE_EQ(x, 1.5);
  // Finite coordinates whose box overflows, or just past the format's
  // bound: refused, saying why; at the bound: a file that decodes.
  for (double far : {1e308, 1.0000001e100, 1e100}) {
    Mesh huge = testing_util::grid(3, 3);
    huge.positions[0] = -far;
    huge.positions[3] = far;
    const Status s = encode_mesh(huge, options, &file, &es);
    if (far == 1e100) {
      ASSERT_TRUE(s.ok()) << s.message();
      out = decode_or_die(file, DecodeOptions(), &ds);
      EXPECT_NEAR(out.positions[3], far, 1e-2 * far);
      continue;
    }
    EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
    EXPECT_EQ(s.message(),
              "mesh: a coordinate's magnitude is over 1e100 (the format's bound): scale the coordinates down");
  }
}

TEST(EncodeDecode, DecoderRefusesAFactorOverItsLimit) {
  const Mesh torus = testing_util::bumpy_torus(24, 12);
  EncodeOptions eo;
  eo.max_anchors = 30;
  eo.solver = Solver::kGlobal;  // a file with a factor
  EncodeStats es;
  const std::vector<uint8_t> file = testing_util::encode_or_die(torus, eo, &es);
  DecodeOptions options;
  options.max_factor_entries = 1000;  // the torus's factor stores several thousand
  Mesh out;
  DecodeStats ds;
  const Status s = decode_mesh(file.data(), file.size(), options, &out, &ds);
  EXPECT_EQ(s.code(), StatusCode::kResourceExhausted);  // the caller's limit, not a corrupt file
  EXPECT_EQ(s.message(), "the factor would exceed 1000 entries");
  options.max_factor_entries = DecodeOptions().max_factor_entries;
  EXPECT_TRUE(decode_mesh(file.data(), file.size(), options, &out, &ds).ok());
}

TEST(EncodeDecode, ReorderedFileDecodesToTheRenumberedMesh) {
  // Not a closed manifold: an isolated vertex, a degenerate triangle, a hole.
  Mesh mesh = bumpy_torus(24, 12);
  mesh.triangles.resize(mesh.triangles.size() - 6);
  mesh.positions.insert(mesh.positions.end(), {3.0, 0.0, 0.0});
  mesh.triangles.insert(mesh.triangles.end(), {5, 5, 7});
  EncodeOptions options;
  options.target_rms_rel = 2e-3;
  EXPECT_TRUE(options.reorder);  // the default (issue 34): the smallest file
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  ASSERT_TRUE(es.reordered);
  ASSERT_EQ(es.new_index.size(), static_cast<size_t>(mesh.num_vertices()));
  EncodeOptions kept = options;
  kept.reorder = false;
  EncodeStats kept_stats;
  const std::vector<uint8_t> kept_file = encode_or_die(mesh, kept, &kept_stats);
  // The same triangles either way; only the order block differs.
  EXPECT_EQ(es.connectivity_bytes, kept_stats.connectivity_bytes);
  EXPECT_EQ(es.order_bytes, 0u);
  EXPECT_GT(kept_stats.order_bytes, 0u);
  EXPECT_TRUE(kept_stats.new_index.empty());

  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  EXPECT_TRUE(ds.reordered);
  const Mesh renumbered = renumber_vertices(mesh, es.new_index);
  EXPECT_EQ(oriented_triangle_set(out.triangles), oriented_triangle_set(renumbered.triangles));
  EXPECT_NEAR(relative_rms(renumbered, out), es.rms_rel, 1e-12);
  EXPECT_LE(es.rms_rel, 2e-3);

  // Kept: the input's numbering, the isolated vertex and the degenerate
  // triangle included.
  const Mesh kept_out = decode_or_die(kept_file, DecodeOptions(), &ds);
  EXPECT_FALSE(ds.reordered);
  EXPECT_EQ(oriented_triangle_set(kept_out.triangles), oriented_triangle_set(mesh.triangles));
  EXPECT_NEAR(relative_rms(mesh, kept_out), kept_stats.rms_rel, 1e-12);
}

TEST(EncodeDecode, OptionErrors) {
  const Mesh mesh = bumpy_torus(8, 6);
  std::vector<uint8_t> file;
  EncodeStats es;
  EncodeOptions none;
  EXPECT_EQ(encode_mesh(mesh, none, &file, &es).message(),
            "set a stopping rule: an anchor count, an RMS or an L-inf target");
  EncodeOptions bits;
  bits.max_anchors = 5;
  bits.bits = 1;
  EXPECT_EQ(encode_mesh(mesh, bits, &file, &es).message(), "bits must be in 2..24");
  // A geometry-only file has no connectivity to number the vertices by: it
  // keeps the given mesh's numbering whatever reorder says.
  EncodeOptions geometry_only;
  geometry_only.max_anchors = 5;
  geometry_only.geometry_only = true;
  ASSERT_TRUE(geometry_only.reorder);
  ASSERT_TRUE(encode_mesh(mesh, geometry_only, &file, &es).ok());
  EXPECT_FALSE(es.reordered);
  EXPECT_TRUE(es.new_index.empty());
  EXPECT_EQ(es.order_bytes, 0u);
  EXPECT_EQ(file[9] & kGabFlagReordered, 0);
  std::vector<uint8_t> kept_file;
  geometry_only.reorder = false;
  ASSERT_TRUE(encode_mesh(mesh, geometry_only, &kept_file, &es).ok());
  EXPECT_EQ(kept_file, file);
  EncodeOptions weight;
  weight.max_anchors = 5;
  for (double w : {0.0, 2e100, std::numeric_limits<double>::infinity()}) {
    weight.weight = w;
    EXPECT_EQ(encode_mesh(mesh, weight, &file, &es).message(), "anchor weight must be in (0, 1e100]") << w;
  }
  Mesh empty;
  EXPECT_FALSE(encode_mesh(empty, bits, &file, &es).ok());
}

TEST(EncodeDecode, TheEncodersGridFollowsTheTarget) {
  // bits = 0: q from the error target, finer for a tighter one, the grid's
  // own RMS (step / 2 over the diagonal) inside the target; 12 for an anchor
  // count alone. (The anchors' grid alone: a detail layer may sit on a
  // coarser one, its own finer.)
  const Mesh mesh = bumpy_torus(40, 20);
  int previous_bits = 0;
  for (double target : {3e-3, 3e-4}) {
    EncodeOptions options;
    options.target_rms_rel = target;
    options.detail = DetailMode::kOff;
    EncodeStats es;
    const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
    EXPECT_TRUE(es.target_met) << target;
    EXPECT_GT(es.bits, previous_bits) << target;
    previous_bits = es.bits;
    GabFileInfo info;
    ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
    EXPECT_EQ(info.bits, es.bits);
    EXPECT_LE(info.step / 2 / bounding_box_diagonal(mesh), target) << target;
  }
  EncodeOptions count;
  count.max_anchors = 50;
  EncodeStats es;
  encode_or_die(mesh, count, &es);
  EXPECT_EQ(es.bits, 12);
}

TEST(EncodeDecode, FinerGridsCostMoreBitsAndErrLess) {
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeOptions coarse;
  coarse.max_anchors = 200;
  coarse.bits = 8;
  EncodeOptions fine = coarse;
  fine.bits = 14;
  EncodeStats a, b;
  encode_or_die(mesh, coarse, &a);
  encode_or_die(mesh, fine, &b);
  EXPECT_LT(a.geometry_bytes, b.geometry_bytes);
  EXPECT_GT(a.rms_rel, b.rms_rel);
}

}  // namespace
}  // namespace gab
