// PLY files (Turk's Polygon File Format): read and write, ASCII and binary.
#pragma once

#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_read_notes.h"
#include "gab/mesh/mesh_write_notes.h"
#include "gab/status.h"

namespace gab {

enum class PlyEncoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct PlyWriteOptions {
  PlyEncoding encoding = PlyEncoding::kBinaryLittleEndian;
  bool float32 = false;  // coordinates as float (smaller, rounded) instead of double (exact)
};

// Reads a PLY file: ASCII or binary of either byte order; x y z of element
// `vertex` (any scalar type), the `vertex_indices` (or `vertex_index`) list of
// element `face` (any list count and index types; polygons fan-triangulated)
// and of element `tristrips` (-1 restarts strips; strips alternate
// orientation; their zero-area stitching triangles are dropped). The other
// vertex properties become per-vertex attributes with their types: `nx ny
// nz` normals; texture coordinates `s t`, `u v`, `texture_u texture_v
// [texture_w]` or `texture_s texture_t`; colours `red green blue [alpha]`,
// `r g b [a]` or `diffuse_red diffuse_green diffuse_blue [diffuse_alpha]`
// (uchar values 0..255, float ones as given); every other scalar property
// a generic attribute of 1 component under its name, a list property of 1
// to 4 items per vertex a generic of as many. A face list `texcoord` (u v
// per corner, as MeshLab writes) becomes per-corner texture coordinates,
// equal pairs sharing an element. The mesh gets them in the order normals,
// texture coordinates, colours, generics. Text (ASCII) values of a float property
// are rounded to float. An attribute with a value it cannot keep (not
// finite, beyond its type, a list of varying length) is dropped, and so are
// properties past kMaxMeshAttributes attributes and names an attribute
// cannot have (MeshAttribute's). Other properties and elements are skipped.
// What was dropped or skipped is counted in `notes` when given (on
// success), with the polygons triangulated; header lines end at LF, CRLF or
// CR, and a line with an unknown keyword is skipped with a warning there.
// Errors name the file and the line
// (header, ASCII body) or the element and its index (binary body): counts the
// file cannot hold (checked before anything is allocated), indices out of
// range, NaN or infinite coordinates, malformed values, truncation, faces
// with fewer than 3 vertices, no vertices or no faces. O(file size).
Status read_ply(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Same, from the file's bytes in memory; `name` is used in messages.
Status parse_ply(std::string_view bytes, const std::string& name, Mesh* mesh, MeshReadNotes* notes = nullptr);

// The PLY bytes of a mesh: element vertex (x y z as double or float, then
// the attributes as properties in their own types, in this order: normals `nx ny nz`,
// texture coordinates `s t` (3 components: `texture_u texture_v
// texture_w`), colours `red green blue [alpha]`, generics by name, one of 2
// to 4 components as a `list uchar TYPE NAME` of that many), element face
// (list uchar int vertex_indices). Per-corner attributes are split at their
// seams first (split_attribute_seams). A generic takes its name first; a
// common kind whose names a generic has takes the reader's next spelling
// (`u v`, `r g b`, ...). What is not written (a second attribute of a kind,
// a second generic of a name, a kind whose every spelling generics have) is
// named in `notes` (when given), with the vertices split. Float32 values are
// written with 9 significant digits in ASCII: reading the bytes back gives
// the same values. O(V + T + attribute values).
std::string format_ply(const Mesh& mesh, const PlyWriteOptions& options = PlyWriteOptions(),
                       MeshWriteNotes* notes = nullptr);

// Validates the mesh (and that float32 data fits a float), then writes
// format_ply(mesh, options) atomically; `notes` as format_ply's, on
// success. O(V + T + attribute values).
Status write_ply(const std::string& path, const Mesh& mesh, const PlyWriteOptions& options = PlyWriteOptions(),
                 MeshWriteNotes* notes = nullptr);

}  // namespace gab
