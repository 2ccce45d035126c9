// PLY body decoder. One loop walks the elements in file order for both
// encodings; a Source (binary cursor or ASCII token scanner) supplies the
// values, so the checks and the messages are written once. Every count is
// checked against the bytes that remain before anything is sized from it.
// The properties kept as attributes are planned from the header
// (ply_attributes.h); their values are checked as they come, and an
// attribute with one it cannot keep is noted as dropped, not an error.
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "gab/mesh/file_io.h"
#include "gab/mesh/ply_io.h"
#include "attribute_text.h"
#include "ply_attributes.h"
#include "ply_header.h"
#include "text_scanner.h"

namespace gab {

namespace {

using mesh_detail::parse_int;
using mesh_detail::parse_real;
using mesh_detail::PlyElement;
using mesh_detail::PlyHeader;
using mesh_detail::PlyProperty;
using mesh_detail::PlyType;
using mesh_detail::ply_type_is_integral;
using mesh_detail::ply_type_size;
using mesh_detail::printable;

enum class Read { kOk, kEnd, kBad };

class BinarySource {
 public:
  BinarySource(std::string_view body, bool big_endian, const std::string& name)
      : p_(reinterpret_cast<const unsigned char*>(body.data())), end_(p_ + body.size()), big_(big_endian),
        name_(name) {}

  Read real(PlyType t, double* v) {
    uint64_t bits;
    if (!load(t, &bits)) return Read::kEnd;
    *v = convert_real(t, bits);
    return Read::kOk;
  }
  Read integer(PlyType t, int64_t* v) {
    uint64_t bits;
    if (!load(t, &bits)) return Read::kEnd;
    *v = convert_int(t, bits);
    return Read::kOk;
  }
  Read skip(PlyType t, int64_t count) {
    const uint64_t bytes = static_cast<uint64_t>(count) * static_cast<uint64_t>(ply_type_size(t));
    if (bytes > static_cast<uint64_t>(end_ - p_)) return Read::kEnd;
    p_ += bytes;
    return Read::kOk;
  }
  size_t remaining() const { return static_cast<size_t>(end_ - p_); }
  // Bytes a list item needs at least.
  static size_t min_item_bytes(PlyType t) { return static_cast<size_t>(ply_type_size(t)); }
  std::string where() const { return name_ + ": "; }
  std::string last_token() const { return ""; }

 private:
  bool load(PlyType t, uint64_t* bits) {
    const int n = ply_type_size(t);
    if (end_ - p_ < n) return false;
    uint64_t v = 0;
    if (big_) {
      for (int i = 0; i < n; ++i) v = (v << 8) | p_[i];
    } else {
      for (int i = n - 1; i >= 0; --i) v = (v << 8) | p_[i];
    }
    p_ += n;
    *bits = v;
    return true;
  }
  static int64_t convert_int(PlyType t, uint64_t b) {
    switch (t) {
      case PlyType::kInt8: return static_cast<int8_t>(static_cast<uint8_t>(b));
      case PlyType::kUint8: return static_cast<uint8_t>(b);
      case PlyType::kInt16: return static_cast<int16_t>(static_cast<uint16_t>(b));
      case PlyType::kUint16: return static_cast<uint16_t>(b);
      case PlyType::kInt32: return static_cast<int32_t>(static_cast<uint32_t>(b));
      case PlyType::kUint32: return static_cast<uint32_t>(b);
      default: return 0;  // float types never reach here (checked in the header)
    }
  }
  static double convert_real(PlyType t, uint64_t b) {
    if (t == PlyType::kFloat32) {
      const uint32_t u = static_cast<uint32_t>(b);
      float f;
      std::memcpy(&f, &u, sizeof(f));
      return f;
    }
    if (t == PlyType::kFloat64) {
      double d;
      std::memcpy(&d, &b, sizeof(d));
      return d;
    }
    return static_cast<double>(convert_int(t, b));
  }

