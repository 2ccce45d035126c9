// OBJ reader and writer. tinyobjloader (its streaming callback API) does the
// parsing. It reports no positions and reads malformed numbers as 0, so a
// first pass over the text, splitting lines exactly as tinyobjloader does
// ('\n', '\r\n' or '\r'), records the line of every `v` and `f` record and
// checks them, so that errors can name lines and nothing malformed slips
// through as a zero. The k-th face tinyobjloader reports is then the k-th `f`
// line of that pass.
#include "gab/mesh/obj_io.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <exception>
#include <sstream>
#include <vector>

#include "gab/mesh/file_io.h"
#include "text_scanner.h"

namespace gab {

namespace {

using mesh_detail::parse_int;
using mesh_detail::parse_real;
using mesh_detail::printable;

std::vector<std::string_view> split_blanks(std::string_view s);

struct ObjLines {
  std::vector<int64_t> vertex_line;  // line of each `v` record
  std::vector<int64_t> face_line;    // line of each `f` record
};

// Records a Mesh does not carry, counted by the same pass.
struct ObjDropped {
  int64_t normals = 0, texcoords = 0, parameter = 0, colors = 0, weights = 0;
  int64_t face_texcoords = 0, face_normals = 0, polygons = 0;
  int64_t lines = 0, points = 0, groups = 0, objects = 0, smoothing = 0, libraries = 0, materials = 0;
  int64_t other = 0;
  std::string first_other;  // keyword of the first other record

  void note(std::string_view key, std::string_view args) {
    if (key == "vn") {
      ++normals;
    } else if (key == "vt") {
      ++texcoords;
    } else if (key == "vp") {
      ++parameter;
    } else if (key == "l") {
      ++lines;
    } else if (key == "p") {
      ++points;
    } else if (key == "g") {
      ++groups;
    } else if (key == "o") {
      ++objects;
    } else if (key == "s") {
      // "s off" and "s 0" say there is no smoothing group.
      const std::vector<std::string_view> w = split_blanks(args);
      if (!w.empty() && w[0] != "off" && w[0] != "0") ++smoothing;
    } else if (key == "mtllib") {
      ++libraries;
    } else if (key == "usemtl") {
      ++materials;
    } else {
      if (other++ == 0) first_other = printable(key);
    }
  }

