// One entry point for mesh files: the format is chosen by the extension
// (.obj, .off, .ply, any case) and the content is checked against it.
#pragma once

#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_read_notes.h"
#include "gab/mesh/mesh_write_notes.h"
#include "gab/mesh/ply_io.h"
#include "gab/status.h"

namespace gab {

enum class MeshFormat { kObj, kOff, kPly };

// The format named by a path's extension; kInvalidArgument naming the path
// and the supported extensions otherwise. O(path).
Status mesh_format_from_path(const std::string& path, MeshFormat* format);

// Reads the file at `path` in the format its extension names, after checking
// that the content looks like that format (a ".ply" that is not PLY is an
// error saying what it looks like). `mesh` gets the positions, the
// triangles (polygons fan-triangulated) and the attributes the format
// holds: normals, texture coordinates and colours, per vertex or (OBJ) per
// corner, and PLY's other per-vertex properties as named generic
// attributes (obj_io.h, off_io.h, ply_io.h say how each format's are
// read). On success, `notes` (when given) says what the file held that
// `mesh` does not carry (materials, groups, lines, points, polygons' arity,
// per-face data, other PLY elements, attributes past kMaxMeshAttributes or
// with values that are not finite: mesh_read_notes.h) and what the reader
// forgave. Text lines end at LF, CRLF or CR. O(file size).
Status read_mesh(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Same, from bytes in memory in a given format; `name` is used in messages.
Status parse_mesh(std::string_view bytes, MeshFormat format, const std::string& name, Mesh* mesh,
                  MeshReadNotes* notes = nullptr);

// Writes `mesh` atomically in the format of the path's extension, with the
// attributes the format holds; `ply` chooses PLY's encoding and coordinate
// type. Per-corner attributes go to OBJ as they are; PLY and OFF hold one
// value per vertex, so vertices where they have seams are split
// (split_attribute_seams). On success `notes` (when given) names what the
// format could not hold (generic attributes in OBJ and OFF, a second
// attribute of a kind, ...) and counts the vertices split. O(V + T +
// attribute values).
Status write_mesh(const std::string& path, const Mesh& mesh, const PlyWriteOptions& ply = PlyWriteOptions(),
                  MeshWriteNotes* notes = nullptr);

}  // namespace gab
