// gab_version and gab_free: the library itself.
#include <cstdlib>

#include "gab/gab.h"

extern "C" const char* gab_version(void) { return GAB_VERSION_STRING; }

extern "C" void gab_free(void* p) { std::free(p); }