  void report(MeshReadNotes* notes) const {
    notes->drop("normals", "normals (vn)", normals);
    notes->drop("texture_coordinates", "texture coordinates (vt)", texcoords);
    notes->drop("parameter_vertices", "parameter-space vertices (vp)", parameter);
    notes->drop("vertex_colors", "vertex colours (v x y z r g b)", colors);
    notes->drop("vertex_weights", "vertex weights (v x y z w)", weights);
    notes->drop("face_texture_indices", "faces with vt indices (f v/vt)", face_texcoords);
    notes->drop("face_normal_indices", "faces with vn indices (f v//vn)", face_normals);
    notes->drop("polygons", "polygons of 4 or more corners (fan-triangulated)", polygons);
    notes->drop("lines", "lines (l)", lines);
    notes->drop("points", "points (p)", points);
    notes->drop("groups", "groups (g)", groups);
    notes->drop("objects", "object names (o)", objects);
    notes->drop("smoothing_groups", "smoothing groups (s)", smoothing);
    notes->drop("material_libraries", "material libraries (mtllib)", libraries);
    notes->drop("material_uses", "material uses (usemtl)", materials);
    notes->drop("other_records", "other records (the first '" + first_other + "')", other);
  }
};

std::vector<std::string_view> split_blanks(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    const size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

// One face corner "v", "v/vt", "v//vn" or "v/vt/vn": false unless every part
// is an integer of at most 10 digits (vt, vn may be empty) and v is a
// nonzero int32 (so tinyobjloader's atoi cannot overflow). has[0], has[1]:
// whether the vt, vn parts are there.
bool parse_corner(std::string_view token, int64_t* v, bool has[2]) {
  size_t slash = token.find('/');
  has[0] = has[1] = false;
  if (!parse_int(token.substr(0, slash), v) || *v == 0 || *v > INT32_MAX || *v < -INT32_MAX) return false;
  for (int part = 0; part < 2 && slash != std::string_view::npos; ++part) {
    const size_t next = token.find('/', slash + 1);
    const std::string_view s = token.substr(slash + 1, next == std::string_view::npos ? next : next - slash - 1);
    int64_t ignored;
    if (!s.empty() && (s.size() > 11 || !parse_int(s, &ignored))) return false;
    has[part] = !s.empty();
    slash = next;
  }
  return slash == std::string_view::npos;
}

Status line_error(const std::string& name, int64_t line, const std::string& what) {
  return Status::Error(StatusCode::kParseError, name + ":" + std::to_string(line) + ": " + what);
}

Status scan_lines(std::string_view text, const std::string& name, ObjLines* lines, ObjDropped* dropped) {
  size_t pos = 0;
  int64_t line_no = 0;
  while (pos < text.size()) {
    size_t end = pos;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    std::string_view line = text.substr(pos, end - pos);
    pos = end;
    if (pos < text.size() && text[pos] == '\r') ++pos;
    if (pos < text.size() && text[pos] == '\n' && (pos == end || text[pos - 1] == '\r')) ++pos;
    ++line_no;
    // tinyobjloader sees a line as a C string: it ends at a NUL byte.
    const size_t nul = line.find('\0');
    if (nul != std::string_view::npos) line = line.substr(0, nul);
    size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i == line.size() || line[i] == '#') continue;
    size_t key_end = i;
    while (key_end < line.size() && line[key_end] != ' ' && line[key_end] != '\t') ++key_end;
    const std::string_view key_word = line.substr(i, key_end - i);
    if (key_word != "v" && key_word != "f") {
      dropped->note(key_word, line.substr(key_end));
      continue;
    }
    if (key_end == line.size()) continue;  // a bare "v" or "f": tinyobjloader skips it
    const char key = line[i];
    const std::vector<std::string_view> w = split_blanks(line.substr(i + 2));
    if (key == 'v') {
      const int64_t v = static_cast<int64_t>(lines->vertex_line.size());
      if (w.size() < 3) {
        return line_error(name, line_no, "vertex " + std::to_string(v) + ": needs 3 coordinates, has " +
                                             std::to_string(w.size()));
      }
      for (int c = 0; c < 3; ++c) {
        double x;
        if (!parse_real(w[c], &x)) {
          return line_error(name, line_no, "vertex " + std::to_string(v) + ": bad coordinate '" + printable(w[c]) + "'");
        }
        if (!std::isfinite(x)) return line_error(name, line_no, "vertex " + std::to_string(v) + ": coordinate is not finite");
      }
      if (lines->vertex_line.size() >= static_cast<size_t>(INT32_MAX)) {
        return line_error(name, line_no, "more than 2^31-1 vertices");
      }
      // tinyobjloader reads "v x y z w" and the common "v x y z r g b".
      if (w.size() >= 6) {
        ++dropped->colors;
      } else if (w.size() >= 4) {
        ++dropped->weights;
      }
      lines->vertex_line.push_back(line_no);
    } else {
      const int64_t f = static_cast<int64_t>(lines->face_line.size());
      if (w.size() < 3) {
        return line_error(name, line_no, "face " + std::to_string(f) + " has " + std::to_string(w.size()) +
                                             " vertices (need 3 or more)");
      }
      bool face_has[2] = {false, false};  // vt, vn indices
      for (std::string_view corner : w) {
        int64_t v;
        bool has[2];
        if (corner == "0" || corner.substr(0, 2) == "0/") {
          return line_error(name, line_no, "face " + std::to_string(f) + ": vertex index 0 (OBJ indices start at 1)");
        }
        if (!parse_corner(corner, &v, has)) {
          return line_error(name, line_no, "face " + std::to_string(f) + ": bad vertex index '" + printable(corner) + "'");
        }
        face_has[0] = face_has[0] || has[0];
        face_has[1] = face_has[1] || has[1];
      }
      dropped->face_texcoords += face_has[0];
      dropped->face_normals += face_has[1];
      dropped->polygons += w.size() > 3;
      lines->face_line.push_back(line_no);
    }
  }
  return Status::Ok();
}

// Receives tinyobjloader's callbacks; the first error wins and stops output.
struct Collector {
  const std::string* name;
  const ObjLines* lines;
  Mesh mesh;
  int64_t faces = 0;
  Status status;

  static void vertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
    Collector& c = *static_cast<Collector*>(self);
    c.mesh.positions.push_back(x);
    c.mesh.positions.push_back(y);
    c.mesh.positions.push_back(z);
  }

