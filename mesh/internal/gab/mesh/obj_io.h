// Wavefront OBJ files: read (through tinyobjloader) and write.
#pragma once

#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_read_notes.h"
#include "gab/mesh/mesh_write_notes.h"
#include "gab/status.h"

namespace gab {

// Reads an OBJ file: `v` records (positions), `f` records (1-based or
// negative relative indices, v/vt/vn triples; polygons fan-triangulated,
// each triangle's corners keeping their polygon corners' vt and vn) and the
// attributes they refer to:
// - `vn` records as a per-corner kNormal attribute and `vt` records as a
//   per-corner kTexCoord (u v; u v w when some w is not 0), indexed by the
//   faces' vt and vn parts. Every record is kept, whether a face refers to it
//   or not, in file order. When some faces have the index and others do not,
//   the others' corners refer to one element added after the file's, all
//   zeros, and a warning says so; when no face has it, the records are noted
//   as dropped.
// - `v x y z r g b` colours as a per-vertex kColor (3 components) when
//   every vertex has them; else noted as dropped.
// Their values are the decimals rounded to float (kFloat32), or as read
// (kFloat64) when one is beyond float's range; an attribute with a value
// that is not finite is noted as dropped instead. Other records and .mtl
// libraries are ignored, and counted in `notes` when given, on success: vp,
// vertex weights (v x y z w), polygons, l, p, g, o, s, mtllib, usemtl,
// others. Lines end at LF, CRLF or CR, as tinyobjloader splits them. Errors
// name the file and line: malformed or non-finite coordinates, missing
// ones, malformed attribute values, bad or out-of-range indices (v, vt or
// vn), index 0, faces with fewer than 3 vertices, no vertices or no faces.
// Coordinates are tinyobjloader's parse, which may differ from the decimal
// in the last bits. O(file size).
Status read_obj(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Same, from the file's bytes in memory; `name` is used in messages.
Status parse_obj(std::string_view text, const std::string& name, Mesh* mesh, MeshReadNotes* notes = nullptr);

// The OBJ text of a mesh: "v x y z [r g b]" (shortest round-trip decimals
// for positions), "vt", "vn", and "f v[/vt][/vn]" (1-based) lines. The
// first attribute of each kind is written: texture coordinates and normals
// per corner as they are (per vertex: one record per vertex, indexed as the
// vertex), colours on the `v` lines as fractions (an integer type over its
// largest value: uchar 255 -> 1); per-corner colours are split at their
// seams first (split_attribute_seams). What OBJ cannot hold (generic
// attributes, a second attribute of a kind, colour alpha) is not written
// and named in `notes` (when given), with the vertices split. Float32
// values are written with 9 significant digits and read back exactly;
// float64 ones are written in full, and read back as floats (the reader's
// type for OBJ text) unless one is beyond float's range. O(V + T +
// attribute values).
std::string format_obj(const Mesh& mesh, MeshWriteNotes* notes = nullptr);

// Validates the mesh, then writes format_obj(mesh) atomically; `notes` as
// format_obj's, on success. O(V + T + attribute values).
Status write_obj(const std::string& path, const Mesh& mesh, MeshWriteNotes* notes = nullptr);

}  // namespace gab
