// gab --version and gab version: the version string alone on stdout, the
// one gab/version.h holds (which gab_version() returns: tests/capi) and the
// build's project() version.
#include <gtest/gtest.h>

#include <string>

#include "gab/version.h"
#include "run_gab.h"

namespace {

using gab_test::CommandResult;
using gab_test::run_gab;

TEST(VersionCliTest, BothSpellingsPrintTheLibraryVersion) {
  EXPECT_STREQ(GAB_VERSION_STRING, GAB_PROJECT_VERSION);
  for (const char* args : {"--version", "version"}) {
    const CommandResult r = run_gab(args);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_EQ(r.out, std::string(GAB_VERSION_STRING) + "\n") << args;
    EXPECT_EQ(r.err, "") << args;
  }
}

TEST(VersionCliTest, ExtraArgumentsAreAUsageError) {
  const CommandResult r = run_gab("version now");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unexpected argument now"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(VersionCliTest, HelpListsIt) {
  const CommandResult r = run_gab("help");
  EXPECT_NE(r.out.find("  version\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gab --version"), std::string::npos) << r.out;
}

}  // namespace
