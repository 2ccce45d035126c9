// The progress line of a long command: one line on stderr, rewritten in
// place, for a person watching a terminal. It appears only once the work
// has run for a while (quick work would only flash it) and only when stderr
// is a terminal (a log or a pipe gets the result alone); --quiet silences
// it.
#pragma once

#include <chrono>
#include <string>

namespace gab {
namespace cli {

class ProgressLine {
 public:
  // How long the work runs before the line appears: 1 s, or
  // GAB_PROGRESS_DELAY_MS milliseconds from the environment.
  static std::chrono::milliseconds delay();

  // On when stderr is a terminal and not `quiet`.
  explicit ProgressLine(bool quiet);
  ~ProgressLine();  // ends the line, if one was shown
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool on() const { return on_; }
  // Shows `text` in place of the line's last text, once delay() has passed
  // since construction, at most ten times a second.
  void show(const std::string& text);

 private:
  bool on_ = false, shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
  std::chrono::milliseconds delay_;
};

}  // namespace cli
}  // namespace gab
