// Status: how every engine routine that can fail reports it. No exceptions
// cross the engine's boundary (it builds with -fno-exceptions); a failure is
// a value carrying a code and a one-line message meant for a human.
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
};

class Status {
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
