// The encoder's search (encode_candidates.h): which candidate files it codes
// for which options, and what EncodeStats::candidates reports of them.
#include "pipeline/encode_candidates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "common/gab_files.h"
#include "common/test_meshes.h"
#include "gab/codec/encoder.h"
#include "pipeline/encoder_tuning.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::encode_or_die;

// A 100k-vertex mesh whose box is a cube (extent / diagonal = 1 / sqrt(3)).
MeshSize cube_box() {
  MeshSize size;
  size.num_vertices = 100000;
  size.extent = 1;
  size.diagonal = std::sqrt(3.0);
  return size;
}

EncodeOptions rms(double target) {
  EncodeOptions o;
  o.target_rms_rel = target;
  return o;
}

std::vector<std::string> names(const std::vector<EncodeCandidate>& candidates) {
  std::vector<std::string> out;
  for (const EncodeCandidate& c : candidates) out.push_back(c.name + std::string(c.rescue_only ? " (rescue)" : ""));
  return out;
}

using Names = std::vector<std::string>;

TEST(EncodeCandidates, TheTargetPicksAnchorsAloneADetailLayerOrBoth) {
  const MeshSize size = cube_box();
  EXPECT_EQ(names(encode_candidates(rms(1e-3), size)),
            (Names{"anchors", "detail (rescue)", "detail over coarse anchors (rescue)"}));
  EXPECT_EQ(names(encode_candidates(rms(3e-4), size)), (Names{"anchors", "detail", "detail over coarse anchors"}));
  EXPECT_EQ(names(encode_candidates(rms(1e-4), size)), (Names{"detail", "detail over coarse anchors"}));
  // An L-inf target counts as kLinfOverRms times the RMS one.
  EncodeOptions linf;
  linf.target_linf_rel = kLinfOverRms * 3e-4;
  EXPECT_EQ(names(encode_candidates(linf, size)), (Names{"anchors", "detail", "detail over coarse anchors"}));
}

TEST(EncodeCandidates, OptionsNarrowTheSearch) {
  const MeshSize size = cube_box();
  EncodeOptions o = rms(1e-4);
  o.detail = DetailMode::kOff;
  EXPECT_EQ(names(encode_candidates(o, size)), (Names{"anchors"}));
  o.detail = DetailMode::kOn;
  o.target_rms_rel = 1e-3;  // on: the detail layer whatever the target
  EXPECT_EQ(names(encode_candidates(o, size)), (Names{"detail", "detail over coarse anchors"}));
  o.bits = 9;  // a fixed q: both detail candidates would have the same grid
  EXPECT_EQ(names(encode_candidates(o, size)), (Names{"detail"}));
  EncodeOptions count;
  count.max_anchors = 40;
  EXPECT_EQ(names(encode_candidates(count, size)), (Names{"anchors"}));
  MeshSize flat = size;
  flat.extent = flat.diagonal = 0;  // one point: nothing for a detail layer to scale by
  EXPECT_EQ(names(encode_candidates(rms(1e-4), flat)), (Names{"anchors"}));
}

TEST(EncodeCandidates, TheCallersTargetReachesTheRightLoop) {
  const MeshSize size = cube_box();
  EncodeOptions o = rms(3e-4);
  o.refine = true;
  o.max_anchors = 20000;
  o.initial_anchors = 300;
  const std::vector<EncodeCandidate> c = encode_candidates(o, size);
  ASSERT_EQ(c.size(), 3u);
  // Anchors alone: the caller's rules, on the default grid for the target.
  EXPECT_EQ(c[0].anchors.target_rms_rel, 3e-4);
  EXPECT_TRUE(c[0].anchors.refine);
  EXPECT_EQ(c[0].anchors.max_anchors, 20000);
  EXPECT_EQ(c[0].anchors.bits, default_bits(1 / std::sqrt(3.0), 3e-4, 0));
  EXPECT_FALSE(c[0].detail);
  // Under a detail layer: a coarse target, no refinement, the count capped.
  for (size_t i = 1; i < 3; ++i) {
    EXPECT_TRUE(c[i].detail);
    EXPECT_EQ(c[i].anchors.target_rms_rel, std::max(kDetailAnchorTarget, kAnchorTargetOverTarget * 3e-4));
    EXPECT_EQ(c[i].anchors.target_linf_rel, 0);
    EXPECT_TRUE(c[i].anchors.stop_at_grid_reach);
    EXPECT_FALSE(c[i].anchors.refine);
    EXPECT_EQ(c[i].anchors.initial_anchors, 300);
    EXPECT_EQ(c[i].anchors.max_anchors, 20000);
  }
  EXPECT_EQ(c[2].anchors.bits, kCoarseAnchorBits);
  // Below kSpreadOnlyBelow the coarse candidate keeps the spread set alone.
  const std::vector<EncodeCandidate> fine = encode_candidates(rms(3e-5), size);
  ASSERT_EQ(fine.size(), 2u);
  EXPECT_EQ(fine[1].anchors.max_anchors, fine[1].anchors.initial_anchors);
  EXPECT_EQ(fine[1].anchors.initial_anchors, static_cast<int32_t>(size.num_vertices * kDetailSpreadShare));
  EXPECT_EQ(fine[0].anchors.max_anchors, static_cast<int32_t>(size.num_vertices * kDetailMaxAnchorShare));
}

