// The lines a run prints from its RunReport (pipeline/run_report.h): the summary (unless -Q),
// warnings about repaired input, notices, and the -V report. Messages go to standard error except
// the summary and -V report, which go to standard output.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "options/switches.h"
#include "pipeline/run_report.h"
#include "quality/check_mesh.h"
#include "refine/refine.h"

namespace deltri {

// The warnings about the input and the result, one line each, without the "deltri: warning:"
// prefix (the JSON report lists the same lines).
std::vector<std::string> run_warnings(const Mesh& mesh, const RunReport& report);

// Why the termination guard's Steiner cap stopped refinement, in one line (the warning, and the
// JSON report's why_missed).
std::string cap_explanation(const RefineReport& q);

class Messages {
 public:
  // The summary and -V report go to standard output, unless a file goes there.
  explicit Messages(const Switches& sw) : sw_(sw), out_(uses_standard_output(sw) ? stderr : stdout) {}
  void notice(const std::string& text) const;
  void check_failed(const CheckReport& check) const;
  // Warnings about the input, then the summary line, then (with -V) the report.
  void finished(const Mesh& mesh, const RunReport& report) const;

 private:
  void warn_about_input(const Mesh& mesh, const RunReport& report) const;
  void verbose_report(const Mesh& mesh, const RunReport& report) const;
  void triangle_report(const Mesh& mesh, const RunReport& report) const;
  const Switches& sw_;
  std::FILE* out_;
};

}  // namespace deltri
