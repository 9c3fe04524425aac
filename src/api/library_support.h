// What every entry of the C++ library does the same way: the switch string read with the command
// line's parser, and every failure turned into one deltri::api::Error with its status code.
#pragma once

#include <string>

#define DELTRI_INTERNAL
#include "deltri/deltri.hpp"

#include "cli/switches.h"

namespace deltri {

// Triangle's switch string (no dash needed; a bare u only with a size function) as Switches, quiet.
Switches parse_library_switches(const std::string& given, bool size_function);

// Called inside a catch block: rethrows the exception being handled as an api::Error (InputError as
// DELTRI_INPUT_ERROR, UsageError as DELTRI_USAGE_ERROR, out of memory as DELTRI_MEMORY_ERROR, other
// exceptions as DELTRI_INTERNAL_ERROR; an api::Error as it is).
[[noreturn]] void rethrow_as_library_error();

}  // namespace deltri
