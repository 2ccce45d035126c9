// Status codes and messages at the C boundary (boundary.h).
#include "boundary.h"

#include <algorithm>
#include <cstdio>
#include <thread>

#include "gab/sparse/symbolic.h"

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

Status options_threads(int32_t given, int32_t* threads) {
  GAB_RETURN_IF_ERROR(require(given >= 0 && given <= kMaxFactorThreads,
                              "options->threads is " + std::to_string(given) + ": must be in 0.." +
                                  std::to_string(kMaxFactorThreads) + " (0: every core)"));
  const unsigned cores = std::thread::hardware_concurrency();
  *threads = given > 0 ? given : static_cast<int32_t>(std::min<unsigned>(std::max(1u, cores), kMaxFactorThreads));
  return Status::Ok();
}

Status check_options_size(const void* options, size_t size, size_t known, const char* init) {
  GAB_RETURN_IF_ERROR(
      require(size >= sizeof(size_t), "options->size is " + std::to_string(size) + ": set it with " + init));
  const unsigned char* bytes = static_cast<const unsigned char*>(options);
  for (size_t i = known; i < size; ++i) {
    if (bytes[i] != 0) {
      return Status::Error(StatusCode::kUnsupported, "options->size is " + std::to_string(size) + " and byte " +
                                                         std::to_string(i) + " is set: gab " GAB_VERSION_STRING
                                                         " knows " + std::to_string(known) + " bytes of options");
    }
  }
  return Status::Ok();
}

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
    case GAB_W_TRUNCATED: return "GAB_W_TRUNCATED";
  }
  return "GAB_E_UNKNOWN";
}
