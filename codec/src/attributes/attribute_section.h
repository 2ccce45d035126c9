// One attribute in one trailing section of a .gab file (docs/format.md
// 6.2-6.4): its description, its quantization, then one range-coded stream
// walking the vertices in the corner table's visit order: per vertex the
// seams between its corners (per-corner attributes), then each new
// element's residual from a prediction over the elements already coded
// (the parallelogram across a decoded triangle, else the mean of decoded
// neighbours, else the previous element). Integer arithmetic only, so every
// decoder reproduces the encoder's integers; the connectivity alone drives
// it, so any level of detail decodes the attributes whole. Internal to the codec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "attributes/attribute_quantizer.h"
#include "attributes/corner_table.h"
#include "gab/mesh/mesh_attribute.h"
#include "gab/status.h"

namespace gab {

// The section kind (its payload's first byte) of an attribute.
constexpr uint8_t kGabSectionAttribute = 1;

// What coding one attribute did.
struct AttributeCoding {
  int bits = 0;             // its quantization's (integer-typed: the span's)
  bool per_corner = false;  // coded per corner (seams); false: per vertex
  int64_t elements = 0;     // elements coded: vertices, or wedges of corners with one value
  // The largest error of a decoded value: degrees between directions for
  // normals, value units otherwise (0: exact).
  double max_error = 0;
};

// The section's payload for `attribute` (valid for the mesh of `table`,
// numbered as the decoder returns it), quantized at `bits` (normals: the
// lattice's, 2..16; float-typed: the grid's, 1..31; integer-typed: ignored,
// exact). A per-corner attribute with no seam is coded per vertex.
// O(elements + corners).
std::vector<uint8_t> encode_attribute_section(const MeshAttribute& attribute, const CornerTable& table, int bits,
                                              AttributeCoding* coding);

// A section's description: what it holds and how it is quantized, read
// without decoding (gab info).
struct AttributeDescription {
  MeshAttribute attribute;  // kind, type, components, name; no values
  AttributeQuantizer quantizer;
  bool per_corner = false;
  uint64_t elements = 0;     // as declared
  size_t stream_offset = 0;  // where the range-coded stream starts in the payload
};
// kParseError / kUnsupported as decode_attribute_section. O(1).
Status read_attribute_description(const uint8_t* payload, size_t size, AttributeDescription* description);

// The attribute a section's payload describes, for the mesh of `table`.
// kParseError naming what is wrong; kUnsupported for a predictor or a kind
// this build does not know. O(payload + elements + corners).
Status decode_attribute_section(const uint8_t* payload, size_t size, const CornerTable& table,
                                MeshAttribute* attribute);

}  // namespace gab
