// gab: the command-line tool. Dispatches to one function per sub-command.
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: gab <command> [options]\n");
    return 2;
  }
  std::fprintf(stderr, "gab: unknown command '%s'\n", argv[1]);
  return 2;
}
