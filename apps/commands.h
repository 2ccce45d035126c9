// The sub-commands of gab in one table: main dispatches through it, `gab
// help` prints it, every usage error quotes the command's synopsis from it,
// and a test holds the README's command blocks to it. A new option is added
// to the synopsis here and to the command's Args::parse list (a test checks
// that every option the synopsis names is accepted).
#pragma once

#include <string>
#include <vector>

namespace gab {
namespace cli {

int run_factor(int argc, char** argv);
int run_study(int argc, char** argv);
int run_diff(int argc, char** argv);
int run_subdivide(int argc, char** argv);
int run_compress(int argc, char** argv);
int run_decompress(int argc, char** argv);
int run_info(int argc, char** argv);
int run_demo(int argc, char** argv);
int run_version(int argc, char** argv);

struct Command {
  const char* name;
  int (*run)(int argc, char** argv);  // the arguments after the command's name
  // The options, one line per string, as `gab help`, the usage errors and
  // the README show them after "gab NAME".
  std::vector<const char*> synopsis;
  const char* summary;  // what it does, for `gab help`
};

// Every command, in the order `gab help` lists them.
const std::vector<Command>& commands();
// The command called `name`, or nullptr.
const Command* find_command(const std::string& name);
// "gab NAME " + the synopsis, continuation lines aligned under its first.
std::string usage_text(const Command& command);

}  // namespace cli
}  // namespace gab
