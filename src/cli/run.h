// The command line's run: read the files, run the stages (pipeline/pipeline.h: Delaunay -> constrained
// Delaunay -> carve -> (refine) -> check), write the files and messages; facets in 3-D go to
// cli/surface_run.h.
#pragma once

#include "options/switches.h"

namespace deltri {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInput = 1;     // the input files are malformed or unreadable
inline constexpr int kExitUsage = 2;     // the switches are wrong
inline constexpr int kExitBounds = 3;    // --strict: some triangles miss the bounds (files written)
inline constexpr int kExitOutput = 4;    // an output file could not be written
inline constexpr int kExitCheck = 5;     // -C found faults in the mesh
inline constexpr int kExitInternal = 6;  // out of memory or a bug

// Runs deltri with the given switches; prints the summary, warnings and -V report; returns the
// exit status. Throws InputError, OutputError or UsageError.
int run(const Switches& switches);

}  // namespace deltri
