#include "gab/mesh/mesh.h"
