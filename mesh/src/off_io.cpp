// OFF reader. The format is free-form text (Geomview's OFF(5) manual
// page): a record may span lines, so the parser walks tokens while counting
// lines for its messages. The per-vertex data the header's prefixes announce
// (normals, a colour, texture coordinates) sits on the vertex's line after
// its coordinates, and a colour has 3 or 4 values, so those are read by
// line; a face's colour after its indices is skipped with the line.
#include "gab/mesh/off_io.h"

#include <cmath>

#include "attribute_text.h"
#include "gab/mesh/file_io.h"
#include "text_scanner.h"

namespace gab {

namespace {

using mesh_detail::parse_int;
using mesh_detail::parse_real;
using mesh_detail::printable;
using mesh_detail::TextScanner;

struct OffHeader {
  bool texture = false, colors = false, normals = false, homogeneous = false, ndim = false;
};

// Splits the [ST][C][N][4][n]OFF keyword; false if the token is not one.
bool parse_keyword(std::string_view key, OffHeader* h) {
  size_t i = 0;
  auto take = [&key, &i](std::string_view prefix) {
    if (key.substr(i, prefix.size()) != prefix) return false;
    i += prefix.size();
    return true;
  };
  h->texture = take("ST");
  h->colors = take("C");
  h->normals = take("N");
  h->homogeneous = take("4");
  h->ndim = take("n");
  return key.substr(i) == "OFF";
}

// The per-vertex data the header announces, as read: x y z [nx ny nz]
// [r g b [a]] [s t] on each vertex's line.
struct OffVertexData {
  std::vector<double> normals, colors, texcoords;
  int color_components = 0;                 // 3 or 4, as the first vertex says
  bool colors_integers = true;              // every colour value an integer token in 0..255
  bool colors_above_one = false;            // some colour value above 1
  int64_t not_finite_line[3] = {0, 0, 0};   // normals, colours, texture coordinates: first line with one
};

// The values a vertex line has after its coordinates, for messages: "nx ny nz r g b [a] s t".
std::string layout(const OffHeader& h) {
  std::string out;
  if (h.normals) out += "nx ny nz";
  if (h.colors) out += std::string(out.empty() ? "" : " ") + "r g b [a]";
  if (h.texture) out += std::string(out.empty() ? "" : " ") + "s t";
  return out;
}

// Reads the rest of vertex v's line into `data`.
Status read_vertex_data(const OffHeader& h, std::string_view keyword, int64_t v, TextScanner* tok,
                        std::vector<std::string_view>* words, OffVertexData* data) {
  words->clear();
  std::string_view t;
  while (!tok->at_line_end() && tok->next(&t)) words->push_back(t);
  const size_t fixed = (h.normals ? 3 : 0) + (h.texture ? 2 : 0);
  const size_t n = words->size();
  const bool count_ok = h.colors ? n == fixed + 3 || n == fixed + 4 : n == fixed;
  const std::string vertex = "vertex " + std::to_string(v);
  if (!count_ok) {
    const std::string need = h.colors ? std::to_string(fixed + 3) + " or " + std::to_string(fixed + 4) : std::to_string(fixed);
    return tok->error_here(vertex + ": " + std::to_string(n) + " values after the coordinates, " + printable(keyword) +
                           " needs " + need + " (" + layout(h) + ")");
  }
  const int color_components = h.colors ? static_cast<int>(n - fixed) : 0;
  if (h.colors && data->color_components == 0) data->color_components = color_components;
  if (color_components != data->color_components) {
    return tok->error_here(vertex + ": " + std::to_string(color_components) + " colour values where vertex 0 has " +
                           std::to_string(data->color_components));
  }
  size_t at = 0;
  auto take = [&](size_t count, std::vector<double>* out, int kind, const char* what) -> Status {
    for (size_t i = 0; i < count; ++i, ++at) {
      double x;
      if (!parse_real((*words)[at], &x)) {
        return tok->error_here(vertex + ": bad " + what + " '" + printable((*words)[at]) + "'");
      }
      if (!std::isfinite(x) && data->not_finite_line[kind] == 0) data->not_finite_line[kind] = tok->line();
      if (kind == 1) {
        int64_t i64;
        data->colors_integers = data->colors_integers && parse_int((*words)[at], &i64) && i64 >= 0 && i64 <= 255;
        data->colors_above_one = data->colors_above_one || x > 1;
      }
      out->push_back(x);
    }
    return Status::Ok();
  };
  if (h.normals) GAB_RETURN_IF_ERROR(take(3, &data->normals, 0, "normal value"));
  if (h.colors) GAB_RETURN_IF_ERROR(take(static_cast<size_t>(color_components), &data->colors, 1, "colour value"));
  if (h.texture) GAB_RETURN_IF_ERROR(take(2, &data->texcoords, 2, "texture coordinate"));
  return Status::Ok();
}

// The attributes from `data`, in the order normals, colours, texture
// coordinates; one with a value that is not finite is noted instead.
void add_vertex_data(const OffHeader& h, std::string_view keyword, OffVertexData* data, int64_t nv, Mesh* mesh,
                     MeshReadNotes* notes) {
  struct Part {
    bool present;
    AttributeKind kind;
    std::vector<double>* values;
    int components;
    const char* key;
    const char* words;
  };
  const Part parts[3] = {
      {h.normals, AttributeKind::kNormal, &data->normals, 3, "normals", "normals"},
      {h.colors, AttributeKind::kColor, &data->colors, data->color_components, "vertex_colors", "vertex colours"},
      {h.texture, AttributeKind::kTexCoord, &data->texcoords, 2, "texture_coordinates", "texture coordinates"},
  };
  for (int i = 0; i < 3; ++i) {
    const Part& p = parts[i];
    if (!p.present) continue;
    if (data->not_finite_line[i] != 0) {
      notes->drop(p.key, std::string(p.words) + " (" + printable(keyword) + "; line " +
                             std::to_string(data->not_finite_line[i]) + " has a value that is not finite)",
                  nv);
      continue;
    }
    MeshAttribute a;
    a.kind = p.kind;
    a.components = p.components;
    a.values = std::move(*p.values);
    // Colours are integers 0..255 when every value is one and some is above
    // 1 (Geomview reads a colour with no value above 1 as fractions).
    if (p.kind == AttributeKind::kColor && data->colors_integers && data->colors_above_one) {
      a.type = ValueType::kUint8;
    } else {
      a.type = mesh_detail::settle_decimal_values(&a.values);
    }
    mesh->attributes.push_back(std::move(a));
  }
}

}  // namespace

Status parse_off(std::string_view text, const std::string& name, Mesh* mesh, MeshReadNotes* notes) {
  TextScanner tok(text, name, '#');
  std::string_view t;
  if (!tok.next(&t)) return tok.error_here("empty file, expected an OFF header");
  OffHeader h;
  if (!parse_keyword(t, &h)) return tok.error("not an OFF file (header '" + printable(t) + "')");
  const std::string_view t0 = t;
  if (h.ndim) {
    int64_t dim = 0;
    if (!tok.next(&t)) return tok.error_here("truncated header: expected the nOFF dimension");
    if (!parse_int(t, &dim) || dim != 3) {
      return tok.error("nOFF dimension '" + printable(t) + "' is not supported (only 3)");
    }
  }
  int64_t counts[3];
  for (int i = 0; i < 3; ++i) {
    if (!tok.next(&t)) return tok.error_here("truncated header: expected vertex, face and edge counts");
    if (i == 0 && t == "BINARY") return tok.error("binary OFF is not supported");
    if (!parse_int(t, &counts[i]) || counts[i] < 0) {
      return tok.error("bad count '" + printable(t) + "' in header");
    }
  }
  const int64_t nv = counts[0], nf = counts[1];
  // Never trust a count for allocation: a vertex takes at least 6 bytes
  // ("0 0 0\n") and a face 8 ("3 0 1 2\n"). (A file cut short passes this
  // coarse bound and is reported as truncated where it ends.)
  const int64_t size = static_cast<int64_t>(text.size());
  if (nv > size / 6 + 1 || nf > size / 8 + 1) {
    return tok.error("header claims " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                     " faces, more than the file's " + std::to_string(size) + " bytes can hold");
  }
  if (nv == 0) return tok.error("mesh has no vertices");
  if (nf == 0) return tok.error("mesh has no faces");
  if (nv > INT32_MAX) return tok.error("more than 2^31-1 vertices");

  MeshReadNotes seen;
  OffVertexData data;
  if (h.normals) data.normals.reserve(static_cast<size_t>(nv) * 3);
  if (h.colors) data.colors.reserve(static_cast<size_t>(nv) * 3);
  if (h.texture) data.texcoords.reserve(static_cast<size_t>(nv) * 2);
  std::vector<std::string_view> words;
  Mesh m;
  m.positions.resize(static_cast<size_t>(nv) * 3);
  const int dims = h.homogeneous ? 4 : 3;
  const bool vertex_extras = h.texture || h.colors || h.normals;
  for (int64_t v = 0; v < nv; ++v) {
    double x[4];
    for (int c = 0; c < dims; ++c) {
      if (!tok.next(&t)) {
        return tok.error_here("truncated: file ends in vertex " + std::to_string(v) + " of " + std::to_string(nv));
      }
      if (!parse_real(t, &x[c])) {
        return tok.error("vertex " + std::to_string(v) + ": bad coordinate '" + printable(t) + "'");
      }
      if (!std::isfinite(x[c])) return tok.error("vertex " + std::to_string(v) + ": coordinate is not finite");
    }
    if (h.homogeneous) {
      if (x[3] == 0.0) return tok.error("vertex " + std::to_string(v) + ": homogeneous coordinate w is 0");
      for (int c = 0; c < 3; ++c) {
        x[c] /= x[3];
        if (!std::isfinite(x[c])) return tok.error("vertex " + std::to_string(v) + ": coordinate is not finite");
      }
    }
    for (int c = 0; c < 3; ++c) m.positions[static_cast<size_t>(v) * 3 + c] = x[c];
    if (vertex_extras) {
      GAB_RETURN_IF_ERROR(read_vertex_data(h, t0, v, &tok, &words, &data));
      tok.skip_line();
    }
  }

  m.triangles.reserve(static_cast<size_t>(nf) * 3);
  int64_t polygons = 0, face_colors = 0;
  for (int64_t f = 0; f < nf; ++f) {
    int64_t k;
    if (!tok.next(&t)) {
      return tok.error_here("truncated: file ends in face " + std::to_string(f) + " of " + std::to_string(nf));
    }
    if (!parse_int(t, &k) || k < 0) {
      return tok.error("face " + std::to_string(f) + ": bad vertex count '" + printable(t) + "'");
    }
    if (k < 3) return tok.error("face " + std::to_string(f) + " has " + std::to_string(k) + " vertices (need 3 or more)");
    // k indices take at least 2k - 1 bytes.
    if (k > static_cast<int64_t>(tok.remaining() / 2) + 1) {
      return tok.error("face " + std::to_string(f) + ": vertex count " + std::to_string(k) +
                       " is more than the rest of the file can hold");
    }
    if (k > 3) ++polygons;
    if (static_cast<int64_t>(m.triangles.size() / 3) + (k - 2) > INT32_MAX) {
      return tok.error("face " + std::to_string(f) + ": more than 2^31-1 triangles");
    }
    int32_t first = 0, prev = 0;
    for (int64_t c = 0; c < k; ++c) {
      int64_t idx;
      if (!tok.next(&t)) {
        return tok.error_here("truncated: file ends in face " + std::to_string(f) + " of " + std::to_string(nf));
      }
      if (!parse_int(t, &idx)) {
        return tok.error("face " + std::to_string(f) + ": bad vertex index '" + printable(t) + "'");
      }
      if (idx < 0 || idx >= nv) {
        return tok.error("face " + std::to_string(f) + ": vertex index " + std::to_string(idx) +
                         " out of range [0, " + std::to_string(nv) + ")");
      }
      // Fan triangulation (v0, v_{c-1}, v_c).
      if (c == 0) first = static_cast<int32_t>(idx);
      if (c >= 2) {
        m.triangles.push_back(first);
        m.triangles.push_back(prev);
        m.triangles.push_back(static_cast<int32_t>(idx));
      }
      prev = static_cast<int32_t>(idx);
    }
    if (!tok.at_line_end()) ++face_colors;  // OFF(5): a colour may follow the indices
    tok.skip_line();
  }
  add_vertex_data(h, t0, &data, nv, &m, &seen);
  seen.drop("polygons", "polygons of 4 or more corners (fan-triangulated)", polygons);
  seen.drop("face_colors", "face colours (after the indices)", face_colors);
  *mesh = std::move(m);
  if (notes != nullptr) *notes = std::move(seen);
  return Status::Ok();
}

Status read_off(const std::string& path, Mesh* mesh, MeshReadNotes* notes) {
  std::string bytes;
  GAB_RETURN_IF_ERROR(read_file(path, &bytes));
  return parse_off(bytes, path, mesh, notes);
}

}  // namespace gab
