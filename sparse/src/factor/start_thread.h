// Starting a thread without the risk of std::terminate: under an
// address-space cap (ulimit -v) the system may refuse one (each stack is
// mapped), and std::thread reports that by throwing, which the engine
// (built without exceptions) could not catch. The callers then do the work
// on fewer threads, which never changes a result.
#pragma once

#include <functional>
#include <thread>

namespace gab {

// Starts fn on a new thread held by *t; false (and *t not joinable) when
// the system refuses one. Built with exceptions (sparse/CMakeLists.txt).
bool try_start_thread(std::thread* t, std::function<void()> fn);

}  // namespace gab