  static void face(void* self, tinyobj::index_t* corners, int count) {
    Collector& c = *static_cast<Collector*>(self);
    const int64_t f = c.faces++;
    if (!c.status.ok()) return;
    if (f >= static_cast<int64_t>(c.lines->face_line.size())) {
      c.status = Status::Error(StatusCode::kParseError, *c.name + ": tinyobjloader reported more faces than the file has");
      return;
    }
    const int64_t line = c.lines->face_line[f];
    const int64_t total = static_cast<int64_t>(c.lines->vertex_line.size());
    const int64_t so_far = c.mesh.num_vertices();
    int32_t first = 0, prev = 0;
    for (int k = 0; k < count; ++k) {
      const int64_t raw = corners[k].vertex_index;
      int64_t v;
      if (raw > 0) {
        // Absolute indices may point to vertices defined further down.
        if (raw > total) {
          c.status = line_error(*c.name, line, "face " + std::to_string(f) + ": vertex index " + std::to_string(raw) +
                                                   " out of range [1, " + std::to_string(total) + "]");
          return;
        }
        v = raw - 1;
      } else {
        // Relative: -1 is the last vertex defined before this line.
        v = so_far + raw;
        if (raw == 0 || v < 0) {
          c.status = line_error(*c.name, line, "face " + std::to_string(f) + ": relative vertex index " +
                                                   std::to_string(raw) + " reaches before the first vertex (" +
                                                   std::to_string(so_far) + " defined so far)");
          return;
        }
      }
      const int32_t idx = static_cast<int32_t>(v);
      if (k == 0) first = idx;
      if (k >= 2) {
        c.mesh.triangles.push_back(first);
        c.mesh.triangles.push_back(prev);
        c.mesh.triangles.push_back(idx);
      }
      prev = idx;
    }
    if (c.mesh.triangles.size() / 3 > static_cast<size_t>(INT32_MAX)) {
      c.status = line_error(*c.name, line, "more than 2^31-1 triangles");
    }
  }
};

}  // namespace

Status parse_obj(std::string_view text, const std::string& name, Mesh* mesh, MeshReadNotes* notes) {
  ObjLines lines;
  ObjDropped dropped;
  GAB_RETURN_IF_ERROR(scan_lines(text, name, &lines, &dropped));
  if (lines.vertex_line.empty()) return Status::Error(StatusCode::kParseError, name + ": mesh has no vertices");
  if (lines.face_line.empty()) return Status::Error(StatusCode::kParseError, name + ": mesh has no faces");
  Collector c;
  c.name = &name;
  c.lines = &lines;
  c.mesh.positions.reserve(lines.vertex_line.size() * 3);
  c.mesh.triangles.reserve(lines.face_line.size() * 3);
  tinyobj::callback_t callbacks;
  callbacks.vertex_cb = &Collector::vertex;
  callbacks.index_cb = &Collector::face;
  try {
    std::istringstream stream{std::string(text)};
    std::string warn, err;
    // No material reader: `mtllib` lines are ignored, no other file is opened.
    if (!tinyobj::LoadObjWithCallback(stream, callbacks, &c, nullptr, &warn, &err)) {
      for (char& ch : err) ch = ch == '\n' ? ' ' : ch;  // one-line messages
      return Status::Error(StatusCode::kParseError, name + ": tinyobjloader: " + err);
    }
  } catch (const std::bad_alloc&) {
    return Status::Error(StatusCode::kOutOfMemory, name + ": out of memory while parsing");
  } catch (const std::exception& e) {
    return Status::Error(StatusCode::kParseError, name + ": tinyobjloader: " + e.what());
  }
  GAB_RETURN_IF_ERROR(c.status);
  if (c.mesh.num_vertices() != static_cast<int64_t>(lines.vertex_line.size()) ||
      c.faces != static_cast<int64_t>(lines.face_line.size())) {
    return Status::Error(StatusCode::kParseError, name + ": tinyobjloader and the line scan disagree on the records");
  }
  // The scan saw finite decimals; tinyobjloader's own conversion (not
  // correctly rounded) can still overflow near the largest doubles.
  for (size_t i = 0; i < c.mesh.positions.size(); ++i) {
    if (!std::isfinite(c.mesh.positions[i])) {
      return line_error(name, lines.vertex_line[i / 3],
                        "vertex " + std::to_string(i / 3) + ": coordinate overflows tinyobjloader's number parser");
    }
  }
  *mesh = std::move(c.mesh);
  if (notes != nullptr) {
    *notes = MeshReadNotes();
    dropped.report(notes);
  }
  return Status::Ok();
}

Status read_obj(const std::string& path, Mesh* mesh, MeshReadNotes* notes) {
  std::string bytes;
  GAB_RETURN_IF_ERROR(read_file(path, &bytes));
  return parse_obj(bytes, path, mesh, notes);
}

std::string format_obj(const Mesh& mesh) {
  std::string out = "# written by gab\n";
  out.reserve(out.size() + static_cast<size_t>(mesh.num_vertices()) * (2 + 3 * (mesh_detail::kMaxRealChars + 1)) +
              static_cast<size_t>(mesh.num_triangles()) * (2 + 3 * (mesh_detail::kMaxIndexChars + 1)));
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    if (i % 3 == 0) out += "v";
    out += ' ';
    mesh_detail::append_real(&out, mesh.positions[i]);
    if (i % 3 == 2) out += '\n';
  }
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (t % 3 == 0) out += "f";
    out += ' ';
    mesh_detail::append_int(&out, static_cast<int64_t>(mesh.triangles[t]) + 1);
    if (t % 3 == 2) out += '\n';
  }
  return out;
}

Status write_obj(const std::string& path, const Mesh& mesh) {
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, path));
  return write_output_file(path, format_obj(mesh));
}

}  // namespace gab