  const unsigned char* p_;
  const unsigned char* end_;
  bool big_;
  const std::string& name_;
};

class AsciiSource {
 public:
  AsciiSource(std::string_view body, int64_t first_line, const std::string& name)
      : scan_(body, name, '\0'), name_(name) {
    scan_.set_line(first_line);
  }

  Read real(PlyType, double* v) {
    if (!scan_.next(&token_)) return Read::kEnd;
    return parse_real(token_, v) ? Read::kOk : Read::kBad;
  }
  Read integer(PlyType, int64_t* v) {
    if (!scan_.next(&token_)) return Read::kEnd;
    return parse_int(token_, v) ? Read::kOk : Read::kBad;
  }
  Read skip(PlyType t, int64_t count) {
    for (int64_t i = 0; i < count; ++i) {
      double v;
      const Read r = real(t, &v);
      if (r != Read::kOk) return r;
    }
    return Read::kOk;
  }
  size_t remaining() const { return scan_.remaining(); }
  static size_t min_item_bytes(PlyType) { return 2; }  // a digit and a separator
  std::string where() const { return name_ + ":" + std::to_string(scan_.token_line()) + ": "; }
  std::string last_token() const { return printable(token_); }

 private:
  mesh_detail::TextScanner scan_;
  const std::string& name_;
  std::string_view token_;
};

// What the decoder does with each element.
struct Roles {
  int vertex = -1;            // element index of "vertex"
  int xyz[3] = {-1, -1, -1};  // its x, y, z properties
  int face = -1, face_list = -1;
  int strips = -1, strips_list = -1;
  mesh_detail::PlyAttributes attributes;  // the properties kept as attributes
};

int index_list(const PlyElement& e) {
  const int p = e.find("vertex_indices");
  return p >= 0 ? p : e.find("vertex_index");
}

Status header_error(const std::string& name, int64_t line, const std::string& what) {
  return Status::Error(StatusCode::kParseError, name + ":" + std::to_string(line) + ": " + what);
}

// Face colours: the names a face property of colour may have.
bool is_color_name(const std::string& p) {
  for (const char* n : {"red", "green", "blue", "alpha", "r", "g", "b", "a", "diffuse_red", "diffuse_green",
                        "diffuse_blue", "diffuse_alpha"}) {
    if (p == n) return true;
  }
  return false;
}

// What the header declares that the decoder skips, into `notes`: vertex
// properties that are no attribute's (past kMaxMeshAttributes, or named as
// no attribute can be), by name; face and strip properties other than the
// index list and the per-corner texture coordinates (colours together,
// others by name); other elements by name. Counts are the elements that
// carry the data.
void note_skipped(const PlyHeader& h, const Roles& roles, MeshReadNotes* notes) {
  for (size_t ei = 0; ei < h.elements.size(); ++ei) {
    const PlyElement& e = h.elements[ei];
    const int index = static_cast<int>(ei);
    if (index != roles.vertex && index != roles.face && index != roles.strips) {
      notes->drop("element." + printable(e.name), "'" + printable(e.name) + "' elements", e.count);
      continue;
    }
    const int kept = index == roles.face ? roles.face_list : index == roles.strips ? roles.strips_list : -1;
    const std::vector<mesh_detail::PlySlot>* slots =
        index == roles.vertex ? &roles.attributes.vertex : index == roles.face ? &roles.attributes.face : nullptr;
    std::string color_names;  // a face's colour properties
    std::vector<int> named;   // the others, by name
    for (size_t pi = 0; pi < e.properties.size(); ++pi) {
      const int p = static_cast<int>(pi);
      if (p == kept || (slots != nullptr && !slots->empty() && (*slots)[pi].plan >= 0)) continue;
      if (index == roles.vertex && (p == roles.xyz[0] || p == roles.xyz[1] || p == roles.xyz[2])) continue;
      if (index != roles.vertex && is_color_name(e.properties[pi].name)) {
        color_names += (color_names.empty() ? "" : " ") + e.properties[pi].name;
      } else {
        named.push_back(p);
      }
    }
    if (!color_names.empty()) notes->drop("face_colors", printable(e.name) + " colours (" + color_names + ")", e.count);
    for (int pi : named) {
      const std::string p = printable(e.properties[pi].name);
      notes->drop(printable(e.name) + "." + p, printable(e.name) + " property '" + p + "'", e.count);
    }
  }
}

// Assigns roles, then checks the header against the body size: every
// element instance needs a minimum number of bytes, so a count larger than
// the body can hold is refused before any allocation.
Status plan(const PlyHeader& h, size_t body_size, const std::string& name, Roles* roles) {
  for (size_t i = 0; i < h.elements.size(); ++i) {
    const PlyElement& e = h.elements[i];
    const bool is_face = e.name == "face", is_strips = e.name == "tristrips";
    if (e.name == "vertex") {
      roles->vertex = static_cast<int>(i);
      const char* axes[3] = {"x", "y", "z"};
      for (int c = 0; c < 3; ++c) {
        roles->xyz[c] = e.find(axes[c]);
        if (roles->xyz[c] < 0) return header_error(name, e.line, std::string("element 'vertex' has no property '") + axes[c] + "'");
        if (e.properties[roles->xyz[c]].is_list) {
          return header_error(name, e.line, std::string("vertex property '") + axes[c] + "' is a list");
        }
      }
      if (e.count == 0) return header_error(name, e.line, "mesh has no vertices");
      if (e.count > INT32_MAX) return header_error(name, e.line, "more than 2^31-1 vertices");
    } else if (is_face || is_strips) {
      const int list = index_list(e);
      if (list < 0 || !e.properties[list].is_list) {
        return header_error(name, e.line, "element '" + e.name + "' has no vertex_indices list");
      }
      if (!ply_type_is_integral(e.properties[list].type)) {
        return header_error(name, e.line, "element '" + e.name + "': vertex indices are not an integer type");
      }
      (is_face ? roles->face : roles->strips) = static_cast<int>(i);
      (is_face ? roles->face_list : roles->strips_list) = list;
    }
  }
  if (roles->vertex < 0) return Status::Error(StatusCode::kParseError, name + ": no 'vertex' element");
  if (roles->face < 0 && roles->strips < 0) {
    return Status::Error(StatusCode::kParseError, name + ": no 'face' or 'tristrips' element (mesh has no faces)");
  }
  const bool ascii = h.encoding == PlyEncoding::kAscii;
  uint64_t need = 0;
  for (const PlyElement& e : h.elements) {
    uint64_t min_bytes = 0;
    for (const PlyProperty& p : e.properties) {
      min_bytes += ascii ? 2 : static_cast<uint64_t>(ply_type_size(p.is_list ? p.count_type : p.type));
    }
    // An ASCII body may lack the final separator: one byte of slack.
    const uint64_t budget = body_size + (ascii ? 1 : 0) - need;
    if (min_bytes > 0 && static_cast<uint64_t>(e.count) > budget / min_bytes) {
      return header_error(name, e.line,
                          "element '" + printable(e.name) + "' claims " + std::to_string(e.count) +
                              " entries, more than the " + std::to_string(body_size) +
                              " bytes after the header can hold");
    }
    need += static_cast<uint64_t>(e.count) * min_bytes;
  }
  roles->attributes = mesh_detail::plan_ply_attributes(h, roles->vertex, roles->xyz, roles->face, roles->strips >= 0);
  return Status::Ok();
}

constexpr size_t kMaxTriangleIndices = static_cast<size_t>(INT32_MAX) / 3 * 3;

// One planned attribute's values as the body gives them, or why they
// cannot be kept (the first problem met; the rest of its values are read
// and ignored).
struct AttributeValues {
  int32_t components = 0;
  std::vector<double> values;
  std::vector<int32_t> corners;  // per corner (the faces' texcoord lists)
  std::string problem;
};

// Per-corner texture coordinates: equal (u, v) pairs share an element, so
// that a vertex whose corners agree is no seam.
struct UvKey {
  uint64_t u, v;
  bool operator==(const UvKey& o) const { return u == o.u && v == o.v; }
};
struct UvKeyHash {
  size_t operator()(const UvKey& k) const { return std::hash<uint64_t>()(k.u * 0x9E3779B97F4A7C15ull ^ k.v); }
};

template <class Source>
class BodyDecoder {
 public:
  BodyDecoder(Source* src, const PlyHeader& h, const Roles& roles, const std::string& name, Mesh* m)
      : src_(*src), h_(h), roles_(roles), name_(name), m_(*m) {
    nv_ = h.elements[roles.vertex].count;
  }

