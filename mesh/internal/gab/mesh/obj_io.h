// Wavefront OBJ files: read (through tinyobjloader) and write.
#pragma once

#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_read_notes.h"
#include "gab/status.h"

namespace gab {

// Reads the `v` and `f` records of an OBJ file (1-based or negative relative
// indices; v/vt/vn triples use the v part; polygons fan-triangulated; other
// records and .mtl libraries ignored, and counted in `notes` when given, on
// success: vn, vt, vp, vertex colours, faces' vt/vn indices, polygons, l, p,
// g, o, s, mtllib, usemtl, others). Lines end at LF, CRLF or CR, as
// tinyobjloader splits them. Errors name the file and line:
// malformed or non-finite coordinates, missing ones, bad or out-of-range
// indices, faces with fewer than 3 vertices, no vertices or no faces.
// Coordinates are tinyobjloader's parse, which may differ from the decimal in
// the last bits. O(file size).
Status read_obj(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Same, from the file's bytes in memory; `name` is used in messages.
Status parse_obj(std::string_view text, const std::string& name, Mesh* mesh, MeshReadNotes* notes = nullptr);

// The OBJ text of a mesh: "v x y z" (shortest round-trip decimals) and
// "f i j k" (1-based) lines. O(V + T).
std::string format_obj(const Mesh& mesh);

// Validates the mesh, then writes format_obj(mesh) atomically. O(V + T).
Status write_obj(const std::string& path, const Mesh& mesh);

}  // namespace gab
