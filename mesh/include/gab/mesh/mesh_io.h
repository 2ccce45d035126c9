// One entry point for mesh files: the format is chosen by the extension
// (.obj, .off, .ply, any case) and the content is checked against it.
#pragma once

#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_read_notes.h"
#include "gab/mesh/ply_io.h"
#include "gab/status.h"

namespace gab {

enum class MeshFormat { kObj, kOff, kPly };

// The format named by a path's extension; kInvalidArgument naming the path
// and the supported extensions otherwise. O(path).
Status mesh_format_from_path(const std::string& path, MeshFormat* format);

// Reads the file at `path` in the format its extension names, after checking
// that the content looks like that format (a ".ply" that is not PLY is an
// error saying what it looks like). On success, `notes` (when given) says
// what the file held that `mesh` does not carry (normals, texture
// coordinates, colours, materials, groups, lines, points, polygons'
// arity, other PLY properties and elements: mesh_read_notes.h) and what the
// reader forgave. Text lines end at LF, CRLF or CR. O(file size).
Status read_mesh(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Same, from bytes in memory in a given format; `name` is used in messages.
Status parse_mesh(std::string_view bytes, MeshFormat format, const std::string& name, Mesh* mesh,
                  MeshReadNotes* notes = nullptr);

// Writes `mesh` atomically in the format of the path's extension; `ply`
// chooses PLY's encoding and coordinate type. O(V + T).
Status write_mesh(const std::string& path, const Mesh& mesh, const PlyWriteOptions& ply = PlyWriteOptions());

}  // namespace gab
