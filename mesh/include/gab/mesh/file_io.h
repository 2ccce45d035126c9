// Whole-file reads and atomic writes (temporary file + rename), shared by the
// mesh readers and writers and by anything above that writes output files.
#pragma once

#include <string>
#include <string_view>

#include "gab/status.h"

namespace gab {

// Reads the whole file at `path` into `bytes`. Errors: kIoError naming the
// path and the system's reason. O(file size).
Status read_file(const std::string& path, std::string* bytes);

// Writes `bytes` to `path` atomically: a temporary file in the same folder
// (created exclusively, mode 0666 less the umask), flushed to disk, then
// renamed over `path`. On any failure the temporary is removed and `path` is
// untouched. O(size).
Status write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace gab
