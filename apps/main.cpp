// gab: the command-line tool. Dispatches to one function per sub-command
// (the contract: exit 0 ok, 1 failure, 2 usage; JSON on stdout only).
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>

#include "cli.h"
#include "commands.h"
#include "gab/mesh/file_io.h"
#include "malloc_tuning.h"

namespace {

// Appends each line of `block` to `text`, after `indent` and without its
// first `skip` characters.
void append_lines(const std::string& block, const std::string& indent, size_t skip, std::string* text) {
  for (size_t at = 0, end; at < block.size(); at = end + 1) {
    end = block.find('\n', at);
    if (end == std::string::npos) end = block.size();
    *text += indent + block.substr(at + skip, end - at - skip) + "\n";
  }
}

// `gab help`: the command table (commands.h), each usage without its "gab "
// (continuation lines are aligned four columns further too), then the summary.
std::string help_text() {
  std::string text =
      "gab: geometry-aware bases for triangle meshes, and a sparse Cholesky engine\n"
      "\n"
      "usage: gab <command> [options]\n"
      "\n"
      "commands:\n";
  for (const gab::cli::Command& c : gab::cli::commands()) {
    append_lines(gab::cli::usage_text(c), "  ", 4, &text);
    append_lines(c.summary, "      ", 0, &text);
  }
  return text +
         "\n"
         "--json prints one JSON object on stdout; messages go to stderr. --threads: threads for the\n"
         "factorizations (compress/decompress default: all cores; factor: 1); results never depend on it.\n";
}

// Ctrl-C, SIGTERM, SIGHUP: the output files being written leave no
// temporary behind; then the signal's default action (the exit status a
// shell expects).
extern "C" void on_stop_signal(int signal) {
  gab::remove_partial_outputs();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

int main(int argc, char** argv) {
  gab::cli::tune_malloc();
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    // A signal the caller ignores (nohup, a background job) stays ignored.
    if (std::signal(signal, on_stop_signal) == SIG_IGN) std::signal(signal, SIG_IGN);
  }
  if (argc < 2) {
    std::fputs(help_text().c_str(), stderr);
    return gab::cli::kExitUsage;
  }
  const char* command = argv[1];
  if (!std::strcmp(command, "help") || !std::strcmp(command, "--help") || !std::strcmp(command, "-h")) {
    std::fputs(help_text().c_str(), stdout);
    return gab::cli::kExitOk;
  }
  if (!std::strcmp(command, "--version")) command = "version";
  if (const gab::cli::Command* c = gab::cli::find_command(command)) {
    // `gab CMD --help` (or -h) anywhere among its arguments: its usage and
    // what it does, on stdout, and nothing run.
    for (int i = 2; i < argc; ++i) {
      if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
        std::string text = "usage: " + gab::cli::usage_text(*c) + "\n\n";
        append_lines(c->summary, "", 0, &text);
        text += "\nThe options: docs/cli.md; every command: gab help.\n";
        std::fputs(text.c_str(), stdout);
        return gab::cli::kExitOk;
      }
    }
    // The library reports failures as Status; what escapes as an exception
    // (memory exhausted, above all) is still one line and exit 1.
    try {
      return c->run(argc - 2, argv + 2);
    } catch (const std::bad_alloc&) {
      return gab::cli::fail(std::string("out of memory (") + command + ")");
    } catch (const std::exception& e) {
      return gab::cli::fail(std::string(command) + ": " + e.what());
    }
  }
  std::fprintf(stderr, "gab: unknown command '%s' (try 'gab help')\n", command);
  return gab::cli::kExitUsage;
}
