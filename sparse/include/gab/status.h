// Status: how every gab routine that can fail reports it, in every layer
// (engine, mesh, codec). No exceptions cross the engine's boundary (it builds
// with -fno-exceptions); a failure is a value carrying a code, for programs,
// and a one-line message, for humans. A Status must be looked at: dropping
// one is a compile-time diagnostic ([[nodiscard]]; gab builds with
// -Werror=unused-result).
#pragma once

#include <string>
#include <utility>

namespace gab {

enum class StatusCode {
  kOk = 0,
  kInvalidArgument,     // caller passed something the routine's contract forbids
  kIoError,             // a file could not be opened, read or written
  kParseError,          // a file's content is malformed (message names the line)
  kNotPositiveDefinite, // Cholesky met a non-positive pivot (message names the column)
  kOverflow,            // a count exceeds the int32 index limit
  kOutOfMemory,         // storage for the factor or a workspace could not be had
  kResourceExhausted,   // the work would exceed a limit the caller set (e.g. a decoder's
                        // max_factor_entries): the input may be fine, the limit refused it
  kUnsupported,         // well-formed input this build cannot read (a newer format
                        // version or an unknown format flag)
};

class [[nodiscard]] Status {
 public:
  Status() = default;  // ok
  static Status Ok() { return Status(); }
  static Status Error(StatusCode code, std::string message) {
    Status s;
    s.code_ = code;
    s.message_ = std::move(message);
    return s;
  }

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
};

}  // namespace gab

// Propagates a failed Status to the caller.
#define GAB_RETURN_IF_ERROR(expr)        \
  do {                                   \
    ::gab::Status gab_status_ = (expr);  \
    if (!gab_status_.ok()) return gab_status_; \
  } while (0)
