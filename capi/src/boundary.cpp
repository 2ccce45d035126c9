// Status codes and messages at the C boundary (boundary.h).
#include "boundary.h"

#include <cstdio>

namespace gab {
namespace capi {

int error_code(StatusCode code) {
  switch (code) {
    case StatusCode::kOk: return GAB_OK;
    case StatusCode::kInvalidArgument: return GAB_E_INVALID_ARGUMENT;
    case StatusCode::kIoError: return GAB_E_IO;
    case StatusCode::kParseError: return GAB_E_PARSE;
    case StatusCode::kNotPositiveDefinite: return GAB_E_NOT_POSITIVE_DEFINITE;
    case StatusCode::kOverflow: return GAB_E_OVERFLOW;
    case StatusCode::kOutOfMemory: return GAB_E_OUT_OF_MEMORY;
    case StatusCode::kResourceExhausted: return GAB_E_RESOURCE_EXHAUSTED;
    case StatusCode::kUnsupported: return GAB_E_UNSUPPORTED;
  }
  return GAB_E_INTERNAL;  // a code added to status.h and not mapped here
}

void write_message(const char* function, const char* text, char* message, size_t size) {
  if (message == nullptr || size == 0) return;
  if (text[0] == '\0') {
    message[0] = '\0';
  } else {
    std::snprintf(message, size, "%s: %s", function, text);
  }
}

Status invalid(const std::string& what) { return Status::Error(StatusCode::kInvalidArgument, what); }

Status require(bool ok, const std::string& what) { return ok ? Status::Ok() : invalid(what); }

int report(const char* function, const Status& status, char* message, size_t size) {
  write_message(function, status.ok() ? "" : status.message().c_str(), message, size);
  return error_code(status.code());
}

}  // namespace capi
}  // namespace gab

extern "C" const char* gab_error_name(int code) {
  switch (code) {
    case GAB_OK: return "GAB_OK";
    case GAB_E_INVALID_ARGUMENT: return "GAB_E_INVALID_ARGUMENT";
    case GAB_E_IO: return "GAB_E_IO";
    case GAB_E_PARSE: return "GAB_E_PARSE";
    case GAB_E_NOT_POSITIVE_DEFINITE: return "GAB_E_NOT_POSITIVE_DEFINITE";
    case GAB_E_OVERFLOW: return "GAB_E_OVERFLOW";
    case GAB_E_OUT_OF_MEMORY: return "GAB_E_OUT_OF_MEMORY";
    case GAB_E_RESOURCE_EXHAUSTED: return "GAB_E_RESOURCE_EXHAUSTED";
    case GAB_E_UNSUPPORTED: return "GAB_E_UNSUPPORTED";
    case GAB_E_STATE: return "GAB_E_STATE";
    case GAB_E_INTERNAL: return "GAB_E_INTERNAL";
  }
  return "GAB_E_UNKNOWN";
}
