// Whether long double arithmetic rounds to its full significand right now. The incircle filter's
// long double stage (predicates.cpp) and the decimal reader's extended path (io/decimal_parse.h)
// take their error bounds from long double's 64-bit significand (x87). That is the type's, not
// always the arithmetic's: foreign code in the same process may have lowered the x87 precision
// control to 53 or 24 bits (some graphics and numeric libraries do), and valgrind carries out x87
// arithmetic in doubles. Either way a bound for 64 bits would prove wrong signs (under valgrind
// refinement of data/water.poly flipped edges forever), so each use asks first: a few cycles.
#pragma once

namespace deltri {

inline bool extended_precision_active() {
  volatile long double one = 1.0L, tiny = 0x1p-63L;
  return one + tiny != one;
}

}  // namespace deltri
