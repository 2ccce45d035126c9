// gab version (and gab --version): the version string, the same that the
// library's gab_version() returns (both are gab/version.h's, from the
// build's project() version), alone on stdout so scripts can compare it.
#include <cstdio>

#include "cli.h"
#include "commands.h"
#include "gab/version.h"

namespace gab {
namespace cli {

int run_version(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {}, {})) return usage_error("version", args.error());
  if (!args.positionals().empty()) return usage_error("version", "unexpected argument " + args.positionals()[0]);
  std::printf("%s\n", GAB_VERSION_STRING);
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
