// Every command's options are written once (apps/commands.cpp): the usage
// errors quote them, `gab help` lists them, the parser accepts each one, and
// the README shows the same text.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "run_gab.h"

namespace {

using gab_test::CommandResult;
using gab_test::run_gab;

const char* kCommands[] = {"compress", "decompress", "info", "demo", "factor", "study", "diff", "subdivide",
                           "version"};

// The usage a command prints after a bad option: "usage: gab NAME ..." to
// the end of stderr.
std::string usage_of(const std::string& command) {
  const CommandResult r = run_gab(command + " --no-such-option");
  EXPECT_EQ(r.exit_code, 2) << command;
  EXPECT_NE(r.err.find("unknown option --no-such-option"), std::string::npos) << r.err;
  const size_t at = r.err.find("usage: ");
  return at == std::string::npos ? "" : r.err.substr(at + 7);
}

// Whitespace-separated words: the README aligns the columns differently.
std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  return {std::istream_iterator<std::string>(in), std::istream_iterator<std::string>()};
}

// The README's synopsis of a command: the line starting "gab NAME" inside a
// code block and the indented lines under it.
std::string readme_synopsis(const std::string& readme, const std::string& command) {
  std::istringstream in(readme);
  std::string line, found;
  bool inside = false;
  while (std::getline(in, line)) {
    if (inside && !line.empty() && line[0] == ' ') {
      found += "\n" + line;
      continue;
    }
    if (inside) break;
    if (line.rfind("gab " + command + " ", 0) == 0 || line == "gab " + command) {
      found = line;
      inside = true;
    }
  }
  return found;
}

TEST(UsageTest, HelpListsEveryCommandsUsage) {
  const CommandResult help = run_gab("help");
  ASSERT_EQ(help.exit_code, 0);
  const std::vector<std::string> help_words = words(help.out);
  for (const char* command : kCommands) {
    std::vector<std::string> usage = words(usage_of(command));
    ASSERT_GE(usage.size(), 2u) << command;
    usage.erase(usage.begin());  // "gab": the help lists "  NAME ..."
    EXPECT_NE(std::search(help_words.begin(), help_words.end(), usage.begin(), usage.end()), help_words.end())
        << command << " in\n" << help.out;
  }
}

TEST(UsageTest, EveryOptionInTheUsageIsAccepted) {
  int options = 0;
  for (const char* command : kCommands) {
    const std::string usage = usage_of(command);
    const std::regex option("--[a-z][a-z-]*");
    for (auto it = std::sregex_iterator(usage.begin(), usage.end(), option); it != std::sregex_iterator(); ++it) {
      const CommandResult r = run_gab(std::string(command) + " " + it->str());
      EXPECT_EQ(r.err.find("unknown option"), std::string::npos) << command << " " << it->str() << ": " << r.err;
      ++options;
    }
  }
  EXPECT_GE(options, 30);  // the regex found the options at all
}

TEST(UsageTest, TheReadmeShowsTheSameUsage) {
  std::ifstream file(std::string(GAB_SOURCE_DIR) + "/README.md");
  ASSERT_TRUE(file) << "README.md not found";
  const std::string readme((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  for (const char* command : kCommands) {
    const std::string shown = readme_synopsis(readme, command);
    EXPECT_EQ(words(shown), words(usage_of(command))) << "README shows:\n" << shown;
  }
}

}  // namespace
