// A fast path for the shortest round-trip text of a double, for the magnitudes mesh coordinates
// usually have. std::to_chars takes almost all of a .node's writing time; this gives the identical
// characters for 0.01 <= |value| < 1000, where to_chars always chooses fixed notation (there it
// is strictly shorter than scientific), and declines everything else.
#pragma once

namespace deltri {

// Up to this many bytes from p may be overwritten (the result itself is at most 24 characters).
inline constexpr int kShortestFixedScratch = 25;

// Writes `value` at p exactly as std::to_chars(p, end, value) would and returns the end, or
// returns nullptr when `value` is outside the fast path.
char* format_shortest_fixed(char* p, double value);

}  // namespace deltri
