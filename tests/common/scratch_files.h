// Files the tests write. Each test process (ctest runs every test in a
// process of its own) gets one scratch folder under the test temp dir, made on
// first use and removed with everything in it when the process exits, so a
// run of the suite leaves nothing behind and parallel tests never collide.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

namespace gab_test {

// This process's scratch folder.
inline const std::string& scratch_dir() {
  struct Dir {
    std::string path = ::testing::TempDir() + "/gab_test_" + std::to_string(getpid());
    Dir() { std::filesystem::create_directories(path); }
    ~Dir() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Dir dir;
  return dir.path;
}

// A path in the scratch folder (the file is not created).
inline std::string scratch_path(const std::string& name) { return scratch_dir() + "/" + name; }

// Writes `bytes` to `path` (replacing it); returns `path`.
inline std::string write_file(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// Writes `bytes` to a file of the scratch folder; returns its path.
inline std::string write_scratch_file(const std::string& name, const std::string& bytes) {
  return write_file(scratch_path(name), bytes);
}

// The whole content of `path` ("" when it cannot be read).
inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The names in the scratch folder that start with `prefix` (e.g. a writer's
// leftover temporary files).
inline std::vector<std::string> scratch_entries(const std::string& prefix) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(scratch_dir())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0) names.push_back(name);
  }
  return names;
}

}  // namespace gab_test
