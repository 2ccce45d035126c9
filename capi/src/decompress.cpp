// gab_decompress, gab_decompress_ex, gab_decompress_options_init: the
// decoder (gab/codec/decoder.h) behind the C door. The decoder's contract on
// untrusted bytes holds here: errors, never reads outside `data`, memory
// within the options' budget.
#include <cstddef>
#include <cstdio>
#include <cstring>

#include "boundary.h"
#include "gab/codec/decoder.h"
#include "ordering_codes.h"

namespace gab {
namespace capi {

namespace {

// The caller's options (NULL: the defaults) as the decoder's.
Status read_options(const gab_decompress_options* in, DecodeOptions* out) {
  gab_decompress_options o;
  gab_decompress_options_init(&o, sizeof o);
  if (in != nullptr) {
    GAB_RETURN_IF_ERROR(check_options_size(in, in->size, sizeof o, "gab_decompress_options_init"));
#define GAB_TAKE(field) take_field(in, in->size, offsetof(gab_decompress_options, field), &o.field)
    GAB_TAKE(max_memory);
    GAB_TAKE(max_anchors);
    GAB_TAKE(threads);
    GAB_TAKE(ordering);
#undef GAB_TAKE
  }
  GAB_RETURN_IF_ERROR(options_threads(o.threads, &out->threads));
  GAB_RETURN_IF_ERROR(codec_ordering_of_code(o.ordering, &out->ordering));
  out->max_anchors = o.max_anchors < 0 ? -1 : o.max_anchors;
  out->max_memory = o.max_memory < 0 ? -1 : o.max_memory;
  return Status::Ok();
}

int decompress(const char* function, const unsigned char* data, size_t size, const DecodeOptions* fixed,
               const gab_decompress_options* options, double** positions, int32_t* n, int32_t** triangles,
               int32_t* t, char* message, size_t message_size) {
  DecodeStats stats;
  const int code = guarded(function, message, message_size, [&]() -> Status {
    GAB_RETURN_IF_ERROR(clear_mesh_outputs(positions, n, triangles, t));
    GAB_RETURN_IF_ERROR(require(data != nullptr || size == 0, "data is NULL"));
    static const unsigned char kEmpty = 0;
    DecodeOptions decode_options;
    if (fixed != nullptr) {
      decode_options = *fixed;
    } else {
      GAB_RETURN_IF_ERROR(read_options(options, &decode_options));
    }
    Mesh mesh;
    GAB_RETURN_IF_ERROR(decode_mesh(data != nullptr ? data : &kEmpty, size, decode_options, &mesh, &stats));
    return export_mesh(mesh, positions, n, triangles, t);
  });
  if (code != GAB_OK || !stats.truncated) return code;
  char text[160];
  std::snprintf(text, sizeof text, "the file is truncated: decoded %d of %d chunks (%d of %d anchors)", stats.chunks,
                stats.chunks_in_file, stats.anchors, stats.anchors_in_file);
  write_message(function, text, message, message_size);
  return GAB_W_TRUNCATED;
}

}  // namespace

}  // namespace capi
}  // namespace gab

extern "C" void gab_decompress_options_init(gab_decompress_options* options, size_t size) {
  gab_decompress_options o;
  std::memset(&o, 0, sizeof o);
  o.max_anchors = -1;
  o.threads = 1;
  o.ordering = GAB_ORDERING_AUTO;
  gab::capi::init_options(o, options, size);
}

extern "C" int gab_decompress(const unsigned char* data, size_t size, int32_t max_anchors, double** positions,
                              int32_t* n, int32_t** triangles, int32_t* t, char* message, size_t message_size) {
  gab::DecodeOptions options;
  options.max_anchors = max_anchors < 0 ? -1 : max_anchors;
  return gab::capi::decompress("gab_decompress", data, size, &options, nullptr, positions, n, triangles, t, message,
                               message_size);
}

extern "C" int gab_decompress_ex(const unsigned char* data, size_t size, const gab_decompress_options* options,
                                 double** positions, int32_t* n, int32_t** triangles, int32_t* t, char* message,
                                 size_t message_size) {
  return gab::capi::decompress("gab_decompress_ex", data, size, nullptr, options, positions, n, triangles, t,
                               message, message_size);
}
