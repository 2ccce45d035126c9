// OFF files (Geomview Object File Format): read and write.
#pragma once

#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_read_notes.h"
#include "gab/status.h"

namespace gab {

// Reads an OFF file, header [ST][C][N][4][n]OFF ('#' comments allowed; nOFF
// only with dimension 3; 4OFF coordinates divided by w). Polygons are
// fan-triangulated; per-vertex or per-face extras (colours, normals, texture
// coordinates) are skipped, and counted in `notes` (when given, on success)
// with the polygons triangulated. Lines end at LF, CRLF or CR. Errors name the file and line: bad header, counts
// the file cannot hold (checked before anything is allocated), indices out of
// range, NaN or infinite coordinates, truncated files, faces with fewer than
// 3 vertices, no vertices or no faces. O(file size).
Status read_off(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Same, from the file's bytes in memory; `name` is used in messages.
Status parse_off(std::string_view text, const std::string& name, Mesh* mesh, MeshReadNotes* notes = nullptr);

// The OFF text of a mesh ("OFF", counts, shortest round-trip coordinates,
// "3 i j k" faces): reading it back gives the same mesh. O(V + T).
std::string format_off(const Mesh& mesh);

// Validates the mesh, then writes format_off(mesh) atomically. O(V + T).
Status write_off(const std::string& path, const Mesh& mesh);

}  // namespace gab
