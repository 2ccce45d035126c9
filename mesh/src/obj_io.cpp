// OBJ reader. tinyobjloader (its streaming callback API) does the parsing of
// positions and faces. It reports no positions and reads malformed numbers
// as 0, so a first pass over the text, splitting lines exactly as
// tinyobjloader does ('\n', '\r\n' or '\r'), records the line of every `v`
// and `f` record and checks them, so that errors can name lines and nothing
// malformed slips through as a zero. The k-th face tinyobjloader reports is
// then the k-th `f` line of that pass. The same pass reads the `vn` and `vt`
// records and the colours of `v x y z r g b` itself (tinyobjloader's
// callbacks give no colours, and its numbers are not correctly rounded);
// the faces' vt and vn indices come from tinyobjloader with the v index and
// are resolved against the records the pass counted before each face.
#include "gab/mesh/obj_io.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <exception>
#include <sstream>
#include <vector>

#include "attribute_text.h"
#include "gab/mesh/file_io.h"
#include "text_scanner.h"

namespace gab {

namespace {

using mesh_detail::parse_int;
using mesh_detail::parse_real;
using mesh_detail::printable;

std::vector<std::string_view> split_blanks(std::string_view s);

// The records of one kind of face index: vt (texture coordinates) or vn
// (normals), as the line scan reads them.
struct ObjElements {
  std::vector<double> values;    // 3 per record (vt: u v w, the missing ones 0)
  int64_t first_not_finite = 0;  // line of the first record with a value that is not finite (0: none)

  int64_t count() const { return static_cast<int64_t>(values.size() / 3); }
  // Face f's line comes now: its relative indices count back from here.
  void note_face(int64_t f) {
    if (values.empty()) return;  // 0 before it: kept implicitly (a file without records keeps nothing)
    before_.resize(static_cast<size_t>(f), 0);
    before_.push_back(count());
  }
  // The records defined before face f's line.
  int64_t before(int64_t f) const { return f < static_cast<int64_t>(before_.size()) ? before_[f] : 0; }

 private:
  std::vector<int64_t> before_;  // per face up to the last one after a record
};

struct ObjLines {
  std::vector<int64_t> vertex_line;  // line of each `v` record
  std::vector<int64_t> face_line;    // line of each `f` record
  ObjElements texcoords, normals;
  std::vector<double> colors;        // r g b of each `v x y z r g b` record
  int64_t colors_not_finite = 0;     // line of the first colour that is not finite (0: none)
};

// Records a Mesh does not carry, counted by the same pass.
struct ObjDropped {
  int64_t parameter = 0, weights = 0, polygons = 0;
  int64_t lines = 0, points = 0, groups = 0, objects = 0, smoothing = 0, libraries = 0, materials = 0;
  int64_t other = 0;
  std::string first_other;  // keyword of the first other record

