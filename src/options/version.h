// The program's version, set in one place: project(deltri VERSION ...) in CMakeLists.txt.
#pragma once

namespace deltri {

// e.g. "0.9.0"; printed by --version and -V and written into the JSON report.
const char* version();

}  // namespace deltri
