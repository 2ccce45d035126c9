// What the shared libgab exports (capi/CMakeLists.txt's version script):
// exactly the C functions gab.h declares, and C++ symbols only of the names
// the installed headers declare (every free function among them), nothing
// of the internal headers or of the libraries libgab uses.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "common/scratch_files.h"

namespace {

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The identifier starting at `at` in `text`.
std::string identifier_at(const std::string& text, size_t at) {
  size_t end = at;
  while (end < text.size() && name_char(text[end])) ++end;
  return text.substr(at, end - at);
}

// `nm -D --defined-only -C` of the shared library: one symbol name per entry.
std::vector<std::string> exported_symbols() {
  std::vector<std::string> names;
  const std::string command = std::string(GAB_NM) + " -D --defined-only -C " + GAB_SHARED_LIBRARY;
  FILE* p = popen(command.c_str(), "r");
  if (p == nullptr) return names;
  char line[4096];
  while (std::fgets(line, sizeof line, p) != nullptr) {
    std::string text(line);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    const size_t name = text.find(' ', text.find(' ') + 1);  // "ADDRESS TYPE NAME"
    if (name != std::string::npos) names.push_back(text.substr(name + 1));
  }
  pclose(p);
  return names;
}

TEST(SymbolsTest, SharedLibraryExportsOnlyTheCAndCppApis) {
  if (std::string(GAB_NM).empty()) GTEST_SKIP() << "no nm on this machine";
  const std::vector<std::string> symbols = exported_symbols();
  ASSERT_FALSE(symbols.empty()) << "nm found nothing in " << GAB_SHARED_LIBRARY;

  // The C functions gab.h declares.
  const std::string header = gab_test::read_file(std::string(GAB_SOURCE_DIR) + "/capi/include/gab/gab.h");
  std::set<std::string> declared_c;  // every "gab_NAME(" (std::regex trips GCC 12's warnings under ASan)
  for (size_t at = header.find("gab_"); at != std::string::npos; at = header.find("gab_", at + 1)) {
    const std::string name = identifier_at(header, at);
    if ((at == 0 || !name_char(header[at - 1])) && header.compare(at + name.size(), 1, "(") == 0) declared_c.insert(name);
  }
  EXPECT_GE(declared_c.size(), 14u);
  // The names of the installed C++ headers' classes, structs and functions.
  std::set<std::string> declared_cxx;
  std::ifstream names(GAB_EXPORTED_CXX_NAMES);
  for (std::string name; std::getline(names, name);) {
    if (!name.empty()) declared_cxx.insert(name);
  }
  ASSERT_GE(declared_cxx.size(), 40u);

  std::set<std::string> exported_c, exported_cxx;
  for (const std::string& symbol : symbols) {
    if (symbol.find("::") == std::string::npos && symbol.find('(') == std::string::npos) {
      exported_c.insert(symbol);
    } else if (symbol.rfind("gab::", 0) == 0) {
      const std::string entity = identifier_at(symbol, 5);
      EXPECT_EQ(declared_cxx.count(entity), 1u) << symbol << " is exported but no installed header declares " << entity;
      exported_cxx.insert(entity);
    } else {
      ADD_FAILURE() << symbol << " is exported and is not gab's";
    }
  }
  EXPECT_EQ(exported_c, declared_c);
  // Every free function of the installed headers (lower-case names; the
  // types have out-of-line members or none) is there.
  for (const std::string& name : declared_cxx) {
    if (std::islower(static_cast<unsigned char>(name[0]))) {
      EXPECT_EQ(exported_cxx.count(name), 1u) << name;
    }
  }
  for (const char* must : {"Cholesky", "encode_mesh", "decode_mesh", "read_mesh"}) EXPECT_EQ(exported_cxx.count(must), 1u);
}

}  // namespace
