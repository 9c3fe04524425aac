// The pipeline for facets in 3-D (TetGen's .poly with a 3-D node section, or .smesh): read ->
// mesh every facet, agreeing on shared segments (surface/surface_mesher.h) -> -C -> write.
#pragma once

#include <optional>
#include <string>

#include "options/switches.h"

namespace deltri {

// The facet file this run reads, if its input is one: a .smesh, or a .poly (named, or by -p)
// whose node header says dimension 3. Nothing for standard input.
std::optional<std::string> surface_input(const Switches& sw);

// Runs deltri on facets in 3-D; returns the exit status (as run() does).
int run_surface(const Switches& sw, const std::string& path);

}  // namespace deltri