  void note(std::string_view key, std::string_view args) {
    if (key == "vp") {
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
    notes->drop("parameter_vertices", "parameter-space vertices (vp)", parameter);
    notes->drop("vertex_weights", "vertex weights (v x y z w)", weights);
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

// An index part of a face corner: an integer of at most 11 characters
// within int32 (so tinyobjloader's atoi cannot overflow).
bool parse_index(std::string_view s, int64_t* v) {
  return s.size() <= 11 && parse_int(s, v) && *v <= INT32_MAX && *v >= -INT32_MAX;
}

// One face corner "v", "v/vt", "v//vn" or "v/vt/vn" into index[0..2]
// (v, vt, vn; 0 where a part is absent or empty). False unless every part
// written is an index; written[part]: whether the part has text.
bool parse_corner(std::string_view token, int64_t index[3], bool written[3]) {
  size_t slash = token.find('/');
  index[1] = index[2] = 0;
  written[0] = true;
  written[1] = written[2] = false;
  if (!parse_index(token.substr(0, slash), &index[0])) return false;
  for (int part = 1; part < 3 && slash != std::string_view::npos; ++part) {
    const size_t next = token.find('/', slash + 1);
    const std::string_view s = token.substr(slash + 1, next == std::string_view::npos ? next : next - slash - 1);
    written[part] = !s.empty();
    if (written[part] && !parse_index(s, &index[part])) return false;
    slash = next;
  }
  return slash == std::string_view::npos;
}

Status line_error(const std::string& name, int64_t line, const std::string& what) {
  return Status::Error(StatusCode::kParseError, name + ":" + std::to_string(line) + ": " + what);
}

// Reads `count` numbers of `w` from `first` into `out` (the caller checked
// there are that many); the first bad one is an error naming the record:
// `what` (its kind) and `index`.
Status parse_values(const std::vector<std::string_view>& w, size_t first, size_t count, const std::string& name,
                    int64_t line, const char* what, int64_t index, double* out, bool* finite) {
  for (size_t c = 0; c < count; ++c) {
    if (!parse_real(w[first + c], &out[c])) {
      return line_error(name, line, what + std::to_string(index) + ": bad value '" + printable(w[first + c]) + "'");
    }
    *finite = *finite && std::isfinite(out[c]);
  }
  return Status::Ok();
}

// A `vn` (3 values) or `vt` (u [v [w]]) record.
Status scan_element(const std::vector<std::string_view>& w, bool texcoord, const std::string& name, int64_t line,
                    ObjElements* e) {
  const int64_t index = e->count();
  const char* what = texcoord ? "texture coordinate " : "normal ";
  const size_t need = texcoord ? 1 : 3;
  if (w.size() < need) {
    return line_error(name, line, what + std::to_string(index) + ": needs " + (texcoord ? "1 to 3 values" : "3 values") +
                                      ", has " + std::to_string(w.size()));
  }
  if (index >= INT32_MAX) return line_error(name, line, "more than 2^31-1 " + std::string(texcoord ? "vt" : "vn") + " records");
  double v[3] = {0, 0, 0};
  bool finite = true;
  GAB_RETURN_IF_ERROR(parse_values(w, 0, w.size() < 3 ? w.size() : 3, name, line, what, index, v, &finite));
  if (!finite && e->first_not_finite == 0) e->first_not_finite = line;
  e->values.insert(e->values.end(), v, v + 3);
  return Status::Ok();
}

Status scan_vertex(const std::vector<std::string_view>& w, const std::string& name, int64_t line, ObjLines* lines,
                   ObjDropped* dropped) {
  const int64_t v = static_cast<int64_t>(lines->vertex_line.size());
  if (w.size() < 3) {
    return line_error(name, line, "vertex " + std::to_string(v) + ": needs 3 coordinates, has " + std::to_string(w.size()));
  }
  for (int c = 0; c < 3; ++c) {
    double x;
    if (!parse_real(w[c], &x)) {
      return line_error(name, line, "vertex " + std::to_string(v) + ": bad coordinate '" + printable(w[c]) + "'");
    }
    if (!std::isfinite(x)) return line_error(name, line, "vertex " + std::to_string(v) + ": coordinate is not finite");
  }
  if (lines->vertex_line.size() >= static_cast<size_t>(INT32_MAX)) return line_error(name, line, "more than 2^31-1 vertices");
  // tinyobjloader reads "v x y z w"; "v x y z r g b" is the common colour extension.
  if (w.size() >= 6) {
    double rgb[3];
    bool finite = true;
    GAB_RETURN_IF_ERROR(parse_values(w, 3, 3, name, line, "colour of vertex ", v, rgb, &finite));
    if (!finite && lines->colors_not_finite == 0) lines->colors_not_finite = line;
    lines->colors.insert(lines->colors.end(), rgb, rgb + 3);
  } else if (w.size() >= 4) {
    ++dropped->weights;
  }
  lines->vertex_line.push_back(line);
  return Status::Ok();
}

Status scan_face(const std::vector<std::string_view>& w, const std::string& name, int64_t line, ObjLines* lines,
                 ObjDropped* dropped) {
  const int64_t f = static_cast<int64_t>(lines->face_line.size());
  auto face = [f] { return "face " + std::to_string(f); };
  if (w.size() < 3) {
    return line_error(name, line, face() + " has " + std::to_string(w.size()) + " vertices (need 3 or more)");
  }
  static const char* const kPart[3] = {"vertex", "texture coordinate", "normal"};
  for (std::string_view corner : w) {
    int64_t index[3];
    bool written[3];
    if (corner == "0" || corner.substr(0, 2) == "0/") {
      return line_error(name, line, face() + ": vertex index 0 (OBJ indices start at 1)");
    }
    if (!parse_corner(corner, index, written) || index[0] == 0) {
      return line_error(name, line, face() + ": bad vertex index '" + printable(corner) + "'");
    }
    // tinyobjloader reads an index 0 as "absent": say it is wrong instead.
    for (int part = 1; part < 3; ++part) {
      if (written[part] && index[part] == 0) {
        return line_error(name, line, face() + ": " + kPart[part] + " index 0 (OBJ indices start at 1)");
      }
    }
  }
  dropped->polygons += w.size() > 3;
  lines->face_line.push_back(line);
  lines->texcoords.note_face(f);
  lines->normals.note_face(f);
  return Status::Ok();
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
    const std::string_view key = line.substr(i, key_end - i);
    const bool known = key == "v" || key == "f" || key == "vn" || key == "vt";
    if (!known) {
      dropped->note(key, line.substr(key_end));
      continue;
    }
    if (key_end == line.size()) continue;  // a bare keyword: tinyobjloader skips it
    const std::vector<std::string_view> w = split_blanks(line.substr(key_end));
    if (key == "v") {
      GAB_RETURN_IF_ERROR(scan_vertex(w, name, line_no, lines, dropped));
    } else if (key == "f") {
      GAB_RETURN_IF_ERROR(scan_face(w, name, line_no, lines, dropped));
    } else {
      GAB_RETURN_IF_ERROR(scan_element(w, key == "vt", name, line_no, key == "vt" ? &lines->texcoords : &lines->normals));
    }
  }
  return Status::Ok();
}

// The corners' elements of one kind of face index, in triangle order (-1:
// the corner has none), and the faces without one.
struct CornerIndices {
  std::vector<int32_t> element;
  int64_t faces_without = 0;
  int64_t first_face_without = -1;
  int64_t faces_with = 0;
};

// Receives tinyobjloader's callbacks; the first error wins and stops output.
struct Collector {
  const std::string* name;
  const ObjLines* lines;
  Mesh mesh;
  CornerIndices texcoords, normals;
  int64_t faces = 0;
  Status status;

  static void vertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
    Collector& c = *static_cast<Collector*>(self);
    c.mesh.positions.push_back(x);
    c.mesh.positions.push_back(y);
    c.mesh.positions.push_back(z);
  }

  // The 0-based index of a raw OBJ index `raw` (1-based, or negative:
  // relative to the `so_far` records before the face) into `total` records;
  // false when it is out of range.
  static bool resolve(int64_t raw, int64_t so_far, int64_t total, int32_t* out) {
    // Absolute indices may point to records defined further down; relative
    // ones count back from the face: -1 is the last record defined before it.
    const int64_t v = raw > 0 ? raw - 1 : so_far + raw;
    if (v < 0 || v >= total || (raw < 0 && v >= so_far)) return false;
    *out = static_cast<int32_t>(v);
    return true;
  }

  // Why `raw` does not resolve; `what`: "vertex", "texture coordinate", "normal".
  Status index_error(int64_t raw, int64_t so_far, int64_t total, int64_t f, const char* what) const {
    const int64_t line = lines->face_line[f];
    if (raw > 0) {
      return line_error(*name, line, "face " + std::to_string(f) + ": " + what + " index " + std::to_string(raw) +
                                         " out of range [1, " + std::to_string(total) + "]");
    }
    return line_error(*name, line, "face " + std::to_string(f) + ": relative " + what + " index " +
                                       std::to_string(raw) + " reaches before the first " + what + " (" +
                                       std::to_string(so_far) + " defined so far)");
  }

  static void face(void* self, tinyobj::index_t* corners, int count) {
    Collector& c = *static_cast<Collector*>(self);
    const int64_t f = c.faces++;
    if (!c.status.ok()) return;
    if (f >= static_cast<int64_t>(c.lines->face_line.size())) {
      c.status = Status::Error(StatusCode::kParseError, *c.name + ": tinyobjloader reported more faces than the file has");
      return;
    }
    if (!c.add_face(f, corners, count)) return;  // c.status says why
  }

  // Adds face f's triangles and its corners' vt and vn; false (and
  // `status` set) on a bad index.
  bool add_face(int64_t f, const tinyobj::index_t* corners, int count) {
    bool has_texcoord = false, has_normal = false, lacks_texcoord = false, lacks_normal = false;
    const int64_t vertices = static_cast<int64_t>(lines->vertex_line.size());
    const int64_t texcoord_total = lines->texcoords.count(), normal_total = lines->normals.count();
    const int64_t texcoords_before = lines->texcoords.before(f), normals_before = lines->normals.before(f);
    Corner first, prev;
    for (int k = 0; k < count; ++k) {
      Corner c;
      const tinyobj::index_t& corner = corners[k];
      if (!resolve(corner.vertex_index, mesh.num_vertices(), vertices, &c.v)) {
        status = index_error(corner.vertex_index, mesh.num_vertices(), vertices, f, "vertex");
        return false;
      }
      if (corner.texcoord_index != 0 && !resolve(corner.texcoord_index, texcoords_before, texcoord_total, &c.vt)) {
        status = index_error(corner.texcoord_index, texcoords_before, texcoord_total, f, "texture coordinate");
        return false;
      }
      if (corner.normal_index != 0 && !resolve(corner.normal_index, normals_before, normal_total, &c.vn)) {
        status = index_error(corner.normal_index, normals_before, normal_total, f, "normal");
        return false;
      }
      (c.vt >= 0 ? has_texcoord : lacks_texcoord) = true;
      (c.vn >= 0 ? has_normal : lacks_normal) = true;
      if (k == 0) first = c;
      if (k >= 2) {
        // Fan triangulation (c0, c_{k-1}, c_k): each corner keeps its own vt
        // and vn. (A file without vt or vn records keeps no corners for
        // them: a face that refers to one has failed above.)
        mesh.triangles.push_back(first.v);
        mesh.triangles.push_back(prev.v);
        mesh.triangles.push_back(c.v);
        if (texcoord_total > 0) push3(&texcoords.element, first.vt, prev.vt, c.vt);
        if (normal_total > 0) push3(&normals.element, first.vn, prev.vn, c.vn);
      }
      prev = c;
    }
    count_face(has_texcoord, lacks_texcoord, f, &texcoords);
    count_face(has_normal, lacks_normal, f, &normals);
    if (mesh.triangles.size() / 3 > static_cast<size_t>(INT32_MAX)) {
      status = line_error(*name, lines->face_line[f], "more than 2^31-1 triangles");
      return false;
    }
    return true;
  }

  // A polygon corner's vertex, texture coordinate and normal (-1: none).
  struct Corner {
    int32_t v = 0, vt = -1, vn = -1;
  };

  static void push3(std::vector<int32_t>* out, int32_t a, int32_t b, int32_t c) {
    out->push_back(a);
    out->push_back(b);
    out->push_back(c);
  }

  static void count_face(bool has, bool lacks, int64_t f, CornerIndices* c) {
    c->faces_with += has;
    if (!lacks) return;
    if (c->faces_without++ == 0) c->first_face_without = f;
  }
};

// The normals or texture coordinates, per corner, when the faces refer to
// them; what is not carried is noted. Corners without an index (faces that
// have none where others have them) refer to one element added after the
// file's, all zeros, and a warning says so.
void add_corner_attribute(AttributeKind kind, const ObjElements& records, CornerIndices* corners,
                          const ObjLines& lines, const std::string& name, Mesh* mesh, MeshReadNotes* notes) {
  const bool texcoord = kind == AttributeKind::kTexCoord;
  const std::string words = texcoord ? "texture coordinates (vt" : "normals (vn";
  const std::string key = texcoord ? "texture_coordinates" : "normals";
  if (corners->faces_with == 0) {
    notes->drop(key, words + "; no face refers to them)", records.count());
    return;
  }
  if (records.first_not_finite != 0) {
    notes->drop(key, words + "; line " + std::to_string(records.first_not_finite) + " has a value that is not finite)",
                records.count());
    return;
  }
  MeshAttribute a;
  a.kind = kind;
  // vt: u v, with w only when one is nonzero.
  a.components = 3;
  if (texcoord) {
    bool any_w = false;
    for (size_t i = 2; i < records.values.size(); i += 3) any_w = any_w || records.values[i] != 0.0;
    a.components = any_w ? 3 : 2;
  }
  const size_t k = static_cast<size_t>(a.components);
  a.values.reserve(records.values.size() / 3 * k + k);
  for (size_t i = 0; i < records.values.size(); i += 3) a.values.insert(a.values.end(), &records.values[i], &records.values[i] + k);
  a.corners = std::move(corners->element);
  if (corners->faces_without > 0) {
    const int32_t added = static_cast<int32_t>(records.count());
    a.values.insert(a.values.end(), k, 0.0);
    for (int32_t& e : a.corners) e = e < 0 ? added : e;
    notes->warn(name + ":" + std::to_string(lines.face_line[corners->first_face_without]) + ": " +
                std::to_string(corners->faces_without) + " faces have no " + (texcoord ? "vt" : "vn") +
                " index; their corners refer to " + (texcoord ? "texture coordinate " : "normal ") +
                std::to_string(added + 1) + " (all zeros), added after the file's " + std::to_string(added));
  }
  a.type = mesh_detail::settle_decimal_values(&a.values);
  mesh->attributes.push_back(std::move(a));
}

// Per-vertex colours when every vertex has them; else noted.
void add_colors(const ObjLines& lines, Mesh* mesh, MeshReadNotes* notes) {
  const int64_t colored = static_cast<int64_t>(lines.colors.size() / 3);
  if (colored == 0) return;
  if (colored != mesh->num_vertices()) {
    notes->drop("vertex_colors", "vertex colours (v x y z r g b; not on every vertex)", colored);
    return;
  }
  if (lines.colors_not_finite != 0) {
    notes->drop("vertex_colors",
                "vertex colours (v x y z r g b; line " + std::to_string(lines.colors_not_finite) +
                    " has a value that is not finite)",
                colored);
    return;
  }
  MeshAttribute a;
  a.kind = AttributeKind::kColor;
  a.components = 3;
  a.values = lines.colors;
  a.type = mesh_detail::settle_decimal_values(&a.values);
  mesh->attributes.push_back(std::move(a));
}

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
  MeshReadNotes seen;
  add_corner_attribute(AttributeKind::kNormal, lines.normals, &c.normals, lines, name, &c.mesh, &seen);
  add_corner_attribute(AttributeKind::kTexCoord, lines.texcoords, &c.texcoords, lines, name, &c.mesh, &seen);
  add_colors(lines, &c.mesh, &seen);
  dropped.report(&seen);
  *mesh = std::move(c.mesh);
  if (notes != nullptr) *notes = std::move(seen);
  return Status::Ok();
}

Status read_obj(const std::string& path, Mesh* mesh, MeshReadNotes* notes) {
  std::string bytes;
  GAB_RETURN_IF_ERROR(read_file(path, &bytes));
  return parse_obj(bytes, path, mesh, notes);
}

}  // namespace gab