TEST(EncodeCandidates, TheDenseRetryIsACoarserGridOnceOnly) {
  const MeshSize size = cube_box();
  const EncodeOptions o = rms(1e-3);
  const EncodeCandidate anchors = encode_candidates(o, size).front();
  EncodeCandidate retry;
  const int32_t half = size.num_vertices / 2;
  EXPECT_FALSE(dense_grid_candidate(o, size, anchors, half, &retry));  // not over half
  ASSERT_TRUE(dense_grid_candidate(o, size, anchors, half + 1, &retry));
  EXPECT_STREQ(retry.name, "anchors on a coarser grid");
  EXPECT_LE(retry.anchors.bits, anchors.anchors.bits);
  EXPECT_EQ(retry.anchors.min_step_rel, 2 * kDenseGridShare * 1e-3);
  EXPECT_EQ(retry.anchors.target_rms_rel, 1e-3);
  EXPECT_FALSE(dense_grid_candidate(o, size, retry, size.num_vertices, &retry));  // never a retry of a retry
  EncodeOptions fixed = o;
  fixed.bits = 9;
  EXPECT_FALSE(dense_grid_candidate(fixed, size, encode_candidates(fixed, size).front(), half + 1, &retry));
  EncodeOptions linf;
  linf.target_linf_rel = 4e-3;  // no RMS target to size the grid by
  EXPECT_FALSE(dense_grid_candidate(linf, size, encode_candidates(linf, size).front(), half + 1, &retry));
}

TEST(EncodeCandidates, StatsListEveryCandidateAndKeepTheFileReturned) {
  const Mesh mesh = bumpy_torus(50, 25);
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, rms(3e-4), &es);
  ASSERT_EQ(es.candidates.size(), 3u);
  EXPECT_EQ(es.candidates[0].name, "anchors");
  EXPECT_EQ(es.candidates[1].name, "detail");
  EXPECT_EQ(es.candidates[2].name, "detail over coarse anchors");
  size_t best_estimate = SIZE_MAX;
  int kept = 0;
  for (const EncodeStats::Candidate& c : es.candidates) {
    EXPECT_GT(c.anchors, 0);
    EXPECT_GT(c.estimate_bytes, 0u);
    EXPECT_GT(c.seconds, 0);
    best_estimate = std::min(best_estimate, c.estimate_bytes);
    if (c.kept) {
      ++kept;
      EXPECT_EQ(c.bytes, file.size());
      EXPECT_EQ(c.bits, es.bits);
      EXPECT_EQ(c.anchors, es.anchors);
      EXPECT_EQ(c.name != "anchors", es.detail);
    }
  }
  EXPECT_EQ(kept, 1);
  for (const EncodeStats::Candidate& c : es.candidates) {
    // The best estimate is always finished; the file kept is the smallest
    // finished (all meet the target here).
    if (c.estimate_bytes == best_estimate) {
      EXPECT_GT(c.bytes, 0u) << c.name;
    }
    if (c.bytes > 0) {
      EXPECT_GE(c.bytes, file.size()) << c.name;
    }
  }
  // An anchor count alone: one candidate, kept.
  EncodeOptions count;
  count.max_anchors = 40;
  encode_or_die(mesh, count, &es);
  ASSERT_EQ(es.candidates.size(), 1u);
  EXPECT_TRUE(es.candidates[0].kept);
  EXPECT_EQ(es.candidates[0].bytes, es.bytes);
}

}  // namespace
}  // namespace gab
