// The meshes a size benchmark reads: those named on its command line, or
// else every shared mesh (../shared/meshes), largest first.
#pragma once

#include <string>
#include <vector>

namespace gab_bench {

inline std::vector<std::string> mesh_paths(int argc, char** argv) {
  std::vector<std::string> paths(argv + 1, argv + argc);
  if (paths.empty()) {
    for (const char* name : {"igea", "nefertiti", "feline", "horse", "max-planck", "bunny", "bunny-small", "camel-head"}) {
      paths.push_back(std::string(GAB_SHARED_MESHES) + "/" + name + ".off");
    }
  }
  return paths;
}

}  // namespace gab_bench
