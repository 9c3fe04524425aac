// "00" "01" ... "99": the integer and decimal writers produce two digits per table lookup, which
// halves the number of divisions.
#pragma once

namespace deltri {

struct DigitPairs {
  char text[200];
};

inline constexpr DigitPairs kDigitPairs = [] {
  DigitPairs table{};
  for (int i = 0; i < 100; ++i) {
    table.text[2 * i] = static_cast<char>('0' + i / 10);
    table.text[2 * i + 1] = static_cast<char>('0' + i % 10);
  }
  return table;
}();

}  // namespace deltri
