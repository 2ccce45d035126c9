// OFF files (Geomview Object File Format): read and write.
#pragma once

#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_read_notes.h"
#include "gab/mesh/mesh_write_notes.h"
#include "gab/status.h"

namespace gab {

// Reads an OFF file, header [ST][C][N][4][n]OFF ('#' comments allowed; nOFF
// only with dimension 3, others refused; 4OFF coordinates divided by w).
// The prefixes' per-vertex data, on each vertex's line after its
// coordinates in the order [nx ny nz] [r g b [a]] [s t], is kept as
// per-vertex attributes: N as kNormal, C as kColor (3 or 4 values, the same
// on every line), ST as kTexCoord (2 components). Colours are kUint8 when
// every colour value of the file is an integer 0..255 and some is above 1,
// else fractions (Geomview reads a colour none of whose values is above 1
// as fractions). Fractional values are rounded to float (kFloat32), or kept
// as read (kFloat64) when one is beyond float's range; an attribute with a
// value that is not finite is noted as dropped instead. Polygons are
// fan-triangulated; a face's colour after its indices is skipped, and
// counted in `notes` (when given, on success) with the polygons
// triangulated. Lines end at LF, CRLF or CR. Errors name the file and line:
// bad header, counts the file cannot hold (checked before anything is
// allocated), a vertex line with too few or too many values for its prefixes
// or a bad one, indices out of range, NaN or infinite coordinates, truncated
// files, faces with fewer than 3 vertices, no vertices or no faces. O(file
// size).
Status read_off(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Same, from the file's bytes in memory; `name` is used in messages.
Status parse_off(std::string_view text, const std::string& name, Mesh* mesh, MeshReadNotes* notes = nullptr);

// The OFF text of a mesh: the header with the prefixes of what it holds
// ("OFF", "NOFF", "STCNOFF", ...), counts, each vertex's line (shortest
// round-trip coordinates, then the first normal, colour and texture
// coordinate attributes: float32 values with 9 significant digits, uchar
// colours as integers 0..255 when one is above 1, other colours as
// fractions with a decimal point), "3 i j k" faces: reading it back gives
// the same mesh (float64 attribute values come back as floats, the reader's
// type for OFF text, unless one is beyond float's range). Per-corner
// attributes are split at their seams first
// (split_attribute_seams); what OFF cannot hold (generic attributes, a
// second attribute of a kind, texture coordinates' w) is not written, and
// named in `notes` (when given) with the vertices split. O(V + T +
// attribute values).
std::string format_off(const Mesh& mesh, MeshWriteNotes* notes = nullptr);

// Validates the mesh, then writes format_off(mesh) atomically; `notes` as
// format_off's, on success. O(V + T + attribute values).
Status write_off(const std::string& path, const Mesh& mesh, MeshWriteNotes* notes = nullptr);

}  // namespace gab