  Status run() {
    m_.positions.assign(static_cast<size_t>(nv_) * 3, 0.0);
    if (roles_.face >= 0) m_.triangles.reserve(static_cast<size_t>(h_.elements[roles_.face].count) * 3);
    const std::vector<mesh_detail::PlyAttributePlan>& plans = roles_.attributes.plans;
    values_.resize(plans.size());
    for (size_t a = 0; a < plans.size(); ++a) {
      values_[a].components = plans[a].attribute.components;
      if (!plans[a].list && !is_face_plan(static_cast<int>(a))) {
        values_[a].values.assign(static_cast<size_t>(nv_) * static_cast<size_t>(values_[a].components), 0.0);
      }
    }
    for (size_t ei = 0; ei < h_.elements.size(); ++ei) {
      const PlyElement& e = h_.elements[ei];
      if (e.properties.empty()) continue;  // nothing stored; the count costs no bytes
      const bool is_face = static_cast<int>(ei) == roles_.face;
      for (int64_t i = 0; i < e.count; ++i) {
        double xyz[3] = {0, 0, 0};
        polygon_.clear();
        uv_.clear();
        for (size_t pi = 0; pi < e.properties.size(); ++pi) {
          const PlyProperty& p = e.properties[pi];
          Status s = p.is_list ? list(e, static_cast<int>(ei), i, static_cast<int>(pi))
                               : scalar(e, static_cast<int>(ei), i, static_cast<int>(pi), xyz);
          if (!s.ok()) return s;
        }
        if (static_cast<int>(ei) == roles_.vertex) {
          for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(xyz[c])) return fail(e, i, "coordinate is not finite");
            m_.positions[static_cast<size_t>(i) * 3 + c] = xyz[c];
          }
        }
        if (is_face) GAB_RETURN_IF_ERROR(finish_face(e, i));
      }
    }
    if (m_.triangles.empty()) return Status::Error(StatusCode::kParseError, name_ + ": mesh has no faces");
    return Status::Ok();
  }

