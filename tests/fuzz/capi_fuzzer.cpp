// libFuzzer target: the C API's decoder entry point, gab_decompress, on
// untrusted bytes (issue 20: the C boundary fed hostile bytes). The first
// input byte picks max_anchors (bit 0 set: a prefix of byte >> 1 anchors,
// else the whole file); the rest is the file. Checks beyond "no crash": a
// failure is a known code with a one-line message starting
// "gab_decompress: " and NULL / 0 outputs; a success is a mesh with finite
// coordinates and triangles inside it, its message empty or naming the
// attributes it does not return, and so is a file cut short
// (GAB_W_TRUNCATED), its message saying so; gab_decompress_with_attributes
// ends the same way, every attribute it returns inside its mesh. The default decode limit (64 MiB for
// a file this small) bounds what a forged file can ask for.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "fuzz_check.h"
#include "gab/gab.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t* file = data + 1;
  const size_t file_size = size - 1;
  const int32_t max_anchors = (data[0] & 1) ? data[0] >> 1 : -1;
  double* positions = nullptr;
  int32_t* triangles = nullptr;
  int32_t n = -1, t = -1;
  char message[256];
  const int code = gab_decompress(file, file_size, max_anchors, &positions, &n, &triangles, &t, message,
                                  sizeof message);
  if (code == GAB_W_TRUNCATED) {
    gab_fuzz::require(std::strncmp(message, "gab_decompress: the file is truncated: ", 39) == 0,
                      "truncation without its message");
  } else if (code != GAB_OK) {
    gab_fuzz::require(code > GAB_OK && code <= GAB_E_INTERNAL && code != GAB_E_INTERNAL, "unknown or internal code");
    gab_fuzz::require(std::strncmp(message, "gab_decompress: ", 16) == 0, "message without the function's name");
    gab_fuzz::require(std::strchr(message, '\n') == nullptr, "message spans lines");
    gab_fuzz::require(positions == nullptr && triangles == nullptr && n == 0 && t == 0, "outputs set on failure");
    return 0;
  }
  // A success says nothing, or names the attributes gab_decompress does not
  // return (gab.h), on one line.
  gab_fuzz::require(code == GAB_W_TRUNCATED || message[0] == '\0' ||
                        std::strncmp(message, "gab_decompress: not returned: ", 30) == 0,
                    "message on success");
  gab_fuzz::require(std::strchr(message, '\n') == nullptr, "message spans lines");
  gab_fuzz::require(n > 0 && t > 0 && positions != nullptr && triangles != nullptr, "empty mesh on success");
  for (int64_t i = 0; i < 3 * int64_t{n}; ++i) gab_fuzz::require(std::isfinite(positions[i]), "non-finite coordinate");
  for (int64_t i = 0; i < 3 * int64_t{t}; ++i) {
    gab_fuzz::require(triangles[i] >= 0 && triangles[i] < n, "triangle index out of range");
  }
  gab_free(positions);
  gab_free(triangles);
  // The attribute door on the same bytes: the same outcome, and every
  // attribute it returns inside its mesh (its one block freed).
  gab_decompress_options options;
  gab_decompress_options_init(&options, sizeof options);
  options.max_anchors = max_anchors;
  gab_attribute* attributes = nullptr;
  int32_t count = -1;
  const int with = gab_decompress_with_attributes(file, file_size, &options, &positions, &n, &triangles, &t,
                                                  &attributes, &count, message, sizeof message);
  gab_fuzz::require(with == code, "the attribute door ends otherwise");
  gab_fuzz::require(count >= 0 && count <= GAB_MAX_ATTRIBUTES && (count == 0) == (attributes == nullptr),
                    "attribute count and array disagree");
  for (int32_t a = 0; a < count; ++a) {
    const gab_attribute& at = attributes[a];
    gab_fuzz::require(at.components >= 1 && at.components <= 4 && at.elements >= 0, "attribute shape");
    for (int64_t i = 0; i < int64_t{at.components} * at.elements; ++i) {
      gab_fuzz::require(std::isfinite(at.values[i]), "non-finite attribute value");
    }
    if (at.corners == nullptr) {
      gab_fuzz::require(at.elements == n, "per-vertex attribute of another size");
    } else {
      for (int64_t i = 0; i < 3 * int64_t{t}; ++i) {
        gab_fuzz::require(at.corners[i] >= 0 && at.corners[i] < at.elements, "corner index out of range");
      }
    }
  }
  gab_free(attributes);
  gab_free(positions);
  gab_free(triangles);
  return 0;
}
