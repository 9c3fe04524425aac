// The pipeline: read -> Delaunay -> constrained Delaunay -> carve -> (refine) -> check -> write.
// The only place that knows every stage.
#pragma once

#include "cli/switches.h"
#include "refine/refine.h"

namespace deltri {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInput = 1;     // the input files are malformed or unreadable
inline constexpr int kExitUsage = 2;     // the switches are wrong
inline constexpr int kExitBounds = 3;    // --strict: some triangles miss the bounds (files written)
inline constexpr int kExitOutput = 4;    // an output file could not be written
inline constexpr int kExitCheck = 5;     // -C found faults in the mesh
inline constexpr int kExitInternal = 6;  // out of memory or a bug

// The refinement options the switches ask for (-q, -a, -u, -D, -Y, -S, -k, --queue, ...); with
// area_file, per-triangle bounds are honoured (-a bare, or an .area read).
RefineOptions refine_options(const Switches& sw, bool area_file);

// Runs deltri with the given switches; prints the summary, warnings and -V report; returns the
// exit status. Throws InputError, OutputError or UsageError.
int run(const Switches& switches);

}  // namespace deltri
