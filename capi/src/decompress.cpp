// gab_decompress: the decoder (gab/codec/decoder.h) behind the C door. The
// decoder's contract on untrusted bytes holds here: errors, never reads
// outside `data`.
#include "boundary.h"
#include "gab/codec/decoder.h"

extern "C" int gab_decompress(const unsigned char* data, size_t size, int32_t max_anchors, double** positions,
                              int32_t* n, int32_t** triangles, int32_t* t, char* message, size_t message_size) {
  using namespace gab;
  using capi::require;
  return capi::guarded("gab_decompress", message, message_size, [&]() -> Status {
    GAB_RETURN_IF_ERROR(capi::clear_mesh_outputs(positions, n, triangles, t));
    GAB_RETURN_IF_ERROR(require(data != nullptr || size == 0, "data is NULL"));
    static const unsigned char kEmpty = 0;
    DecodeOptions options;
    options.max_anchors = max_anchors < 0 ? -1 : max_anchors;
    Mesh mesh;
    DecodeStats stats;
    GAB_RETURN_IF_ERROR(decode_mesh(data != nullptr ? data : &kEmpty, size, options, &mesh, &stats));
    return capi::export_mesh(mesh, positions, n, triangles, t);
  });
}
