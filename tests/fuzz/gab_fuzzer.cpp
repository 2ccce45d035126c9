// libFuzzer target: the .gab decoder on untrusted bytes. The first input
// byte picks the decoder's options (bit 0: supply the connectivity a
// geometry-only seed was made from; bit 1: decode only a prefix of the
// anchors, bits 2-7 their count; else bit 2: decode on two threads too,
// which must give the same outcome and the same bits); the rest is the file. Checks beyond "no crash": a failure is a
// one-line message; a success is a mesh of the declared size with finite
// coordinates and valid triangles; read_gab_info agrees on the counts (and, for a full decode, on validity);
// find_gab_chunk_ends (the viewer's streaming cut points) lists increasing ends inside the input, no more
// than the header declares, and finds the head of every file that decodes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fuzz_check.h"
#include "gab/codec/decoder.h"
#include "gab_fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const gab::Mesh connectivity = gab_fuzz::seed_torus();
  gab::DecodeOptions options;
  options.connectivity = (data[0] & 1) ? &connectivity : nullptr;
  options.max_anchors = (data[0] & 2) ? data[0] >> 2 : -1;
  // The default decode limits (max_memory: 64 MiB for a file this small)
  // are what keeps forged counts within the fuzzer's memory limit.
  gab::Mesh mesh;
  gab::DecodeStats stats;
  const gab::Status status = gab::decode_mesh(data + 1, size - 1, options, &mesh, &stats);
  gab::GabFileInfo info;
  const gab::Status info_status = gab::read_gab_info(data + 1, size - 1, &info);
  gab::GabStreamFrames frames;
  const gab::Status frames_status = gab::find_gab_chunk_ends(data + 1, size - 1, &frames);
  if (frames_status.ok()) {
    gab_fuzz::require(frames.head_complete || frames.chunk_ends.empty(), "chunk ends before the head");
    gab_fuzz::require(frames.chunk_ends.size() <= static_cast<size_t>(std::max(0, frames.chunks_in_file)),
                      "more chunk ends than chunks");
    for (size_t i = 0; i < frames.chunk_ends.size(); ++i) {
      gab_fuzz::require(frames.chunk_ends[i] <= size - 1, "chunk end past the input");
      gab_fuzz::require(i == 0 || frames.chunk_ends[i] > frames.chunk_ends[i - 1], "chunk ends not increasing");
    }
  } else {
    gab_fuzz::require(!frames_status.message().empty(), "empty error message");
    gab_fuzz::require(frames_status.message().find('\n') == std::string::npos, "error message spans lines");
  }
  if ((data[0] & 6) == 4) {
    gab::DecodeOptions two = options;
    two.threads = 2;
    gab::Mesh other;
    gab::DecodeStats other_stats;
    const gab::Status other_status = gab::decode_mesh(data + 1, size - 1, two, &other, &other_stats);
    gab_fuzz::require(other_status.code() == status.code(), "two threads end otherwise");
    gab_fuzz::require(!status.ok() || other.positions == mesh.positions, "two threads decode other bits");
  }
  if (!status.ok()) {
    gab_fuzz::require(!status.message().empty(), "empty error message");
    gab_fuzz::require(status.message().find('\n') == std::string::npos, "error message spans lines");
    return 0;
  }
  // A prefix decode never looks at the later chunks; a full one has
  // checked everything info checks.
  if (options.max_anchors < 0) gab_fuzz::require(info_status.ok(), "decodes but info fails");
  gab_fuzz::require(frames_status.ok() && frames.head_complete, "decodes but its head is not found");
  gab_fuzz::require(!info_status.ok() || (info.num_vertices == stats.num_vertices &&
                                           info.anchors == stats.anchors_in_file),
                    "info and decoder disagree");
  gab_fuzz::require(mesh.positions.size() == 3 * static_cast<size_t>(stats.num_vertices), "wrong vertex count");
  for (double x : mesh.positions) gab_fuzz::require(std::isfinite(x), "non-finite coordinate");
  gab_fuzz::require(gab::validate_mesh(mesh, "decoded").ok(), "decoded mesh is invalid");
  return 0;
}
