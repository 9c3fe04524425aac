// What every entry of the C++ library does the same way: the switch string read with the command
// line's parser, and every failure turned into one deltri::api::Error with its status code.
#pragma once

#include <string>

#define DELTRI_INTERNAL
#include "deltri/deltri.hpp"

#include "options/options.h"

namespace deltri {

// Triangle's switch string (no dash needed; a bare u only with a size function) as Options, quiet,
// read by the parser the command line uses (options/switches.h): every entry decides from these what to read and write, never
// from the letters of the string. Throws api::Error (DELTRI_USAGE_ERROR for bad switches).
Options parse_library_switches(const std::string& given, bool size_function);

// api::triangulate on switches already parsed (parse_library_switches with `size` given or not),
// so that an entry which needs them first (the C library) parses the string once.
api::Mesh triangulate_parsed(const api::Input& input, const Options& sw, const api::SizeFunction& size);

// Called inside a catch block: rethrows the exception being handled as an api::Error (InputError as
// DELTRI_INPUT_ERROR, UsageError as DELTRI_USAGE_ERROR, out of memory as DELTRI_MEMORY_ERROR, other
// exceptions as DELTRI_INTERNAL_ERROR; an api::Error as it is).
[[noreturn]] void rethrow_as_library_error();

}  // namespace deltri
