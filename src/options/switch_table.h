// The table of switches: one row per letter. The parser and the -h text are both made from it.
#pragma once

#include <span>

#include "options/switches.h"

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

// Options beyond Triangle's letters, written --name or --name=value.
struct LongOption {
  const char* name;      // without the dashes
  const char* argument;  // for -h, e.g. "FILE"; "" when the option takes no value
  bool value_optional;   // --name alone is allowed too
  const char* help;      // one line
  // `value` is null when no '=' followed the name.
  void (*apply)(Switches& s, const std::string* value);
};

std::span<const LongOption> long_option_table();

}  // namespace deltri
