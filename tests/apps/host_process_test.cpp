// The tool is the process its user started: it tunes malloc in place
// (malloc_tuning.h) rather than re-executing itself, which would surprise
// gdb, strace and valgrind users (a second execve, a changed environment).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/scratch_files.h"
#include "run_gab.h"

namespace gab_test {
namespace {

// Lines of an strace -o log that record an execve.
int execve_count(const std::string& log) {
  int count = 0;
  for (size_t at = log.find("execve("); at != std::string::npos; at = log.find("execve(", at + 1)) ++count;
  return count;
}

TEST(HostProcessTest, TheToolExecutesOnce) {
  if (std::system("strace -V >/dev/null 2>&1") != 0) GTEST_SKIP() << "no strace on this machine";
  const std::string log = scratch_path("execve_trace.txt");
  // main tunes malloc before it dispatches: any command shows it.
  const CommandResult r = run_gab("--version", "strace -f -qq -e trace=execve -o " + log);
  if (r.exit_code != 0 && r.err.find("ptrace") != std::string::npos) GTEST_SKIP() << "strace cannot trace here";
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string trace = read_file(log);
  EXPECT_EQ(execve_count(trace), 1) << trace;  // strace's own, of the binary named
  std::remove(log.c_str());
}

}  // namespace
}  // namespace gab_test
