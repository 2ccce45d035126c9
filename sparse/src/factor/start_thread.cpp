#include "factor/start_thread.h"

#include <system_error>
#include <utility>

namespace gab {

bool try_start_thread(std::thread* t, std::function<void()> fn) {
#if defined(__cpp_exceptions)
  try {
    *t = std::thread(std::move(fn));
    return true;
  } catch (const std::system_error&) {
    return false;
  }
#else
  *t = std::thread(std::move(fn));  // built without exceptions: a refusal ends the process
  return true;
#endif
}

}  // namespace gab
