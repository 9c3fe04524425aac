#include <cctype>
#include <charconv>
#include <string>

#include "cli/switch_table.h"
#include "pslg/errors.h"

namespace deltri {
namespace {

const SwitchRow* find_row(char letter) {
  for (const SwitchRow& row : switch_table())
    if (row.letter == letter) return &row;
  return nullptr;
}

// Length of the number starting at text: digits and at most one point, then an exponent only when
// a digit follows the 'e' (so "-a0.1e" still means area 0.1 plus -e, as in Triangle).
std::size_t number_length(std::string_view text, bool integer) {
  std::size_t i = 0;
  bool point = false;
  while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || (!integer && !point && text[i] == '.'))) {
    if (text[i] == '.') point = true;
    ++i;
  }
  if (integer || i == 0 || i + 1 >= text.size() || (text[i] != 'e' && text[i] != 'E')) return i;
  std::size_t j = i + 1;
  if (text[j] == '+' || text[j] == '-') ++j;
  if (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) {
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
    return j;
  }
  return i;
}

void parse_word(std::string_view word, Switches& s) {
  for (std::size_t i = 1; i < word.size();) {
    const char letter = word[i++];
    const SwitchRow* row = find_row(letter);
    if (!row) throw UsageError(std::string("-") + letter + ": unknown switch (see deltri -h)");
    bool has_value = false;
    double value = 0.0;
    if (row->arg != ArgKind::None) {
      const std::size_t n = number_length(word.substr(i), row->arg == ArgKind::OptionalInt);
      if (n == 0 && row->arg == ArgKind::RequiredReal)
        throw UsageError(std::string("-") + letter + ": a number must follow, e.g. -" + letter + "0.05");
      if (n > 0) {
        const auto res = std::from_chars(word.data() + i, word.data() + i + n, value);
        if (res.ec != std::errc() || res.ptr != word.data() + i + n)
          throw UsageError(std::string("-") + letter + ": malformed number '" + std::string(word.substr(i, n)) + "'");
        has_value = true;
        i += n;
      }
    }
    row->apply(s, has_value, value);
  }
}

}  // namespace

Switches parse_switches(int argc, const char* const* argv) {
  Switches s;
  for (int k = 1; k < argc; ++k) {
    const std::string_view word = argv[k];
    if (word.size() > 1 && word[0] == '-') {
      parse_word(word, s);
    } else {
      s.input = std::string(word);
    }
  }
  if (s.quality && !(s.min_angle >= 0.0 && s.min_angle < 60.0))
    throw UsageError("-q: the minimum angle must be at least 0 and below 60 degrees");
  if (s.refine && s.no_iteration) throw UsageError("-I: cannot be combined with -r (the output would overwrite the input)");
  return s;
}

std::string help_text() {
  std::string out =
      "deltri: two-dimensional quality mesh generation and Delaunay triangulation\n"
      "usage: deltri [-switches] inputfile\n"
      "  Switches are letters run together after one '-', e.g. deltri -pq30a0.1 box.poly\n"
      "  The input is name.node (points), name.poly (with -p), or name.node + name.ele (with -r).\n\n";
  for (const SwitchRow& row : switch_table()) {
    std::string name = std::string("  -") + row.letter;
    if (row.arg == ArgKind::RequiredReal) name += std::string("<") + row.argument_name + ">";
    else if (row.arg != ArgKind::None) name += std::string("[") + row.argument_name + "]";
    name.resize(std::max<std::size_t>(name.size() + 1, 14), ' ');
    out += name + row.help + "\n";
  }
  out += "\nExit status: 0 success, 1 bad input, 2 bad switches, 4 output not written, 5 -C found faults.\n";
  return out;
}

}  // namespace deltri
