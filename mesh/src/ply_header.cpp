// PLY header: "ply", "format <ascii|binary_little_endian|binary_big_endian>
// 1.0", then element / property / comment / obj_info lines, "end_header"
// (Greg Turk, "The PLY Polygon File Format", 1994). Lines are read one at a
// time. They end at LF, CRLF or CR, as the first line's end says: a binary
// body may begin with byte 0x0A, so after "end_header\r" of a CR file that
// byte is the body's, not the rest of a CRLF. Lines with an unknown keyword
// (exporters write "Created by ...") are skipped with a warning.
#include "ply_header.h"

#include <set>

#include "text_scanner.h"

namespace gab {
namespace mesh_detail {

namespace {

bool parse_type(std::string_view word, PlyType* type) {
  static const struct {
    const char* name;
    PlyType type;
  } kTypes[] = {{"char", PlyType::kInt8},     {"int8", PlyType::kInt8},     {"uchar", PlyType::kUint8},
                {"uint8", PlyType::kUint8},   {"short", PlyType::kInt16},   {"int16", PlyType::kInt16},
                {"ushort", PlyType::kUint16}, {"uint16", PlyType::kUint16}, {"int", PlyType::kInt32},
                {"int32", PlyType::kInt32},   {"uint", PlyType::kUint32},   {"uint32", PlyType::kUint32},
                {"float", PlyType::kFloat32}, {"float32", PlyType::kFloat32}, {"double", PlyType::kFloat64},
                {"float64", PlyType::kFloat64}};
  for (const auto& t : kTypes) {
    if (word == t.name) {
      *type = t.type;
      return true;
    }
  }
  return false;
}

// Splits a header line into words separated by blanks.
std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

}  // namespace

int ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 0;
}

bool ply_type_is_integral(PlyType type) { return type != PlyType::kFloat32 && type != PlyType::kFloat64; }

int PlyElement::find(std::string_view property) const {
  for (size_t i = 0; i < properties.size(); ++i) {
    if (properties[i].name == property) return static_cast<int>(i);
  }
  return -1;
}

Status parse_ply_header(std::string_view bytes, const std::string& name, PlyHeader* header) {
  PlyHeader h;
  size_t pos = bom_length(bytes);
  int64_t line_no = 0;
  bool have_format = false;
  bool cr_lines = false;  // the first line ended with a lone '\r'
  // Names seen, to reject duplicates in O(log) each (a hostile header may
  // declare millions). Views point into `bytes`.
  std::set<std::string_view> element_names;
  std::set<std::pair<size_t, std::string_view>> property_names;
  auto error = [&name, &line_no](const std::string& what) {
    return Status::Error(StatusCode::kParseError, name + ":" + std::to_string(line_no) + ": " + what);
  };
  for (;;) {
    if (pos >= bytes.size()) {
      ++line_no;
      if (line_no == 1) return error("empty file, expected a PLY header");
      return error("truncated header: no end_header line");
    }
    const size_t eol = bytes.find_first_of("\r\n", pos);
    const std::string_view line = bytes.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos);
    const bool crlf = eol != std::string_view::npos && bytes[eol] == '\r' && eol + 1 < bytes.size() && bytes[eol + 1] == '\n';
    pos = eol == std::string_view::npos ? bytes.size() : eol + (crlf && !cr_lines ? 2 : 1);
    ++line_no;
    if (line_no == 1) {
      if (line != "ply") return error("not a PLY file (first line '" + printable(line) + "', expected 'ply')");
      cr_lines = eol != std::string_view::npos && bytes[eol] == '\r' && !crlf;
      continue;
    }
    const std::vector<std::string_view> w = split_words(line);
    if (w.empty()) continue;
    const std::string_view key = w[0];
    if (key == "comment" || key == "obj_info") continue;
    if (key == "format") {
      if (have_format) return error("second format line");
      if (w.size() != 3) return error("format line needs an encoding and a version");
      if (w[1] == "ascii") {
        h.encoding = PlyEncoding::kAscii;
      } else if (w[1] == "binary_little_endian") {
        h.encoding = PlyEncoding::kBinaryLittleEndian;
      } else if (w[1] == "binary_big_endian") {
        h.encoding = PlyEncoding::kBinaryBigEndian;
      } else {
        return error("unknown PLY format '" + printable(w[1]) + "'");
      }
      if (w[2] != "1.0" && w[2] != "1") return error("unsupported PLY version '" + printable(w[2]) + "'");
      have_format = true;
    } else if (key == "element") {
      if (w.size() != 3) return error("element line needs a name and a count");
      PlyElement e;
      e.name = std::string(w[1]);
      e.line = line_no;
      if (!parse_int(w[2], &e.count) || e.count < 0) {
        return error("bad count '" + printable(w[2]) + "' for element '" + printable(w[1]) + "'");
      }
      if (!element_names.insert(w[1]).second) return error("element '" + printable(w[1]) + "' declared twice");
      h.elements.push_back(std::move(e));
    } else if (key == "property") {
      if (h.elements.empty()) return error("property before any element");
      PlyProperty p;
      size_t type_word = 1;
      if (w.size() >= 2 && w[1] == "list") {
        if (w.size() != 5) return error("list property needs a count type, an item type and a name");
        p.is_list = true;
        if (!parse_type(w[2], &p.count_type)) return error("unknown property type '" + printable(w[2]) + "'");
        if (!ply_type_is_integral(p.count_type)) {
          return error("list count type '" + printable(w[2]) + "' is not an integer type");
        }
        type_word = 3;
      } else if (w.size() != 3) {
        return error("property line needs a type and a name");
      }
      if (!parse_type(w[type_word], &p.type)) return error("unknown property type '" + printable(w[type_word]) + "'");
      p.name = std::string(w[type_word + 1]);
      PlyElement& e = h.elements.back();
      if (!property_names.insert({h.elements.size(), w[type_word + 1]}).second) return error("property '" + printable(p.name) + "' declared twice in element '" + printable(e.name) + "'");
      e.properties.push_back(std::move(p));
    } else if (key == "end_header") {
      if (!have_format) return error("end_header before any format line");
      h.body_offset = pos;
      h.body_line = line_no + 1;
      break;
    } else {
      h.notes.warn(name + ":" + std::to_string(line_no) + ": unknown header line '" + printable(line) + "' skipped");
    }
  }
  *header = std::move(h);
  return Status::Ok();
}

}  // namespace mesh_detail
}  // namespace gab
