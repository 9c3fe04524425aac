// The machine-readable report of a run (--json): what was read, what was built, how good it is,
// what was repaired, how long each stage took, which files were written. One JSON object; its
// keys are documented in docs/formats.md.
#pragma once

#include <string>

#include "cli/report.h"
#include "mesh/mesh.h"

namespace deltri {

// `sw` are the run's switches (report.options is their Options part); `exit_status` is the status
// the run ends with (0, or 3 with --strict).
std::string json_report(const Mesh& mesh, const Switches& sw, const RunReport& report, int exit_status);

}  // namespace deltri
