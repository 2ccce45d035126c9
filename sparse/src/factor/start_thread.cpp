#include "factor/start_thread.h"

#include <system_error>
#include <utility>

namespace gab {

bool try_start_thread(std::thread* t, std::function<void()> fn) {
  try {
    *t = std::thread(std::move(fn));
    return true;
  } catch (const std::system_error&) {
    return false;
  }
}

}  // namespace gab
