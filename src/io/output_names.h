// Names of input and output files, as Triangle derives them.
//   input_base("box.poly")  == "box"  (extension "poly")      input_base("box") == "box" ("")
//   output_base("box")      == "box.1"
//   output_base("mesh.3")   == "mesh.4"    (so -r chains: mesh.3.* -> mesh.4.*)
//   output_base("mesh", true) == "mesh"    (-I)
// Only the last path component is inspected: a dot in a directory name means nothing.
#pragma once

#include <string>

namespace deltri {

// Strips a known extension (.node, .poly, .ele, .area) and reports which one (without the dot,
// or "" when there was none).
std::string input_base(const std::string& path, std::string* extension);

// The base of the output files: the iteration number after the last dot incremented, or ".1"
// appended when there is none; unchanged with `no_iteration_number`.
std::string output_base(const std::string& input_base, bool no_iteration_number);

}  // namespace deltri
