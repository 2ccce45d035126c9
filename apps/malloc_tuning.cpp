#include "malloc_tuning.h"

#include <cstdlib>
#include <cstring>
#include <string>

#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

namespace gab {
namespace cli {

void tune_malloc(char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
  static const char* const kSettings[][2] = {{"glibc.malloc.hugetlb", "1"},
                                             {"glibc.malloc.mmap_threshold", "33554432"}};
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::string value = tunables != nullptr ? tunables : "";
  bool added = false;
  for (const auto& setting : kSettings) {
    if (std::strstr(value.c_str(), setting[0]) != nullptr) continue;
    value += std::string(value.empty() ? "" : ":") + setting[0] + "=" + setting[1];
    added = true;
  }
  if (!added || setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Not re-executed (no /proc, say): carry on with glibc's defaults, and do
  // not leave the variable to a child that did not ask for it.
  if (tunables != nullptr) {
    setenv("GLIBC_TUNABLES", tunables, 1);
  } else {
    unsetenv("GLIBC_TUNABLES");
  }
#else
  (void)argv;
#endif
}

}  // namespace cli
}  // namespace gab