  // The attributes into the mesh, in plan order; the ones with a problem
  // into `notes` instead.
  void finish(MeshReadNotes* notes) {
    const std::vector<mesh_detail::PlyAttributePlan>& plans = roles_.attributes.plans;
    for (size_t a = 0; a < plans.size(); ++a) {
      const mesh_detail::PlyAttributePlan& plan = plans[a];
      AttributeValues& v = values_[a];
      if (!v.problem.empty()) {
        const bool open = !plan.label.empty() && plan.label.back() == '(';
        const int64_t count = is_face_plan(static_cast<int>(a)) ? h_.elements[roles_.face].count : nv_;
        notes->drop(plan.key, plan.label + (open ? "" : "; ") + v.problem + ")", count);
        continue;
      }
      MeshAttribute attribute = plan.attribute;
      attribute.components = v.components;
      attribute.values = std::move(v.values);
      attribute.corners = std::move(v.corners);
      m_.attributes.push_back(std::move(attribute));
    }
  }

  int64_t polygons() const { return polygons_; }

 private:
  Status fail(const PlyElement& e, int64_t i, const std::string& what) const {
    return Status::Error(StatusCode::kParseError, src_.where() + printable(e.name) + " " + std::to_string(i) + ": " + what);
  }
  Status end_or_bad(Read r, const PlyElement& e, int64_t i, const PlyProperty& p) const {
    if (r == Read::kEnd) {
      return Status::Error(StatusCode::kParseError, src_.where() + "truncated: file ends in " + printable(e.name) + " " +
                                                        std::to_string(i) + " of " + std::to_string(e.count));
    }
    return fail(e, i, "bad value '" + src_.last_token() + "' for property '" + printable(p.name) + "'");
  }

