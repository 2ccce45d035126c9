#include "gab/mesh/mesh_attribute.h"

#include <cmath>
#include <limits>

namespace gab {

std::string attribute_label(const MeshAttribute& attribute) {
  switch (attribute.kind) {
    case AttributeKind::kNormal:
      return "normals";
    case AttributeKind::kTexCoord:
      return "texture_coordinates";
    case AttributeKind::kColor:
      return "vertex_colors";
    case AttributeKind::kGeneric:
      break;
  }
  return "generic:" + attribute.name;
}

bool is_integer_type(ValueType type) { return type != ValueType::kFloat32 && type != ValueType::kFloat64; }

void value_type_range(ValueType type, double* lo, double* hi) {
  switch (type) {
    case ValueType::kInt8:
      *lo = -128, *hi = 127;
      return;
    case ValueType::kUint8:
      *lo = 0, *hi = 255;
      return;
    case ValueType::kInt16:
      *lo = -32768, *hi = 32767;
      return;
    case ValueType::kUint16:
      *lo = 0, *hi = 65535;
      return;
    case ValueType::kInt32:
      *lo = -2147483648.0, *hi = 2147483647.0;
      return;
    case ValueType::kUint32:
      *lo = 0, *hi = 4294967295.0;
      return;
    case ValueType::kFloat32:
    case ValueType::kFloat64:
      break;
  }
  *hi = std::numeric_limits<double>::max();
  *lo = -*hi;
}

bool valid_attribute_components(AttributeKind kind, int32_t components) {
  switch (kind) {
    case AttributeKind::kNormal:
      return components == 3;
    case AttributeKind::kTexCoord:
      return components == 2 || components == 3;
    case AttributeKind::kColor:
      return components == 3 || components == 4;
    case AttributeKind::kGeneric:
      return components >= 1 && components <= 4;
  }
  return false;
}

namespace {

bool valid_generic_name(const std::string& name) {
  if (name.empty() || name.size() > 255) return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

Status validate_attribute(const MeshAttribute& a, int64_t num_vertices, int64_t num_triangles,
                          const std::string& name) {
  const std::string where = name + ": " + attribute_label(a) + ": ";
  auto invalid = [&where](const std::string& what) { return Status::Error(StatusCode::kInvalidArgument, where + what); };
  if (static_cast<uint8_t>(a.kind) > static_cast<uint8_t>(AttributeKind::kGeneric)) return invalid("unknown kind");
  if (static_cast<uint8_t>(a.type) > static_cast<uint8_t>(ValueType::kFloat64)) return invalid("unknown value type");
  if (!valid_attribute_components(a.kind, a.components)) return invalid(std::to_string(a.components) + " components, not what the kind holds");
  if (a.kind == AttributeKind::kGeneric ? !valid_generic_name(a.name) : !a.name.empty()) {
    return invalid(a.kind == AttributeKind::kGeneric
                       ? "a generic attribute's name is 1 to 255 letters, digits, '_', '-' or '.'"
                       : "only a generic attribute has a name");
  }
  if (a.values.size() % static_cast<size_t>(a.components) != 0) {
    return invalid("values are not a multiple of its " + std::to_string(a.components) + " components");
  }
  const int64_t elements = a.num_elements();
  if (elements > INT32_MAX) return Status::Error(StatusCode::kOverflow, where + "more than 2^31-1 elements");
  double lo = 0, hi = 0;
  value_type_range(a.type, &lo, &hi);
  const bool integer = is_integer_type(a.type);
  for (size_t i = 0; i < a.values.size(); ++i) {
    const double x = a.values[i];
    if (!std::isfinite(x)) return invalid("element " + std::to_string(i / a.components) + ": value is not finite");
    if (integer && (x < lo || x > hi || x != std::floor(x))) {
      return invalid("element " + std::to_string(i / a.components) + ": " + std::to_string(x) +
                     " is not a value of its integer type");
    }
  }
  if (!a.per_corner()) {
    if (elements != num_vertices) {
      return invalid(std::to_string(elements) + " elements for " + std::to_string(num_vertices) + " vertices");
    }
    return Status::Ok();
  }
  if (static_cast<int64_t>(a.corners.size()) != 3 * num_triangles) {
    return invalid(std::to_string(a.corners.size()) + " corner indices for " + std::to_string(num_triangles) +
                   " triangles");
  }
  for (size_t i = 0; i < a.corners.size(); ++i) {
    if (a.corners[i] < 0 || a.corners[i] >= elements) {
      return invalid("triangle " + std::to_string(i / 3) + ": element index " + std::to_string(a.corners[i]) +
                     " out of range [0, " + std::to_string(elements) + ")");
    }
  }
  return Status::Ok();
}

}  // namespace gab
