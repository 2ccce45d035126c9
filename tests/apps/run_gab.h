// Running the gab binary from a test: exit code, stdout and stderr apart.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

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
  const std::string err_path = ::testing::TempDir() + "/gab_stderr_" + std::to_string(getpid()) + "_" +
                               std::to_string(++calls) + ".txt";
  const std::string cmd = (prefix.empty() ? "" : prefix + " ") + std::string(GAB_BINARY) + " " + args + " 2>" + err_path;
  CommandResult r{-1, "", ""};
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return r;
  char buf[4096];
  size_t got;
  while ((got = fread(buf, 1, sizeof(buf), p)) > 0) r.out.append(buf, got);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(err_path);
  r.err.assign(std::istreambuf_iterator<char>(e), std::istreambuf_iterator<char>());
  std::remove(err_path.c_str());
  return r;
}

// This process's scratch folder in the test temp dir: made on first use and
// removed, with whatever the tests and the binary wrote in it, when the
// process exits (ctest runs each test in a process of its own).
inline const std::string& scratch_dir() {
  struct Dir {
    std::string path = ::testing::TempDir() + "/gab_cli_" + std::to_string(getpid());
    Dir() { std::filesystem::create_directories(path); }
    ~Dir() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Dir dir;
  return dir.path;
}

// A path in the scratch folder.
inline std::string scratch_path(const std::string& name) { return scratch_dir() + "/" + name; }

// Writes `text` to a file in the scratch folder; returns its path.
inline std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = scratch_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
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
