// Whole-file reads and output writes (atomic for regular files), shared by the
// mesh readers and writers and by anything above that writes output files.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gab/status.h"

namespace gab {

// Reads the whole file at `path` into `bytes`. Errors: kIoError naming the
// path and the system's reason. O(file size).
Status read_file(const std::string& path, std::string* bytes);

// Writes `bytes` to the output `path` the way its user means it:
// - a new path or a regular file: atomically. A temporary file beside the
//   target (PATH.gab-partial-PID-N, created exclusively) is renamed over it,
//   keeping a replaced file's permission bits: a reader sees the old file or
//   the new one, and on failure the target is untouched. A file it replaces
//   is flushed to disk first, so that a crash cannot leave a part of it in
//   the old one's place; a new path is not (nothing there to lose, and the
//   flush would cost a decode of a small mesh more than the decode).
// - a symbolic link: followed (a dangling one too); its target is written.
// - anything else that exists (a device such as /dev/null, /dev/stdout, a
//   FIFO): opened and written in place, every write error reported (ENOSPC
//   from /dev/full).
// A directory is refused, and so is a regular file without write permission
// for the caller or with none at all, root included (a read-only file is a
// decision its owner made: make it writable or remove it first).
// Errors: kIoError naming `path` and the reason. O(size).
Status write_output_file(const std::string& path, std::string_view bytes);

// Before the work that makes an output's bytes: whether write_output_file
// can write `path`. kIoError naming `path` when it is a directory, or when
// it is new and its folder does not exist; kInvalidArgument when it is the
// same file as one of `inputs` (writing it would replace that input).
// Descriptors (/dev/stdout, ...) pass. A few stat calls.
Status check_output_file(const std::string& path, const std::vector<std::string>& inputs);

// Removes the temporary files of the writes in progress: for a program's
// SIGINT / SIGTERM handler (the library installs none). Async-signal-safe.
void remove_partial_outputs() noexcept;

}  // namespace gab
