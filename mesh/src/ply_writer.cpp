// PLY writer: vertex x y z (double or float) and the attributes as vertex
// properties in their own types, face lists of uchar count and int
// indices, in ASCII or either binary byte order. PLY holds one value per
// vertex, so per-corner attributes are split at their seams first.
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "attribute_text.h"
#include "gab/mesh/attribute_seams.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/ply_io.h"
#include "ply_attributes.h"
#include "text_scanner.h"

namespace gab {

namespace {

// Stores the low `n` bytes of `bits` at *at in the file's byte order and
// moves *at past them (into a string sized beforehand: an append per value
// took most of a binary file's writing time).
inline void put(char** at, uint64_t bits, int n, bool big_endian) {
  for (int i = 0; i < n; ++i) (*at)[big_endian ? n - 1 - i : i] = static_cast<char>((bits >> (8 * i)) & 0xff);
  *at += n;
}

// x as a float; beyond float's range +-infinity (a plain cast would be
// undefined behaviour). write_ply refuses such meshes.
float to_float(double x) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (x > kMax) return std::numeric_limits<float>::infinity();
  if (x < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(x);
}

int type_bytes(ValueType type) {
  switch (type) {
    case ValueType::kInt8:
    case ValueType::kUint8:
      return 1;
    case ValueType::kInt16:
    case ValueType::kUint16:
      return 2;
    case ValueType::kInt32:
    case ValueType::kUint32:
    case ValueType::kFloat32:
      return 4;
    case ValueType::kFloat64:
      break;
  }
  return 8;
}

// `value` in `type`'s binary form, in the low bytes.
uint64_t value_bits(double value, ValueType type) {
  if (type == ValueType::kFloat32) {
    const float f = to_float(value);
    uint32_t u;
    std::memcpy(&u, &f, sizeof(u));
    return u;
  }
  if (type == ValueType::kFloat64) {
    uint64_t u;
    std::memcpy(&u, &value, sizeof(u));
    return u;
  }
  // Two's complement: the low bytes of the int64 are the narrow type's.
  return static_cast<uint64_t>(static_cast<int64_t>(value));
}

// One attribute as vertex properties: its names (one per component), or one
// list property of its components (a generic of 2 to 4).
struct Column {
  const MeshAttribute* attribute = nullptr;
  size_t index = 0;  // in the mesh's attributes
  std::vector<std::string> names;
  bool list = false;
};

// The property names an attribute of a common kind may be written under,
// in the order the reader looks for them (ply_attributes.cpp).
std::vector<std::vector<std::string>> kind_names(const MeshAttribute& a) {
  switch (a.kind) {
    case AttributeKind::kNormal:
      return {{"nx", "ny", "nz"}};
    case AttributeKind::kTexCoord:
      if (a.components == 3) return {{"texture_u", "texture_v", "texture_w"}};
      return {{"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
    case AttributeKind::kColor:
      if (a.components == 4) {
        return {{"red", "green", "blue", "alpha"}, {"r", "g", "b", "a"},
                {"diffuse_red", "diffuse_green", "diffuse_blue", "diffuse_alpha"}};
      }
      return {{"red", "green", "blue"}, {"r", "g", "b"}, {"diffuse_red", "diffuse_green", "diffuse_blue"}};
    case AttributeKind::kGeneric:
      break;
  }
  return {{a.name}};
}

// The attributes written: the first of each common kind under the first
// of its spellings that no generic has (the reader then finds the same),
// then every generic under its name (once); the others noted.
std::vector<Column> choose(const Mesh& mesh, MeshWriteNotes* notes) {
  std::set<std::string> taken = {"x", "y", "z"};
  std::vector<bool> written(mesh.attributes.size(), false);
  for (size_t a = 0; a < mesh.attributes.size(); ++a) {
    const MeshAttribute& attribute = mesh.attributes[a];
    if (attribute.kind != AttributeKind::kGeneric) continue;
    written[a] = taken.insert(attribute.name).second;
    if (!written[a]) mesh_detail::note_not_written(attribute, "a property of that name is written already", notes);
  }
  std::vector<std::vector<std::string>> names(mesh.attributes.size());
  for (AttributeKind kind : {AttributeKind::kNormal, AttributeKind::kTexCoord, AttributeKind::kColor}) {
    const int first = mesh_detail::first_attribute(mesh, kind);
    for (size_t a = 0; a < mesh.attributes.size(); ++a) {
      const MeshAttribute& attribute = mesh.attributes[a];
      if (attribute.kind != kind) continue;
      if (static_cast<int>(a) != first) {
        mesh_detail::note_not_written(attribute, "PLY holds one of each kind", notes);
        continue;
      }
      for (const std::vector<std::string>& spelling : kind_names(attribute)) {
        bool free = true;
        for (const std::string& n : spelling) free = free && taken.count(n) == 0;
        if (!free) continue;
        names[a] = spelling;
        taken.insert(spelling.begin(), spelling.end());
        written[a] = true;
        break;
      }
      if (!written[a]) mesh_detail::note_not_written(attribute, "generic attributes have its property names", notes);
    }
  }
  // Columns in the order the reader gives attributes back: the kinds
  // (normals, texture coordinates, colours), then the generics.
  std::vector<size_t> order;
  for (AttributeKind kind : {AttributeKind::kNormal, AttributeKind::kTexCoord, AttributeKind::kColor}) {
    const int a = mesh_detail::first_attribute(mesh, kind);
    if (a >= 0 && written[a]) order.push_back(static_cast<size_t>(a));
  }
  for (size_t a = 0; a < mesh.attributes.size(); ++a) {
    if (written[a] && mesh.attributes[a].kind == AttributeKind::kGeneric) order.push_back(a);
  }
  std::vector<Column> columns;
  for (size_t a : order) {
    const MeshAttribute& attribute = mesh.attributes[a];
    Column c;
    c.attribute = &attribute;
    c.index = a;
    const bool generic = attribute.kind == AttributeKind::kGeneric;
    c.names = generic ? std::vector<std::string>{attribute.name} : names[a];
    c.list = generic && attribute.components > 1;
    columns.push_back(std::move(c));
  }
  return columns;
}

}  // namespace

std::string format_ply(const Mesh& input, const PlyWriteOptions& options, MeshWriteNotes* notes) {
  MeshWriteNotes seen;
  std::vector<Column> columns = choose(input, &seen);
  std::vector<bool> selected(input.attributes.size(), false);
  bool any_per_corner = false;
  for (const Column& c : columns) {
    if (c.attribute->per_corner()) selected[c.index] = any_per_corner = true;
  }
  Mesh split;
  const Mesh* m = &input;
  if (any_per_corner) {
    split = split_attribute_seams(input, selected, &seen.split_vertices);
    m = &split;
    for (Column& c : columns) c.attribute = &split.attributes[c.index];
  }
  const Mesh& mesh = *m;

  const bool ascii = options.encoding == PlyEncoding::kAscii;
  const bool big = options.encoding == PlyEncoding::kBinaryBigEndian;
  const char* format = ascii ? "ascii" : big ? "binary_big_endian" : "binary_little_endian";
  const char* real = options.float32 ? "float" : "double";
  std::string out = std::string("ply\nformat ") + format + " 1.0\ncomment written by gab\nelement vertex " +
                    std::to_string(mesh.num_vertices()) + "\nproperty " + real + " x\nproperty " + real +
                    " y\nproperty " + real + " z\n";
  size_t vertex_bytes = 3 * (options.float32 ? 4 : 8);
  size_t values_per_vertex = 3;
  for (const Column& c : columns) {
    const char* type = mesh_detail::ply_type_name(c.attribute->type);
    const size_t k = static_cast<size_t>(c.attribute->components);
    if (c.list) {
      out += std::string("property list uchar ") + type + " " + c.names[0] + "\n";
      vertex_bytes += 1;
    } else {
      for (const std::string& n : c.names) out += std::string("property ") + type + " " + n + "\n";
    }
    vertex_bytes += k * static_cast<size_t>(type_bytes(c.attribute->type));
    values_per_vertex += k + (c.list ? 1 : 0);
  }
  out += "element face " + std::to_string(mesh.num_triangles()) + "\nproperty list uchar int vertex_indices\nend_header\n";

  const size_t nv = static_cast<size_t>(mesh.num_vertices());
  if (!ascii) {
    const size_t header = out.size();
    out.resize(header + nv * vertex_bytes + mesh.triangles.size() / 3 * 13);
    char* at = &out[header];
    const ValueType position_type = options.float32 ? ValueType::kFloat32 : ValueType::kFloat64;
    for (size_t v = 0; v < nv; ++v) {
      for (size_t c = 0; c < 3; ++c) put(&at, value_bits(mesh.positions[3 * v + c], position_type), options.float32 ? 4 : 8, big);
      for (const Column& col : columns) {
        const MeshAttribute& a = *col.attribute;
        const size_t k = static_cast<size_t>(a.components);
        const int bytes = type_bytes(a.type);
        if (col.list) put(&at, k, 1, big);
        for (size_t c = 0; c < k; ++c) put(&at, value_bits(a.values[k * v + c], a.type), bytes, big);
      }
    }
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
      put(&at, 3, 1, big);
      for (int c = 0; c < 3; ++c) put(&at, static_cast<uint32_t>(mesh.triangles[t + c]), 4, big);
    }
    if (notes != nullptr) *notes = std::move(seen);
    return out;
  }
  out.reserve(out.size() + nv * values_per_vertex * (mesh_detail::kMaxRealChars + 1) +
              mesh.triangles.size() / 3 * (2 + 3 * (mesh_detail::kMaxIndexChars + 1)));
  for (size_t v = 0; v < nv; ++v) {
    for (size_t c = 0; c < 3; ++c) {
      const double x = mesh.positions[3 * v + c];
      if (c > 0) out += ' ';
      mesh_detail::append_real(&out, options.float32 ? static_cast<double>(to_float(x)) : x);
    }
    for (const Column& col : columns) {
      const MeshAttribute& a = *col.attribute;
      const size_t k = static_cast<size_t>(a.components);
      if (col.list) {
        out += ' ';
        mesh_detail::append_int(&out, static_cast<int64_t>(k));
      }
      for (size_t c = 0; c < k; ++c) {
        out += ' ';
        mesh_detail::append_value(&out, a.values[k * v + c], a.type);
      }
    }
    out += '\n';
  }
  for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
    out += "3";
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      mesh_detail::append_int(&out, mesh.triangles[t + c]);
    }
    out += '\n';
  }
  if (notes != nullptr) *notes = std::move(seen);
  return out;
}

Status write_ply(const std::string& path, const Mesh& mesh, const PlyWriteOptions& options, MeshWriteNotes* notes) {
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, path));
  if (options.float32) {
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      if (std::isinf(to_float(mesh.positions[i]))) {
        return Status::Error(StatusCode::kInvalidArgument,
                             path + ": vertex " + std::to_string(i / 3) + ": coordinate does not fit a float");
      }
    }
  }
  for (const MeshAttribute& a : mesh.attributes) {
    if (a.type != ValueType::kFloat32) continue;
    for (size_t i = 0; i < a.values.size(); ++i) {
      if (std::isinf(to_float(a.values[i]))) {
        return Status::Error(StatusCode::kInvalidArgument, path + ": " + attribute_label(a) + ": element " +
                                                               std::to_string(i / a.components) +
                                                               ": value does not fit a float");
      }
    }
  }
  MeshWriteNotes seen;
  GAB_RETURN_IF_ERROR(write_output_file(path, format_ply(mesh, options, &seen)));
  if (notes != nullptr) *notes = std::move(seen);
  return Status::Ok();
}

}  // namespace gab
