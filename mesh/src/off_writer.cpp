// OFF writer: the header's prefixes name the per-vertex data written
// ([ST][C][N]OFF), each vertex's line holds x y z [nx ny nz] [r g b [a]]
// [s t], faces are "3 i j k". OFF holds one value per vertex, so per-corner
// attributes are split at their seams first.
#include <cstring>

#include "attribute_text.h"
#include "gab/mesh/attribute_seams.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/off_io.h"
#include "text_scanner.h"

namespace gab {

namespace {

using mesh_detail::append_int;
using mesh_detail::append_real;
using mesh_detail::append_value;

// The attribute written for each kind (-1: none), the others noted.
struct OffAttributes {
  int normal = -1, color = -1, texcoord = -1;
};

OffAttributes choose(const Mesh& mesh, MeshWriteNotes* notes) {
  OffAttributes w;
  w.normal = mesh_detail::first_attribute(mesh, AttributeKind::kNormal);
  w.color = mesh_detail::first_attribute(mesh, AttributeKind::kColor);
  w.texcoord = mesh_detail::first_attribute(mesh, AttributeKind::kTexCoord);
  for (size_t a = 0; a < mesh.attributes.size(); ++a) {
    const MeshAttribute& attribute = mesh.attributes[a];
    const int i = static_cast<int>(a);
    if (attribute.kind == AttributeKind::kGeneric) {
      mesh_detail::note_not_written(attribute, "OFF has no place for it", notes);
    } else if (i != w.normal && i != w.texcoord && i != w.color) {
      mesh_detail::note_not_written(attribute, "OFF holds one of each kind", notes);
    }
  }
  if (w.texcoord >= 0 && mesh.attributes[w.texcoord].components == 3) {
    const MeshAttribute& t = mesh.attributes[w.texcoord];
    int64_t nonzero = 0;
    for (size_t i = 2; i < t.values.size(); i += 3) nonzero += t.values[i] != 0.0;
    if (nonzero > 0) notes->drop("texture_coordinates.w", "texture coordinate w values (OFF holds s t)", t.num_elements());
  }
  return w;
}

// Colours as OFF holds them: uchar values as integers 0..255, anything
// else as fractions with a decimal point (an integer type over its largest
// value). A reader takes a file whose colour values are all integers, some
// above 1, as 0..255, and any other as fractions (Geomview's reading), so
// uchar colours none of which is above 1 are written as fractions too.
struct ColorForm {
  bool integers = false;
  double scale = 1.0;  // divides the stored values
  ValueType text = ValueType::kFloat32;
};

ColorForm color_form(const MeshAttribute& c) {
  ColorForm form;
  form.text = c.type == ValueType::kFloat64 ? ValueType::kFloat64 : ValueType::kFloat32;
  if (!is_integer_type(c.type)) return form;
  bool above_one = false;
  for (double x : c.values) above_one = above_one || x > 1;
  if (c.type == ValueType::kUint8 && above_one) {
    form.integers = true;
    return form;
  }
  double lo;
  value_type_range(c.type, &lo, &form.scale);
  return form;
}

void append_color_value(std::string* out, double x, const ColorForm& form) {
  if (form.integers) {
    append_int(out, static_cast<int64_t>(x));
    return;
  }
  const size_t start = out->size();
  append_value(out, x / form.scale, form.text);
  // "1" would read as an integer: "1.0" keeps the fraction a fraction.
  if (out->find_first_of(".eE", start) == std::string::npos) *out += ".0";
}

}  // namespace

std::string format_off(const Mesh& input, MeshWriteNotes* notes) {
  MeshWriteNotes seen;
  const OffAttributes w = choose(input, &seen);
  std::vector<bool> selected(input.attributes.size(), false);
  bool any_per_corner = false;
  for (int a : {w.normal, w.color, w.texcoord}) {
    if (a >= 0 && input.attributes[a].per_corner()) selected[a] = any_per_corner = true;
  }
  Mesh split;
  const Mesh* m = &input;
  if (any_per_corner) {
    split = split_attribute_seams(input, selected, &seen.split_vertices);
    m = &split;
  }
  const Mesh& mesh = *m;
  const MeshAttribute* normal = w.normal >= 0 ? &mesh.attributes[w.normal] : nullptr;
  const MeshAttribute* color = w.color >= 0 ? &mesh.attributes[w.color] : nullptr;
  const MeshAttribute* texcoord = w.texcoord >= 0 ? &mesh.attributes[w.texcoord] : nullptr;
  const ColorForm form = color != nullptr ? color_form(*color) : ColorForm();

  std::string out = std::string(texcoord != nullptr ? "ST" : "") + (color != nullptr ? "C" : "") +
                    (normal != nullptr ? "N" : "") + "OFF\n";
  const size_t per_vertex = 3 + (normal != nullptr ? 3 : 0) + (color != nullptr ? 4 : 0) + (texcoord != nullptr ? 2 : 0);
  out.reserve(64 + static_cast<size_t>(mesh.num_vertices()) * per_vertex * (mesh_detail::kMaxRealChars + 1) +
              static_cast<size_t>(mesh.num_triangles()) * (2 + 3 * (mesh_detail::kMaxIndexChars + 1)));
  append_int(&out, mesh.num_vertices());
  out += ' ';
  append_int(&out, mesh.num_triangles());
  out += " 0\n";
  for (size_t v = 0; v < static_cast<size_t>(mesh.num_vertices()); ++v) {
    for (size_t c = 0; c < 3; ++c) {
      if (c > 0) out += ' ';
      append_real(&out, mesh.positions[3 * v + c]);
    }
    if (normal != nullptr) {
      for (size_t c = 0; c < 3; ++c) {
        out += ' ';
        append_value(&out, normal->values[3 * v + c], normal->type);
      }
    }
    if (color != nullptr) {
      const size_t k = static_cast<size_t>(color->components);
      for (size_t c = 0; c < k; ++c) {
        out += ' ';
        append_color_value(&out, color->values[k * v + c], form);
      }
    }
    if (texcoord != nullptr) {
      const size_t k = static_cast<size_t>(texcoord->components);
      for (size_t c = 0; c < 2; ++c) {
        out += ' ';
        append_value(&out, texcoord->values[k * v + c], texcoord->type);
      }
    }
    out += '\n';
  }
  for (size_t i = 0; i < mesh.triangles.size(); i += 3) {
    out += "3 ";
    for (int c = 0; c < 3; ++c) {
      append_int(&out, mesh.triangles[i + c]);
      out += c == 2 ? '\n' : ' ';
    }
  }
  if (notes != nullptr) *notes = std::move(seen);
  return out;
}

Status write_off(const std::string& path, const Mesh& mesh, MeshWriteNotes* notes) {
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, path));
  MeshWriteNotes seen;
  GAB_RETURN_IF_ERROR(write_output_file(path, format_off(mesh, &seen)));
  if (notes != nullptr) *notes = std::move(seen);
  return Status::Ok();
}

}  // namespace gab
