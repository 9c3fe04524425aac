#include "options/version.h"

// CMakeLists.txt passes the project's version to this file alone, so that a new version recompiles
// one file.
#ifndef DELTRI_VERSION
#error "DELTRI_VERSION is defined by CMakeLists.txt from project(deltri VERSION ...)"
#endif

namespace deltri {

const char* version() { return DELTRI_VERSION; }

}  // namespace deltri