  bool is_face_plan(int plan) const {
    for (const mesh_detail::PlySlot& s : roles_.attributes.face) {
      if (s.plan == plan) return true;
    }
    return false;
  }

  // Reads one value of property `p` for an attribute into *x; `problem`
  // gets why the attribute cannot keep it (a value that is not finite, or
  // an ASCII value its declared type cannot hold), unless it has one.
  Status attribute_value(const PlyElement& e, int64_t i, const PlyProperty& p, AttributeValues* a, double* x) {
    const Read r = src_.real(p.type, x);
    if (r != Read::kOk) return end_or_bad(r, e, i, p);
    if (!a->problem.empty()) return Status::Ok();
    const std::string where = printable(e.name) + " " + std::to_string(i) + ": ";
    if (!std::isfinite(*x)) {
      a->problem = where + "a value that is not finite";
    } else if (p.type == PlyType::kFloat32) {
      if (!mesh_detail::round_to_float(*x, x)) a->problem = where + "a value beyond float's range";
    } else if (ply_type_is_integral(p.type)) {
      double lo, hi;
      value_type_range(mesh_detail::value_type(p.type), &lo, &hi);
      if (*x < lo || *x > hi || *x != std::floor(*x)) {
        a->problem = where + "a value that is not a " + mesh_detail::ply_type_name(mesh_detail::value_type(p.type));
      }
    }
    return Status::Ok();
  }

  Status scalar(const PlyElement& e, int ei, int64_t i, int pi, double* xyz) {
    const PlyProperty& p = e.properties[pi];
    if (ei == roles_.vertex) {
      for (int c = 0; c < 3; ++c) {
        if (pi != roles_.xyz[c]) continue;
        const Read r = src_.real(p.type, &xyz[c]);
        return r == Read::kOk ? Status::Ok() : end_or_bad(r, e, i, p);
      }
      const mesh_detail::PlySlot slot = roles_.attributes.vertex[pi];
      if (slot.plan >= 0) {
        AttributeValues& a = values_[slot.plan];
        double x;
        GAB_RETURN_IF_ERROR(attribute_value(e, i, p, &a, &x));
        if (a.problem.empty()) a.values[static_cast<size_t>(i) * a.components + slot.component] = x;
        return Status::Ok();
      }
    }
    const Read r = src_.skip(p.type, 1);
    return r == Read::kOk ? Status::Ok() : end_or_bad(r, e, i, p);
  }

  // A vertex list property kept as a generic of as many components as the
  // first vertex's list has items (1 to 4): every vertex must have as many.
  Status vertex_list(const PlyElement& e, int64_t i, const PlyProperty& p, int64_t count, AttributeValues* a) {
    if (a->problem.empty()) {
      if (i == 0 && (count < 1 || count > 4)) {
        a->problem = "vertex 0: " + std::to_string(count) + " items (a generic attribute holds 1 to 4)";
      } else if (i == 0) {
        a->components = static_cast<int32_t>(count);
        a->values.assign(static_cast<size_t>(nv_) * static_cast<size_t>(count), 0.0);
      } else if (count != a->components) {
        a->problem = "vertex " + std::to_string(i) + ": " + std::to_string(count) + " items where vertex 0 has " +
                     std::to_string(a->components);
      }
    }
    for (int64_t k = 0; k < count; ++k) {
      double x;
      GAB_RETURN_IF_ERROR(attribute_value(e, i, p, a, &x));
      if (a->problem.empty()) a->values[static_cast<size_t>(i * a->components + k)] = x;
    }
    return Status::Ok();
  }

