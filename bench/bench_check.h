// A benchmark that measured a failed call would print wrong figures: every
// gab call a benchmark makes goes through check(), which stops the program
// with the failure's message instead.
#pragma once

#include <cstdio>
#include <cstdlib>

#include "gab/status.h"

namespace gab_bench {

inline void check(const gab::Status& s, const char* what) {
  if (s.ok()) return;
  std::fprintf(stderr, "%s: %s\n", what, s.message().c_str());
  std::exit(1);
}

}  // namespace gab_bench
