// Running the gab binary from a test: exit code, stdout and stderr apart.
#pragma once

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "common/scratch_files.h"

namespace gab_test {

struct CommandResult {
  int exit_code;
  std::string out;
  std::string err;
};

// Runs `gab ARGS`, after the shell text `prefix` (e.g. "VAR=value" or
// "cd DIR &&"). stderr goes through a file unique per process and call
// (ctest runs the tests in parallel).
inline CommandResult run_gab(const std::string& args, const std::string& prefix = "") {
  static int calls = 0;
  const std::string err_path = scratch_path("stderr_" + std::to_string(++calls) + ".txt");
  const std::string cmd = (prefix.empty() ? "" : prefix + " ") + std::string(GAB_BINARY) + " " + args + " 2>" + err_path;
  CommandResult r{-1, "", ""};
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return r;
  char buf[4096];
  size_t got;
  while ((got = fread(buf, 1, sizeof(buf), p)) > 0) r.out.append(buf, got);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_file(err_path);
  std::remove(err_path.c_str());
  return r;
}

// The value of "key" in a one-line JSON object; NaN if absent or null.
inline double json_number(const std::string& json, const std::string& key) {
  const size_t at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return std::nan("");
  const std::string rest = json.substr(at + key.size() + 4);
  if (rest.rfind("null", 0) == 0) return std::nan("");
  return std::stod(rest);
}
inline bool json_null(const std::string& json, const std::string& key) {
  return json.find("\"" + key + "\": null") != std::string::npos;
}

}  // namespace gab_test