  Status list(const PlyElement& e, int ei, int64_t i, int pi) {
    const PlyProperty& p = e.properties[pi];
    int64_t count = 0;
    Read r = src_.integer(p.count_type, &count);
    if (r != Read::kOk) return end_or_bad(r, e, i, p);
    if (count < 0) return fail(e, i, "negative list length " + std::to_string(count));
    if (static_cast<uint64_t>(count) > src_.remaining() / Source::min_item_bytes(p.type) + 1) {
      return fail(e, i, "list length " + std::to_string(count) + " is more than the rest of the file can hold");
    }
    const bool is_face = ei == roles_.face && pi == roles_.face_list;
    const bool is_strip = ei == roles_.strips && pi == roles_.strips_list;
    if (ei == roles_.vertex && roles_.attributes.vertex[pi].plan >= 0) {
      return vertex_list(e, i, p, count, &values_[roles_.attributes.vertex[pi].plan]);
    }
    if (ei == roles_.face && !roles_.attributes.face.empty() && roles_.attributes.face[pi].plan >= 0) {
      AttributeValues& a = values_[roles_.attributes.face[pi].plan];
      for (int64_t k = 0; k < count; ++k) {
        double x;
        GAB_RETURN_IF_ERROR(attribute_value(e, i, p, &a, &x));
        uv_.push_back(x);
      }
      return Status::Ok();
    }
    if (!is_face && !is_strip) {
      r = src_.skip(p.type, count);
      return r == Read::kOk ? Status::Ok() : end_or_bad(r, e, i, p);
    }
    if (is_face && count < 3) {
      return Status::Error(StatusCode::kParseError, src_.where() + e.name + " " + std::to_string(i) + " has " +
                                                        std::to_string(count) + " vertices (need 3 or more)");
    }
    if (is_face && count > 3) ++polygons_;
    int32_t a = 0, b = 0;  // the strip's previous two
    int64_t run = 0;       // position in the current strip
    for (int64_t k = 0; k < count; ++k) {
      int64_t v;
      r = src_.integer(p.type, &v);
      if (r != Read::kOk) return end_or_bad(r, e, i, p);
      if (is_strip && v == -1) {  // restart
        run = 0;
        continue;
      }
      if (v < 0 || v >= nv_) {
        return fail(e, i, (is_strip ? "entry " + std::to_string(k) + ": " : std::string()) + "vertex index " +
                              std::to_string(v) + " out of range [0, " + std::to_string(nv_) + ")");
      }
      const int32_t c = static_cast<int32_t>(v);
      if (is_face) {
        polygon_.push_back(c);  // triangulated with its texture coordinates at the face's end
        continue;
      }
      // Strip triangle j = run - 2 is (s_j, s_j+1, s_j+2) for even j and
      // (s_j+1, s_j, s_j+2) for odd j, so all faces share one orientation.
      // Repeated vertices are a strip's way of turning or stitching, not
      // faces: drop those zero-area triangles.
      if (run >= 2 && a != b && b != c && a != c) {
        if ((run - 2) % 2 == 0) {
          push(a, b, c);
        } else {
          push(b, a, c);
        }
      }
      a = b;
      b = c;
      ++run;
      if (m_.triangles.size() > kMaxTriangleIndices) return fail(e, i, "more than 2^31-1 triangles");
    }
    return Status::Ok();
  }

