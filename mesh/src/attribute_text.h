// Internal to the mesh layer: attribute values as the text formats (OBJ,
// OFF, ASCII PLY) read and write them, and what the writers share.
#pragma once

#include <string>
#include <vector>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_write_notes.h"

namespace gab {
namespace mesh_detail {

// Appends `value` as text that reads back to exactly it in `type`: integer
// types as integers, float32 with 9 significant digits (nearer the float
// than half its spacing, so a reader that rounds the decimal to double and
// then to float gets it back), float64 in the shortest form that reads back.
void append_value(std::string* out, double value, ValueType type);

// x rounded to the nearest float, in *out; false when x is not finite or
// lies beyond float's range (a float property cannot hold it).
bool round_to_float(double x, double* out);

// Decimals read for an attribute of a format with no binary types (OBJ,
// OFF): each rounded to the nearest float and kFloat32 returned, as a
// binary float property would hold them; when one lies beyond float's
// range, left as read and kFloat64 returned. O(values).
ValueType settle_decimal_values(std::vector<double>* values);

// Whether `name` can name a generic attribute (validate_attribute's rule).
bool generic_name_ok(const std::string& name);

// The index of the first attribute of `kind` in `mesh`, or -1.
int first_attribute(const Mesh& mesh, AttributeKind kind);

// In messages: "normals", "texture coordinates", "vertex colours",
// "generic attribute 'NAME'".
std::string attribute_words(const MeshAttribute& attribute);

// Notes `attribute` as not written: key attribute_label, label
// "<attribute_words> (<why>)", its elements counted.
void note_not_written(const MeshAttribute& attribute, const std::string& why, MeshWriteNotes* notes);

}  // namespace mesh_detail
}  // namespace gab
