// OBJ writer: `v x y z [r g b]`, `vt`, `vn` and `f v/vt/vn` lines. OBJ
// indexes texture coordinates and normals per corner, so those attributes
// are written as they are (per vertex: one record per vertex); colours sit
// on the `v` lines, so per-corner colours are split at their seams first.
#include <cstdio>

#include "attribute_text.h"
#include "gab/mesh/attribute_seams.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/obj_io.h"
#include "text_scanner.h"

namespace gab {

namespace {

using mesh_detail::append_int;
using mesh_detail::append_real;
using mesh_detail::append_value;

// The attribute written for each kind (-1: none), the others noted.
struct ObjAttributes {
  int normal = -1, texcoord = -1, color = -1;
};

ObjAttributes choose(const Mesh& mesh, MeshWriteNotes* notes) {
  ObjAttributes w;
  w.normal = mesh_detail::first_attribute(mesh, AttributeKind::kNormal);
  w.texcoord = mesh_detail::first_attribute(mesh, AttributeKind::kTexCoord);
  w.color = mesh_detail::first_attribute(mesh, AttributeKind::kColor);
  for (size_t a = 0; a < mesh.attributes.size(); ++a) {
    const MeshAttribute& attribute = mesh.attributes[a];
    const int i = static_cast<int>(a);
    if (attribute.kind == AttributeKind::kGeneric) {
      mesh_detail::note_not_written(attribute, "OBJ has no place for it", notes);
    } else if (i != w.normal && i != w.texcoord && i != w.color) {
      mesh_detail::note_not_written(attribute, "OBJ holds one of each kind", notes);
    }
  }
  if (w.color >= 0 && mesh.attributes[w.color].components == 4 && notes != nullptr) {
    notes->drop("vertex_colors.alpha", "colour alpha values (OBJ holds r g b)", mesh.attributes[w.color].num_elements());
  }
  return w;
}

// A colour component as OBJ's fraction: integer types over their largest
// value (255 for uchar), the float types as they are.
double color_fraction(double value, ValueType type) {
  if (!is_integer_type(type)) return value;
  double lo, hi;
  value_type_range(type, &lo, &hi);
  return value / hi;
}

// `key` lines of an attribute's elements: one per vertex, or the per-corner elements.
void append_elements(const MeshAttribute& a, const char* key, std::string* out) {
  const size_t k = static_cast<size_t>(a.components);
  for (size_t i = 0; i < a.values.size(); ++i) {
    if (i % k == 0) *out += key;
    *out += ' ';
    append_value(out, a.values[i], a.type);
    if (i % k == k - 1) *out += '\n';
  }
}

// The 1-based OBJ index of corner `c`'s element of `a` (vertex `v`'s when per vertex).
int64_t element_number(const MeshAttribute& a, size_t c, int32_t v) {
  return static_cast<int64_t>(a.per_corner() ? a.corners[c] : v) + 1;
}

}  // namespace

std::string format_obj(const Mesh& input, MeshWriteNotes* notes) {
  MeshWriteNotes seen;
  const ObjAttributes w = choose(input, &seen);
  Mesh split;
  const Mesh* m = &input;
  if (w.color >= 0 && input.attributes[w.color].per_corner()) {
    std::vector<bool> selected(input.attributes.size(), false);
    selected[w.color] = true;
    split = split_attribute_seams(input, selected, &seen.split_vertices);
    m = &split;
  }
  const Mesh& mesh = *m;
  const MeshAttribute* color = w.color >= 0 ? &mesh.attributes[w.color] : nullptr;
  const MeshAttribute* texcoord = w.texcoord >= 0 ? &mesh.attributes[w.texcoord] : nullptr;
  const MeshAttribute* normal = w.normal >= 0 ? &mesh.attributes[w.normal] : nullptr;

  std::string out = "# written by gab\n";
  // Reserved from the most characters each line can take: a string that
  // grows copies itself (text_scanner.h).
  const size_t reals_per_vertex = 3 + (color != nullptr ? 3 : 0);
  const size_t indices_per_corner = 1 + (texcoord != nullptr ? 1 : 0) + (normal != nullptr ? 1 : 0);
  size_t reserve = static_cast<size_t>(mesh.num_vertices()) * (2 + reals_per_vertex * (mesh_detail::kMaxRealChars + 1)) +
                   static_cast<size_t>(mesh.num_triangles()) * (2 + 3 * indices_per_corner * (mesh_detail::kMaxIndexChars + 1));
  for (const MeshAttribute* a : {texcoord, normal}) {
    if (a != nullptr) reserve += a->values.size() * (mesh_detail::kMaxRealChars + 1) + 4 * a->values.size() / a->components;
  }
  out.reserve(out.size() + reserve);
  for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
    out += 'v';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      append_real(&out, mesh.positions[3 * static_cast<size_t>(v) + c]);
    }
    if (color != nullptr) {
      const size_t k = static_cast<size_t>(color->components);
      for (size_t c = 0; c < 3; ++c) {
        out += ' ';
        const double x = color_fraction(color->values[k * static_cast<size_t>(v) + c], color->type);
        append_value(&out, x, color->type == ValueType::kFloat64 ? ValueType::kFloat64 : ValueType::kFloat32);
      }
    }
    out += '\n';
  }
  if (texcoord != nullptr) append_elements(*texcoord, "vt", &out);
  if (normal != nullptr) append_elements(*normal, "vn", &out);
  for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
    out += 'f';
    for (size_t c = t; c < t + 3; ++c) {
      const int32_t v = mesh.triangles[c];
      out += ' ';
      append_int(&out, static_cast<int64_t>(v) + 1);
      if (texcoord == nullptr && normal == nullptr) continue;
      out += '/';
      if (texcoord != nullptr) append_int(&out, element_number(*texcoord, c, v));
      if (normal != nullptr) {
        out += '/';
        append_int(&out, element_number(*normal, c, v));
      }
    }
    out += '\n';
  }
  if (notes != nullptr) *notes = std::move(seen);
  return out;
}

Status write_obj(const std::string& path, const Mesh& mesh, MeshWriteNotes* notes) {
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, path));
  MeshWriteNotes seen;
  GAB_RETURN_IF_ERROR(write_output_file(path, format_obj(mesh, &seen)));
  if (notes != nullptr) *notes = std::move(seen);
  return Status::Ok();
}

}  // namespace gab