  // Face i's polygon fan-triangulated (v0, v_{k-1}, v_k); with per-corner
  // texture coordinates, each triangle corner gets its polygon corner's.
  Status finish_face(const PlyElement& e, int64_t i) {
    const size_t k = polygon_.size();
    for (size_t c = 2; c < k; ++c) push(polygon_[0], polygon_[c - 1], polygon_[c]);
    if (m_.triangles.size() > kMaxTriangleIndices) return fail(e, i, "more than 2^31-1 triangles");
    for (const mesh_detail::PlySlot& s : roles_.attributes.face) {
      if (s.plan < 0) continue;
      AttributeValues& a = values_[s.plan];
      if (!a.problem.empty()) continue;
      if (uv_.size() != 2 * k) {
        a.problem = "face " + std::to_string(i) + ": " + std::to_string(uv_.size()) + " values for " +
                    std::to_string(k) + " corners";
        continue;
      }
      for (size_t c = 2; c < k; ++c) {
        for (size_t corner : {size_t{0}, c - 1, c}) a.corners.push_back(uv_element(&a, uv_[2 * corner], uv_[2 * corner + 1]));
      }
    }
    return Status::Ok();
  }

  int32_t uv_element(AttributeValues* a, double u, double v) {
    UvKey key;
    std::memcpy(&key.u, &u, sizeof(u));
    std::memcpy(&key.v, &v, sizeof(v));
    const auto found = uv_elements_.emplace(key, static_cast<int32_t>(a->values.size() / 2));
    if (found.second) {
      a->values.push_back(u);
      a->values.push_back(v);
    }
    return found.first->second;
  }

  void push(int32_t a, int32_t b, int32_t c) {
    m_.triangles.push_back(a);
    m_.triangles.push_back(b);
    m_.triangles.push_back(c);
  }

  Source& src_;
  const PlyHeader& h_;
  const Roles& roles_;
  const std::string& name_;
  Mesh& m_;
  int64_t nv_ = 0;
  int64_t polygons_ = 0;              // faces of 4 or more corners
  std::vector<AttributeValues> values_;  // per plan
  std::vector<int32_t> polygon_;      // the current face's vertices
  std::vector<double> uv_;            // the current face's texture coordinates
  std::unordered_map<UvKey, int32_t, UvKeyHash> uv_elements_;
};

}  // namespace

Status parse_ply(std::string_view bytes, const std::string& name, Mesh* mesh, MeshReadNotes* notes) {
  PlyHeader h;
  GAB_RETURN_IF_ERROR(mesh_detail::parse_ply_header(bytes, name, &h));
  const std::string_view body = bytes.substr(h.body_offset);
  Roles roles;
  GAB_RETURN_IF_ERROR(plan(h, body.size(), name, &roles));
  MeshReadNotes seen = std::move(h.notes);
  note_skipped(h, roles, &seen);
  Mesh m;
  int64_t polygons = 0;
  if (h.encoding == PlyEncoding::kAscii) {
    AsciiSource src(body, h.body_line, name);
    BodyDecoder<AsciiSource> decoder(&src, h, roles, name, &m);
    GAB_RETURN_IF_ERROR(decoder.run());
    decoder.finish(&seen);
    polygons = decoder.polygons();
  } else {
    BinarySource src(body, h.encoding == PlyEncoding::kBinaryBigEndian, name);
    BodyDecoder<BinarySource> decoder(&src, h, roles, name, &m);
    GAB_RETURN_IF_ERROR(decoder.run());
    decoder.finish(&seen);
    polygons = decoder.polygons();
    // What the header declares is the whole body: more bytes than a line
    // end or blanks mean a header that does not describe the file.
    const std::string_view rest = body.substr(body.size() - src.remaining());
    if (rest.find_first_not_of(" \t\r\n") != std::string_view::npos) {
      return Status::Error(StatusCode::kParseError, name + ": " + std::to_string(rest.size()) +
                                                        " bytes after the last element the header declares");
    }
  }
  seen.drop("polygons", "polygons of 4 or more corners (fan-triangulated)", polygons);
  *mesh = std::move(m);
  if (notes != nullptr) *notes = std::move(seen);
  return Status::Ok();
}

Status read_ply(const std::string& path, Mesh* mesh, MeshReadNotes* notes) {
  std::string bytes;
  GAB_RETURN_IF_ERROR(read_file(path, &bytes));
  return parse_ply(bytes, path, mesh, notes);
}

}  // namespace gab
