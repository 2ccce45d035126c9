// The browser's door to the decoder: a few C functions over gab::decode_mesh
// for web/viewer.js (built to WebAssembly by scripts/build-web.sh).
//
// The page receives a .gab file as a stream. It copies the bytes into the
// buffer gab_web_buffer() hands out, asks gab_web_frames() how many chunks
// are complete (gab::find_gab_chunk_ends), and calls gab_web_decode() on a
// prefix each time another chunk has arrived. Each call decodes that
// prefix from the start: the decoder
// keeps no state between calls (a prefix of whole chunks is a valid file,
// so this needs nothing new from the codec; the cost is one whole decode
// per level shown, and the page skips levels that were overtaken while it
// decoded).
//
// One decoding at a time (the page is single-threaded); the results live
// here until the next call. Every function returns a value or a pointer
// into the module's memory: no exceptions cross this boundary, errors are a
// return code plus gab_web_message().
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gab/codec/decoder.h"

#if defined(__EMSCRIPTEN__)
#include <emscripten/emscripten.h>
#define GAB_WEB_EXPORT extern "C" EMSCRIPTEN_KEEPALIVE
#else
#define GAB_WEB_EXPORT extern "C"
#endif

namespace {

// Limits well inside wasm32's memory (2 GiB with ALLOW_MEMORY_GROWTH): a
// hostile file is refused with a message instead of running the module out
// of memory. 2^25 matrix entries and 2^27 factor entries (1 GiB of doubles)
// leave room for meshes of a few million vertices.
constexpr int64_t kMaxMatrixEntries = int64_t{1} << 25;
constexpr int64_t kMaxFactorEntries = int64_t{1} << 27;

struct WebState {
  std::vector<uint8_t> input;         // the bytes received so far (grown by gab_web_buffer)
  std::vector<size_t> chunk_ends;     // byte offset just past each complete chunk
  std::vector<float> positions;       // 3 per vertex, of the last decoding
  std::vector<uint32_t> triangles;    // 3 per triangle
  gab::DecodeStats stats;
  std::string message;                // the last error
};

WebState& state() {
  static WebState s;
  return s;
}

int fail(const gab::Status& status) {
  state().message = status.message();
  return -2;
}

}  // namespace

// A buffer of at least `capacity` bytes holding the bytes given so far
// (their contents kept when it grows). Memory too short for it aborts the
// module (no exceptions in this build), which the page reports. O(capacity).
GAB_WEB_EXPORT uint8_t* gab_web_buffer(size_t capacity) {
  std::vector<uint8_t>& input = state().input;
  if (capacity > input.size()) input.resize(capacity);
  return input.data();
}

// How many chunks of the first `size` buffer bytes are complete: >= 0;
// -1 when the header or the connectivity section has not fully arrived;
// -2 on a bad header (gab_web_message()). O(chunks).
GAB_WEB_EXPORT int32_t gab_web_frames(size_t size) {
  WebState& s = state();
  s.chunk_ends.clear();
  if (size > s.input.size()) size = s.input.size();
  gab::GabStreamFrames frames;
  const gab::Status status = gab::find_gab_chunk_ends(s.input.data(), size, &frames);
  if (!status.ok()) return fail(status);
  if (!frames.head_complete) return -1;
  s.chunk_ends = std::move(frames.chunk_ends);
  return static_cast<int32_t>(s.chunk_ends.size());
}

// The byte offset just past complete chunk `chunk` (of the last
// gab_web_frames call), or 0 when there is none such.
GAB_WEB_EXPORT double gab_web_chunk_end(int32_t chunk) {
  const std::vector<size_t>& ends = state().chunk_ends;
  if (chunk < 0 || static_cast<size_t>(chunk) >= ends.size()) return 0;
  return static_cast<double>(ends[chunk]);
}

// Decodes the first `size` buffer bytes (a whole file or a prefix of it;
// max_anchors < 0: every anchor there). 0 on success, then the getters
// below describe the shape; -2 on a bad file (gab_web_message()).
// Cost: one whole decode of the prefix.
GAB_WEB_EXPORT int32_t gab_web_decode(size_t size, int32_t max_anchors) {
  WebState& s = state();
  if (size > s.input.size()) size = s.input.size();
  gab::DecodeOptions options;
  options.max_anchors = max_anchors;
  options.threads = 1;  // no pthreads in this build: the engine's serial paths only
  options.max_matrix_entries = kMaxMatrixEntries;
  options.max_factor_entries = kMaxFactorEntries;
  // Those entry limits bound the decode by the browser's memory; the
  // budget by the file's size would judge a prefix, not the file.
  options.max_memory = -1;
  gab::Mesh mesh;
  const gab::Status status = gab::decode_mesh(s.input.data(), size, options, &mesh, &s.stats);
  s.positions.clear();
  s.triangles.clear();
  if (!status.ok()) return fail(status);
  s.positions.assign(mesh.positions.begin(), mesh.positions.end());
  s.triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
  s.message.clear();
  return 0;
}

GAB_WEB_EXPORT int32_t gab_web_vertices() { return static_cast<int32_t>(state().positions.size() / 3); }
GAB_WEB_EXPORT int32_t gab_web_triangles() { return static_cast<int32_t>(state().triangles.size() / 3); }
GAB_WEB_EXPORT const float* gab_web_positions() { return state().positions.data(); }
GAB_WEB_EXPORT const uint32_t* gab_web_indices() { return state().triangles.data(); }
GAB_WEB_EXPORT int32_t gab_web_anchors() { return state().stats.anchors; }
GAB_WEB_EXPORT int32_t gab_web_anchors_in_file() { return state().stats.anchors_in_file; }
GAB_WEB_EXPORT int32_t gab_web_chunks() { return state().stats.chunks; }
GAB_WEB_EXPORT int32_t gab_web_chunks_in_file() { return state().stats.chunks_in_file; }
GAB_WEB_EXPORT int32_t gab_web_truncated() { return state().stats.truncated ? 1 : 0; }
GAB_WEB_EXPORT int32_t gab_web_refined() { return state().stats.refined ? 1 : 0; }
GAB_WEB_EXPORT int32_t gab_web_detail() { return state().stats.detail ? 1 : 0; }
GAB_WEB_EXPORT double gab_web_decode_seconds() { return state().stats.decode_s; }
GAB_WEB_EXPORT const char* gab_web_message() { return state().message.c_str(); }
