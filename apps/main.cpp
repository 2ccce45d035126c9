// gab: the command-line tool. Dispatches to one function per sub-command
// (the contract: exit 0 ok, 1 failure, 2 usage; JSON on stdout only).
#include <cstdio>
#include <cstring>
#include <string>

#include "cli.h"
#include "commands.h"
#include "huge_page_malloc.h"

namespace {

// `gab help`: the command table (commands.h) with each command's summary.
std::string help_text() {
  std::string text =
      "gab: geometry-aware bases for triangle meshes, and a sparse Cholesky engine\n"
      "\n"
      "usage: gab <command> [options]\n"
      "\n"
      "commands:\n";
  for (const gab::cli::Command& c : gab::cli::commands()) {
    // "  compress -i IN ...": the usage without its "gab " (four columns,
    // continuation lines too), indented by two.
    const std::string usage = gab::cli::usage_text(c);
    for (size_t at = 0, end; at < usage.size(); at = end + 1) {
      end = usage.find('\n', at);
      if (end == std::string::npos) end = usage.size();
      text += "  " + usage.substr(at + 4, end - at - 4) + "\n";
    }
    const std::string summary = c.summary;
    for (size_t at = 0, end; at < summary.size(); at = end + 1) {
      end = summary.find('\n', at);
      if (end == std::string::npos) end = summary.size();
      text += "      " + summary.substr(at, end - at) + "\n";
    }
  }
  return text +
         "\n"
         "--json prints one JSON object on stdout; messages go to stderr. --threads: threads for the\n"
         "factorizations (compress/decompress default: all cores; factor: 1); results never depend on it.\n";
}

}  // namespace

int main(int argc, char** argv) {
  gab::cli::use_huge_page_malloc(argv);
  if (argc < 2) {
    std::fputs(help_text().c_str(), stderr);
    return gab::cli::kExitUsage;
  }
  const char* command = argv[1];
  if (!std::strcmp(command, "help") || !std::strcmp(command, "--help") || !std::strcmp(command, "-h")) {
    std::fputs(help_text().c_str(), stdout);
    return gab::cli::kExitOk;
  }
  if (const gab::cli::Command* c = gab::cli::find_command(command)) return c->run(argc - 2, argv + 2);
  std::fprintf(stderr, "gab: unknown command '%s' (try 'gab help')\n", command);
  return gab::cli::kExitUsage;
}
