#include "attribute_text.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "text_scanner.h"

namespace gab {
namespace mesh_detail {

void append_value(std::string* out, double value, ValueType type) {
  if (is_integer_type(type)) {
    append_int(out, static_cast<int64_t>(value));
  } else if (type == ValueType::kFloat32) {
    char buf[32];
    const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::general, 9);
    out->append(buf, r.ptr);
  } else {
    append_real(out, value);
  }
}

bool round_to_float(double x, double* out) {
  if (!std::isfinite(x)) return false;
  const float f = std::fabs(x) > static_cast<double>(std::numeric_limits<float>::max())
                      ? std::numeric_limits<float>::infinity()
                      : static_cast<float>(x);
  // Past the largest float, a value rounds to it or to infinity.
  if (std::isinf(f)) return false;
  *out = static_cast<double>(f);
  return true;
}

ValueType settle_decimal_values(std::vector<double>* values) {
  for (double x : *values) {
    double f;
    if (!round_to_float(x, &f)) return ValueType::kFloat64;
  }
  for (double& x : *values) round_to_float(x, &x);
  return ValueType::kFloat32;
}

bool generic_name_ok(const std::string& name) {
  MeshAttribute probe;  // no elements: only the name can be wrong
  probe.kind = AttributeKind::kGeneric;
  probe.name = name;
  return validate_attribute(probe, 0, 0, "").ok();
}

int first_attribute(const Mesh& mesh, AttributeKind kind) {
  for (size_t a = 0; a < mesh.attributes.size(); ++a) {
    if (mesh.attributes[a].kind == kind) return static_cast<int>(a);
  }
  return -1;
}

std::string attribute_words(const MeshAttribute& attribute) {
  switch (attribute.kind) {
    case AttributeKind::kNormal:
      return "normals";
    case AttributeKind::kTexCoord:
      return "texture coordinates";
    case AttributeKind::kColor:
      return "vertex colours";
    case AttributeKind::kGeneric:
      break;
  }
  return "generic attribute '" + attribute.name + "'";
}

void note_not_written(const MeshAttribute& attribute, const std::string& why, MeshWriteNotes* notes) {
  if (notes == nullptr) return;
  notes->drop(attribute_label(attribute), attribute_words(attribute) + " (" + why + ")", attribute.num_elements());
}

}  // namespace mesh_detail
}  // namespace gab
