// MeshAttribute: data a mesh carries beside its positions, per vertex or
// per corner (normals, texture coordinates, colours, any named scalar), as
// the readers find it in OBJ, PLY and OFF files and the codec codes it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gab/status.h"

namespace gab {

// What an attribute describes: the codec predicts and quantizes each kind
// its own way (a normal is a direction, a colour a small integer or a
// fraction, a texture coordinate a point of the texture's plane).
enum class AttributeKind : uint8_t {
  kNormal = 0,    // 3 components, any length (the codec codes the direction)
  kTexCoord = 1,  // 2 components (u v) or 3 (u v w)
  kColor = 2,     // 3 (r g b) or 4 (r g b a): 0..255 when integer-typed, else as the file gives them (0..1)
  kGeneric = 3,   // 1 to 4 components under a name of the file's (a PLY property: "quality", "confidence")
};

// How the source file stored the values: a PLY property's type; OBJ and OFF
// text is kFloat32. Writers write the values back in it; the codec codes
// integer-typed values exactly and the others quantized.
enum class ValueType : uint8_t { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct MeshAttribute {
  AttributeKind kind = AttributeKind::kGeneric;
  ValueType type = ValueType::kFloat32;
  // Generic: the property's name (non-empty, letters, digits, '_', '-', '.').
  // Other kinds: "" (a writer uses its format's own spelling).
  std::string name;
  int32_t components = 1;
  // `components` per element; element e's are values[components * e ...].
  std::vector<double> values;
  // Per corner: 3 per triangle, the element of each corner of the mesh's
  // triangles (OBJ's `f v/vt/vn`: where a vertex has several texture
  // coordinates or normals, a seam). Empty: one element per vertex.
  std::vector<int32_t> corners;

  bool per_corner() const { return !corners.empty(); }
  int64_t num_elements() const { return components > 0 ? static_cast<int64_t>(values.size()) / components : 0; }
};

// "normals", "texture_coordinates", "vertex_colors" or the generic's
// "generic:NAME": the name the CLI, its JSON and the docs use.
std::string attribute_label(const MeshAttribute& attribute);

// Whether `kind` holds `components` values an element (normal 3, texture
// coordinates 2 or 3, colour 3 or 4, generic 1 to 4).
bool valid_attribute_components(AttributeKind kind, int32_t components);

// Whether values of `type` are integers (the codec codes them exactly).
bool is_integer_type(ValueType type);
// The range of an integer `type` (for the float types: -/+ the largest double).
void value_type_range(ValueType type, double* lo, double* hi);

// Checks one attribute of a mesh of `num_vertices` vertices and
// `num_triangles` triangles: components for its kind, values a whole number
// of elements and finite, integer-typed values integers in their type's
// range, per vertex one element per vertex, per corner 3 * num_triangles
// indices in [0, elements), a generic's name. Messages start with `name`.
// O(values + corners).
Status validate_attribute(const MeshAttribute& attribute, int64_t num_vertices, int64_t num_triangles,
                          const std::string& name);

}  // namespace gab
