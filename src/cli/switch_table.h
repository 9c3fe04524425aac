// The table of switches: one row per letter. The parser and the -h text are both made from it.
#pragma once

#include <span>

#include "cli/switches.h"

namespace deltri {

enum class ArgKind {
  None,           // a bare letter
  OptionalReal,   // may be followed by a decimal number (-q, -a)
  OptionalInt,    // may be followed by an integer (-S, -o)
  RequiredReal,   // must be followed by a decimal number (-u)
};

struct SwitchRow {
  char letter;
  ArgKind arg;
  const char* argument_name;  // for -h, e.g. "angle"
  const char* help;           // one line
  // Applies the switch; `has_value` says whether a number followed, `value` holds it.
  void (*apply)(Switches& s, bool has_value, double value);
};

std::span<const SwitchRow> switch_table();

}  // namespace deltri
