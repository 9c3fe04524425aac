// The error types are in util/errors.h, where every layer may see them. This header forwards to it
// for the two files that still name it here (cli/parse_switches.cpp, cli/switch_table.cpp).
#pragma once

#include "util/errors.h"
