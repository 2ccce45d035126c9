// OFF reader and writer. The format is free-form text (Geomview's OFF(5)
// manual page): a record may span lines, so the parser walks tokens while
// counting lines for its messages; optional per-vertex and per-face extras
// sit at the end of a record's line and are skipped with the line.
#include "gab/mesh/off_io.h"

#include <cmath>

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

// The vertex extras the header announces, as dropped data: each vertex
// carries one of each.
void note_vertex_extras(const OffHeader& h, std::string_view keyword, int64_t nv, MeshReadNotes* notes) {
  const std::string form = "(" + std::string(keyword) + ")";
  if (h.normals) notes->drop("normals", "normals " + form, nv);
  if (h.texture) notes->drop("texture_coordinates", "texture coordinates " + form, nv);
  if (h.colors) notes->drop("vertex_colors", "vertex colours " + form, nv);
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
  note_vertex_extras(h, printable(t0), nv, &seen);
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
    if (vertex_extras) tok.skip_line();
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

std::string format_off(const Mesh& mesh) {
  using mesh_detail::append_int;
  using mesh_detail::append_real;
  std::string out = "OFF\n";
  out.reserve(64 + mesh.positions.size() * (mesh_detail::kMaxRealChars + 1) +
              static_cast<size_t>(mesh.num_triangles()) * (2 + 3 * (mesh_detail::kMaxIndexChars + 1)));
  append_int(&out, mesh.num_vertices());
  out += ' ';
  append_int(&out, mesh.num_triangles());
  out += " 0\n";
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    append_real(&out, mesh.positions[i]);
    out += i % 3 == 2 ? '\n' : ' ';
  }
  for (size_t i = 0; i < mesh.triangles.size(); i += 3) {
    out += "3 ";
    for (int c = 0; c < 3; ++c) {
      append_int(&out, mesh.triangles[i + c]);
      out += c == 2 ? '\n' : ' ';
    }
  }
  return out;
}

Status write_off(const std::string& path, const Mesh& mesh) {
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, path));
  return write_output_file(path, format_off(mesh));
}

}  // namespace gab
