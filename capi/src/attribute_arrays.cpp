// Attributes across the C boundary (attribute_arrays.h).
#include "attribute_arrays.h"

#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "boundary.h"

namespace gab {
namespace capi {

// gab.h's codes are the mesh layer's enumerators, so a checked code casts.
static_assert(GAB_ATTRIBUTE_NORMAL == static_cast<int>(AttributeKind::kNormal) &&
                  GAB_ATTRIBUTE_TEXCOORD == static_cast<int>(AttributeKind::kTexCoord) &&
                  GAB_ATTRIBUTE_COLOR == static_cast<int>(AttributeKind::kColor) &&
                  GAB_ATTRIBUTE_GENERIC == static_cast<int>(AttributeKind::kGeneric),
              "GAB_ATTRIBUTE_* are AttributeKind's values");
static_assert(GAB_VALUE_INT8 == static_cast<int>(ValueType::kInt8) &&
                  GAB_VALUE_UINT8 == static_cast<int>(ValueType::kUint8) &&
                  GAB_VALUE_INT16 == static_cast<int>(ValueType::kInt16) &&
                  GAB_VALUE_UINT16 == static_cast<int>(ValueType::kUint16) &&
                  GAB_VALUE_INT32 == static_cast<int>(ValueType::kInt32) &&
                  GAB_VALUE_UINT32 == static_cast<int>(ValueType::kUint32) &&
                  GAB_VALUE_FLOAT32 == static_cast<int>(ValueType::kFloat32) &&
                  GAB_VALUE_FLOAT64 == static_cast<int>(ValueType::kFloat64),
              "GAB_VALUE_* are ValueType's values");
static_assert(GAB_MAX_ATTRIBUTES == kMaxMeshAttributes, "gab.h's limit is the mesh layer's");

namespace {

// The components each kind holds, as a message says it.
const char* components_rule(int32_t kind) {
  switch (kind) {
    case GAB_ATTRIBUTE_NORMAL: return "GAB_ATTRIBUTE_NORMAL has 3";
    case GAB_ATTRIBUTE_TEXCOORD: return "GAB_ATTRIBUTE_TEXCOORD has 2 or 3";
    case GAB_ATTRIBUTE_COLOR: return "GAB_ATTRIBUTE_COLOR has 3 or 4";
  }
  return "GAB_ATTRIBUTE_GENERIC has 1 to 4";
}

// One attribute's fields, in the order a reader of the struct meets them;
// `where` is "attributes[i]".
Status import_attribute(const gab_attribute& in, const std::string& where, int32_t n, int32_t t,
                        MeshAttribute* out) {
  GAB_RETURN_IF_ERROR(require(in.kind >= GAB_ATTRIBUTE_NORMAL && in.kind <= GAB_ATTRIBUTE_GENERIC,
                              where + ".kind is " + std::to_string(in.kind) +
                                  ": must be GAB_ATTRIBUTE_NORMAL, GAB_ATTRIBUTE_TEXCOORD, GAB_ATTRIBUTE_COLOR or "
                                  "GAB_ATTRIBUTE_GENERIC"));
  GAB_RETURN_IF_ERROR(require(in.value_type >= GAB_VALUE_INT8 && in.value_type <= GAB_VALUE_FLOAT64,
                              where + ".value_type is " + std::to_string(in.value_type) +
                                  ": must be one of GAB_VALUE_INT8 .. GAB_VALUE_FLOAT64 (0..7)"));
  const AttributeKind kind = static_cast<AttributeKind>(in.kind);
  GAB_RETURN_IF_ERROR(require(valid_attribute_components(kind, in.components),
                              where + ".components is " + std::to_string(in.components) + ": " +
                                  components_rule(in.kind)));
  const bool named = in.name != nullptr && in.name[0] != '\0';
  if (in.kind == GAB_ATTRIBUTE_GENERIC) {
    GAB_RETURN_IF_ERROR(require(named, where + ".name is " + (in.name == nullptr ? "NULL" : "\"\"") +
                                           ": a generic attribute is named"));
  } else {
    GAB_RETURN_IF_ERROR(require(!named, where + ".name is \"" + std::string(in.name != nullptr ? in.name : "") +
                                            "\": only a generic attribute has a name (NULL or \"\")"));
  }
  const bool per_corner = in.corners != nullptr;
  if (per_corner) {
    GAB_RETURN_IF_ERROR(require(in.elements > 0, where + ".elements is " + std::to_string(in.elements) +
                                                     ": a per-corner attribute has at least one element"));
  } else {
    GAB_RETURN_IF_ERROR(require(in.elements == n, where + ".elements is " + std::to_string(in.elements) +
                                                      ": per vertex (corners NULL) it is n = " + std::to_string(n)));
  }
  GAB_RETURN_IF_ERROR(require(in.values != nullptr, where + ".values is NULL"));
  if (per_corner) {
    const size_t corners = 3 * static_cast<size_t>(t);
    for (size_t c = 0; c < corners; ++c) {
      if (in.corners[c] < 0 || in.corners[c] >= in.elements) {
        return invalid(where + ".corners[" + std::to_string(c) + "] is " + std::to_string(in.corners[c]) +
                       ": out of range [0, " + std::to_string(in.elements) + ")");
      }
    }
    out->corners.assign(in.corners, in.corners + corners);
  }
  out->kind = kind;
  out->type = static_cast<ValueType>(in.value_type);
  out->name = in.kind == GAB_ATTRIBUTE_GENERIC ? in.name : "";
  out->components = in.components;
  out->values.assign(in.values, in.values + static_cast<size_t>(in.elements) * static_cast<size_t>(in.components));
  // What is left is the mesh layer's: finite values, integer types' ranges, a generic's spelling.
  return validate_attribute(*out, n, t, where);
}

size_t aligned(size_t offset, size_t alignment) { return (offset + alignment - 1) / alignment * alignment; }

}  // namespace

Status import_attributes(const gab_attribute* attributes, int32_t count, Mesh* mesh) {
  GAB_RETURN_IF_ERROR(require(count >= 0 && count <= GAB_MAX_ATTRIBUTES,
                              "num_attributes is " + std::to_string(count) + ": must be in 0.." +
                                  std::to_string(GAB_MAX_ATTRIBUTES) + " (GAB_MAX_ATTRIBUTES)"));
  GAB_RETURN_IF_ERROR(require(attributes != nullptr || count == 0,
                              "attributes is NULL and num_attributes is " + std::to_string(count)));
  mesh->attributes.resize(static_cast<size_t>(count));
  for (int32_t i = 0; i < count; ++i) {
    GAB_RETURN_IF_ERROR(import_attribute(attributes[i], "attributes[" + std::to_string(i) + "]",
                                         mesh->num_vertices(), mesh->num_triangles(), &mesh->attributes[i]));
  }
  return Status::Ok();
}

Status export_attributes(const std::vector<MeshAttribute>& attributes, gab_attribute** out, int32_t* count) {
  if (attributes.empty()) {
    *out = nullptr;
    *count = 0;
    return Status::Ok();
  }
  // The block: the structs, the values, the corners, the names (NUL-terminated).
  size_t values = 0, corners = 0, names = 0;
  for (const MeshAttribute& a : attributes) {
    values += a.values.size();
    corners += a.corners.size();
    names += a.name.size() + 1;
  }
  const size_t values_at = aligned(attributes.size() * sizeof(gab_attribute), alignof(double));
  const size_t corners_at = aligned(values_at + values * sizeof(double), alignof(int32_t));
  const size_t names_at = corners_at + corners * sizeof(int32_t);
  unsigned char* block = static_cast<unsigned char*>(std::malloc(names_at + names));
  if (block == nullptr) return Status::Error(StatusCode::kOutOfMemory, "cannot allocate the attributes");
  gab_attribute* structs = reinterpret_cast<gab_attribute*>(block);
  double* value = reinterpret_cast<double*>(block + values_at);
  int32_t* corner = reinterpret_cast<int32_t*>(block + corners_at);
  char* name = reinterpret_cast<char*>(block + names_at);
  for (size_t i = 0; i < attributes.size(); ++i) {
    const MeshAttribute& a = attributes[i];
    gab_attribute& s = structs[i];
    s.kind = static_cast<int32_t>(a.kind);
    s.value_type = static_cast<int32_t>(a.type);
    s.components = a.components;
    s.elements = static_cast<int32_t>(a.num_elements());  // validated meshes: below 2^31
    s.values = value;
    if (!a.values.empty()) std::memcpy(value, a.values.data(), a.values.size() * sizeof(double));
    value += a.values.size();
    s.corners = a.per_corner() ? corner : nullptr;
    if (a.per_corner()) std::memcpy(corner, a.corners.data(), a.corners.size() * sizeof(int32_t));
    corner += a.corners.size();
    s.name = name;
    std::memcpy(name, a.name.c_str(), a.name.size() + 1);
    name += a.name.size() + 1;
  }
  *out = structs;
  *count = static_cast<int32_t>(attributes.size());
  return Status::Ok();
}

Status export_attribute_stats(const std::vector<AttributeStats>& stats, const std::vector<AttributeKind>& kinds,
                              gab_attribute_stats** out) {
  *out = nullptr;
  if (stats.empty()) return Status::Ok();
  if (stats.size() != kinds.size()) {  // a bug: guarded() reports it as GAB_E_INTERNAL
    throw std::logic_error("the encoder reported " + std::to_string(stats.size()) + " attributes of " +
                           std::to_string(kinds.size()));
  }
  size_t labels = 0;
  for (const AttributeStats& a : stats) labels += a.label.size() + 1;
  const size_t labels_at = stats.size() * sizeof(gab_attribute_stats);
  unsigned char* block = static_cast<unsigned char*>(std::malloc(labels_at + labels));
  if (block == nullptr) return Status::Error(StatusCode::kOutOfMemory, "cannot allocate the attributes' report");
  gab_attribute_stats* structs = reinterpret_cast<gab_attribute_stats*>(block);
  char* label = reinterpret_cast<char*>(block + labels_at);
  for (size_t i = 0; i < stats.size(); ++i) {
    const AttributeStats& a = stats[i];
    gab_attribute_stats& s = structs[i];
    std::memset(&s, 0, sizeof s);
    s.label = label;
    std::memcpy(label, a.label.c_str(), a.label.size() + 1);
    label += a.label.size() + 1;
    s.kind = static_cast<int32_t>(kinds[i]);
    s.bits = a.bits;
    s.per_corner = a.per_corner ? 1 : 0;
    s.from_surface = a.from_surface ? 1 : 0;
    s.elements = a.elements;
    s.bytes = a.bytes;
    s.max_error = a.max_error;
  }
  *out = structs;
  return Status::Ok();
}

std::string describe_attributes(const std::vector<MeshAttribute>& attributes) {
  std::string text;
  for (const MeshAttribute& a : attributes) {
    if (!text.empty()) text += ", ";
    text += std::to_string(a.num_elements()) + " " + attribute_label(a) +
            (a.per_corner() ? " (per corner)" : " (per vertex)");
  }
  return text;
}

Status clear_attribute_outputs(gab_attribute** attributes, int32_t* count) {
  if (attributes != nullptr) *attributes = nullptr;
  if (count != nullptr) *count = 0;
  GAB_RETURN_IF_ERROR(require(attributes != nullptr, "attributes is NULL"));
  return require(count != nullptr, "num_attributes is NULL");
}

}  // namespace capi
}  // namespace gab
