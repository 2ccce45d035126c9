// Format dispatch. Extensions pick the parser; a cheap look at the first
// bytes catches a file with the wrong extension before its parser produces a
// confusing message about some later line.
#include "gab/mesh/mesh_io.h"

#include <cctype>

#include "gab/mesh/file_io.h"
#include "gab/mesh/obj_io.h"
#include "gab/mesh/off_io.h"
#include "text_scanner.h"

namespace gab {

namespace {

const char* format_name(MeshFormat f) {
  switch (f) {
    case MeshFormat::kObj: return "OBJ";
    case MeshFormat::kOff: return "OFF";
    case MeshFormat::kPly: return "PLY";
  }
  return "?";
}

// First word of the text after blanks, a BOM and '#' comment lines.
std::string_view first_word(std::string_view bytes) {
  size_t i = mesh_detail::bom_length(bytes);
  for (;;) {
    while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
    if (i < bytes.size() && bytes[i] == '#') {
      while (i < bytes.size() && bytes[i] != '\n' && bytes[i] != '\r') ++i;
      continue;
    }
    break;
  }
  size_t end = i;
  while (end < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[end])) && end - i < 16) ++end;
  return bytes.substr(i, end - i);
}

bool looks_like_off(std::string_view word) {
  return word.size() >= 3 && word.size() <= 8 && word.substr(word.size() - 3) == "OFF";
}

bool looks_binary(std::string_view bytes) {
  const std::string_view head = bytes.substr(0, 4096);
  for (char c : head) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u == 0 || (u < 0x20 && u != '\n' && u != '\r' && u != '\t' && u != '\f' && u != '\v')) return true;
  }
  return false;
}

// What the content looks like, for the message when it is not `expected`.
std::string guess(std::string_view bytes) {
  if (bytes.substr(mesh_detail::bom_length(bytes), 3) == "ply") return "it looks like PLY";
  if (looks_like_off(first_word(bytes))) return "it looks like OFF";
  if (first_word(bytes) == "solid") return "it looks like ASCII STL";
  if (looks_binary(bytes)) return "it looks like binary data";
  return "its first word is '" + mesh_detail::printable(first_word(bytes)) + "'";
}

Status check_content(std::string_view bytes, MeshFormat format, const std::string& name) {
  bool ok = true;
  switch (format) {
    case MeshFormat::kPly: {
      const std::string_view head = bytes.substr(mesh_detail::bom_length(bytes), 4);
      ok = head == "ply\n" || head == "ply\r";
      break;
    }
    case MeshFormat::kOff:
      ok = looks_like_off(first_word(bytes));
      break;
    case MeshFormat::kObj:
      // OBJ has no magic: refuse what is clearly another format or binary.
      ok = !looks_binary(bytes) && bytes.substr(mesh_detail::bom_length(bytes), 3) != "ply" &&
           !looks_like_off(first_word(bytes)) && first_word(bytes) != "solid";
      break;
  }
  // Blank text is left to the parser, which says "empty" in its own words.
  if (ok || (first_word(bytes).empty() && !looks_binary(bytes))) return Status::Ok();
  return Status::Error(StatusCode::kParseError,
                       name + ": not " + (format == MeshFormat::kPly ? "a " : "an ") + format_name(format) +
                           " file (" + guess(bytes) + ")");
}

}  // namespace

Status mesh_format_from_path(const std::string& path, MeshFormat* format) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  std::string ext;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "obj") {
    *format = MeshFormat::kObj;
  } else if (ext == "off") {
    *format = MeshFormat::kOff;
  } else if (ext == "ply") {
    *format = MeshFormat::kPly;
  } else {
    return Status::Error(StatusCode::kInvalidArgument,
                         path + ": unsupported mesh type '" + (ext.empty() ? std::string("(no extension)") : "." + ext) +
                             "' (expected .obj, .off or .ply)");
  }
  return Status::Ok();
}

Status parse_mesh(std::string_view bytes, MeshFormat format, const std::string& name, Mesh* mesh,
                  MeshReadNotes* notes) {
  GAB_RETURN_IF_ERROR(check_content(bytes, format, name));
  switch (format) {
    case MeshFormat::kObj: return parse_obj(bytes, name, mesh, notes);
    case MeshFormat::kOff: return parse_off(bytes, name, mesh, notes);
    case MeshFormat::kPly: return parse_ply(bytes, name, mesh, notes);
  }
  return Status::Error(StatusCode::kInvalidArgument, name + ": unknown mesh format");
}

Status read_mesh(const std::string& path, Mesh* mesh, MeshReadNotes* notes) {
  MeshFormat format;
  GAB_RETURN_IF_ERROR(mesh_format_from_path(path, &format));
  std::string bytes;
  GAB_RETURN_IF_ERROR(read_file(path, &bytes));
  return parse_mesh(bytes, format, path, mesh, notes);
}

Status write_mesh(const std::string& path, const Mesh& mesh, const PlyWriteOptions& ply, MeshWriteNotes* notes) {
  MeshFormat format;
  GAB_RETURN_IF_ERROR(mesh_format_from_path(path, &format));
  switch (format) {
    case MeshFormat::kObj: return write_obj(path, mesh, notes);
    case MeshFormat::kOff: return write_off(path, mesh, notes);
    case MeshFormat::kPly: return write_ply(path, mesh, ply, notes);
  }
  return Status::Error(StatusCode::kInvalidArgument, path + ": unknown mesh format");
}

}  // namespace gab
