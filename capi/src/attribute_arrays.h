// Attributes across the C boundary (gab.h's gab_attribute and
// gab_attribute_stats): the caller's arrays in, checked field by field; one
// malloc'd block out; and the words a message uses for what a door did not
// return.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gab/codec/encoder.h"
#include "gab/gab.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {
namespace capi {

// The caller's `count` attributes for a mesh of n vertices and t triangles
// (checked by import_mesh first), appended to mesh->attributes: every field
// checked with a message naming it ("attributes[1].corners[7] is 12: out of
// range [0, 4)"), then the mesh layer's checks (finite values, integer
// types' ranges, a generic's name). O(values + corners).
Status import_attributes(const gab_attribute* attributes, int32_t count, Mesh* mesh);

// The attributes as one malloc'd block (the structs, then the values, the
// corners and the names), released with one gab_free; NULL and 0 when
// there are none. `out` and `count` are set only on success.
Status export_attributes(const std::vector<MeshAttribute>& attributes, gab_attribute** out, int32_t* count);

// The encoder's per-attribute figures as one malloc'd block (the structs,
// then the labels); `kinds` the coded attributes' kinds, in the same order.
// NULL when there are none.
Status export_attribute_stats(const std::vector<AttributeStats>& stats, const std::vector<AttributeKind>& kinds,
                              gab_attribute_stats** out);

// "762 normals (per corner), 12 generic:quality (per vertex)": the
// attributes a door read or decoded and does not return, for its message.
std::string describe_attributes(const std::vector<MeshAttribute>& attributes);

// Sets *attributes and *count to NULL / 0 when given; fails naming the
// one that is NULL.
Status clear_attribute_outputs(gab_attribute** attributes, int32_t* count);

}  // namespace capi
}  // namespace gab
