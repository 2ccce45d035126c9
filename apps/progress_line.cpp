#include "progress_line.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace gab {
namespace cli {

std::chrono::milliseconds ProgressLine::delay() {
  const char* text = std::getenv("GAB_PROGRESS_DELAY_MS");
  if (text == nullptr || *text == '\0') return std::chrono::milliseconds(1000);
  char* end = nullptr;
  const long ms = std::strtol(text, &end, 10);
  if (*end != '\0' || ms < 0) return std::chrono::milliseconds(1000);
  return std::chrono::milliseconds(ms);
}

ProgressLine::ProgressLine(bool quiet)
    : on_(!quiet && isatty(fileno(stderr)) != 0), start_(std::chrono::steady_clock::now()), delay_(delay()) {}

ProgressLine::~ProgressLine() {
  if (shown_) std::fputc('\n', stderr);
}

void ProgressLine::show(const std::string& text) {
  if (!on_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < delay_) return;
  if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
  // Spaces after the text cover a longer line shown before it.
  std::fprintf(stderr, "\r%s   ", text.c_str());
  std::fflush(stderr);
  shown_ = true;
  last_ = now;
}

}  // namespace cli
}  // namespace gab
