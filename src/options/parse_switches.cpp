#include <cctype>
#include <charconv>
#include <string>
#include <thread>

#ifdef __linux__
#include <sched.h>
#endif

#include "options/switch_table.h"
#include "options/version.h"
#include "util/errors.h"

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

// What a letter's number must be, for a negative one.
std::string negative_number_message(char letter) {
  switch (letter) {
    case 'a': return "the maximum area must be a positive number, e.g. -a0.1";
    case 'q': return "the minimum angle must be at least 0 and below 60 degrees";
    case 'u': return "the maximum edge length must be a positive number, e.g. -u0.05";
    case 'S': return "the number of Steiner points cannot be negative (bare -S: none)";
    default: return "the number cannot be negative";
  }
}

// Letters Triangle 1.6 accepts that have no row of their own: true when `letter` was one.
bool triangle_only_letter(char letter, Switches& s) {
  switch (letter) {
    case 'L':  // Triangle's undocumented synonym of -D
      s.conforming_delaunay = true;
      s.notices.push_back("-L: read as -D (conforming Delaunay), as Triangle 1.6 does");
      return true;
    case 'w':
    case 'W':
      s.notices.push_back(std::string("-") + letter + ": weighted triangulations are not supported; ignored");
      return true;
    case 'H':
    case '?':
      s.help = true;
      return true;
    default: return false;
  }
}

// Triangle reads a switch's number with atof/atoi: a lone "." is 0, and an integer switch stops at
// the point, the rest of the number being ignored. Returns the characters after the number that
// Triangle ignores (-S2.5: ".5").
std::size_t ignored_fraction(std::string_view rest, const SwitchRow& row) {
  if (row.arg != ArgKind::OptionalInt || rest.empty() || rest[0] != '.') return 0;
  std::size_t k = 1;
  while (k < rest.size() && std::isdigit(static_cast<unsigned char>(rest[k]))) ++k;
  return k;
}

void parse_word(std::string_view word, Switches& s, SwitchSource source) {
  for (std::size_t i = 1; i < word.size();) {
    const char letter = word[i++];
    if (triangle_only_letter(letter, s)) continue;
    const SwitchRow* row = find_row(letter);
    if (!row) throw UsageError(std::string("-") + letter + ": unknown switch (see deltri -h)");
    bool has_value = false;
    double value = 0.0;
    if (row->arg != ArgKind::None) {
      // Triangle has no negative bounds, and "-a-1" must not turn into a bare -a and a stray "-".
      if (i + 1 < word.size() && word[i] == '-') {
        const std::size_t digits = number_length(word.substr(i + 1), false);
        if (digits > 0)
          throw UsageError(std::string("-") + letter + std::string(word.substr(i, 1 + digits)) + ": " +
                           negative_number_message(letter));
      }
      const std::size_t n = number_length(word.substr(i), row->arg == ArgKind::OptionalInt);
      if (n == 0 && letter == 'u' && source == SwitchSource::Library) {
        s.caller_size_test = true;
        continue;
      }
      if (n == 0 && letter == 'u') {
        s.stock_size_test = true;  // Triangle's stock triunsuitable (-u<length> is deltri's own test)
        continue;
      }
      if (n == 0 && row->arg == ArgKind::RequiredReal)
        throw UsageError(std::string("-") + letter + ": a number must follow, e.g. -" + letter + "0.05");
      if (n == 1 && word[i] == '.') {
        s.notices.push_back(std::string("-") + letter + ".: read as -" + letter + "0, as Triangle reads a lone point");
        has_value = true;
        i += 1;
      } else if (n > 0) {
        const auto res = std::from_chars(word.data() + i, word.data() + i + n, value);
        if (res.ec != std::errc() || res.ptr != word.data() + i + n)
          throw UsageError(std::string("-") + letter + ": malformed number '" + std::string(word.substr(i, n)) + "'");
        has_value = true;
        i += n;
        if (const std::size_t f = ignored_fraction(word.substr(i), *row); f > 0) {
          s.notices.push_back(std::string("-") + letter + std::string(word.substr(i - n, n + f)) + ": read as -" + letter +
                              std::string(word.substr(i - n, n)) + ", as Triangle does (a whole number)");
          i += f;
        }
      }
    }
    row->apply(s, has_value, value);
  }
}

void parse_long_option(std::string_view word, Switches& s) {
  const std::string_view body = word.substr(2);
  const std::size_t eq = body.find('=');
  const std::string_view name = body.substr(0, eq);
  for (const LongOption& option : long_option_table()) {
    if (name != option.name) continue;
    if (eq == std::string_view::npos) {
      if (*option.argument && !option.value_optional)
        throw UsageError(std::string("--") + option.name + ": give a value, e.g. --" + option.name + "=" + option.argument);
      option.apply(s, nullptr);
    } else {
      if (!*option.argument) throw UsageError(std::string("--") + option.name + ": takes no value");
      const std::string value(body.substr(eq + 1));
      option.apply(s, &value);
    }
    return;
  }
  throw UsageError("--" + std::string(name) + ": unknown option (see deltri -h)");
}

// The name an option's text follows in -h and the man page, e.g. "--msh[=FILE]".
std::string long_option_label(const LongOption& option) {
  std::string label = std::string("--") + option.name;
  if (*option.argument) label += option.value_optional ? std::string("[=") + option.argument + "]" : std::string("=") + option.argument;
  return label;
}

std::string switch_label(const SwitchRow& row) {
  std::string name = std::string("-") + row.letter;
  if (row.arg == ArgKind::RequiredReal) name += std::string("<") + row.argument_name + ">";
  else if (row.arg != ArgKind::None) name += std::string("[") + row.argument_name + "]";
  return name;
}

constexpr const char* kSummary = "two-dimensional quality mesh generation and Delaunay triangulation";

// Shared by -h and the man page so that they cannot disagree.
constexpr const char* kExitStatus[][2] = {
    {"0", "success"},
    {"1", "bad input file (one line: file:line: what is wrong)"},
    {"2", "bad switches"},
    {"3", "with --strict: triangles miss the -q/-a/-u bounds for a reason other than a small input angle, -D left subsegments not Delaunay, or the mesh is empty (the files are written)"},
    {"4", "an output file could not be written"},
    {"5", "-C found faults in the mesh"},
    {"6", "out of memory or an internal error"},
};

// roff text: backslashes and dashes escaped, no line may start with a control character.
std::string roff(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out.insert(0, "\\&");
  return out;
}

}  // namespace

bool uses_standard_output(const Switches& s) {
  for (const Switches::FileRequest* r : {&s.msh, &s.vtu, &s.svg, &s.json, &s.stl})
    if (r->wanted && r->path == "-") return true;
  return false;
}

// The cores this process may run on, from one system call: hardware_concurrency() reads sysfs
// (an open, a read and a close, about 10 us, a few per cent of a small run).
int threads_to_use(const Options& options) {
  if (options.threads > 0) return options.threads;
#ifdef __linux__
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0 && CPU_COUNT(&allowed) > 0) return CPU_COUNT(&allowed);
#endif
  const unsigned cores = std::thread::hardware_concurrency();
  return cores > 0 ? static_cast<int>(cores) : 1;
}

// --corner-lopping (Sec. 6.1) shields the angles of a PSLG's segments (-p), puts vertices on those
// segments (which -Y/-YY forbid) and fills the corners with fixed fans, which need not be Delaunay (-D).
namespace {
void refuse_corner_lopping_combinations(const Switches& s) {
  if (!s.corner_lopping) return;
  if (!s.poly || s.refine) throw RefusedSwitchError("--corner-lopping: needs -p and no -r (it shields the input angles of a PSLG)");
  if (s.no_boundary_steiner > 0)
    throw RefusedSwitchError("--corner-lopping: cannot be combined with -Y or -YY (the shields put vertices on the segments)");
  if (s.conforming_delaunay)
    throw RefusedSwitchError("--corner-lopping: cannot be combined with -D (the fans in the lopped corners need not be Delaunay)");
}

// --each runs the switches once per input, so an option naming one output file cannot follow it.
void refuse_each_combinations(const Switches& s, SwitchSource source) {
  if (!s.each) return;
  if (source == SwitchSource::Library) throw UsageError("--each: only on the command line (the library meshes what it is given)");
  if (s.inputs.size() < 2) return;
  const std::pair<const Switches::FileRequest*, const char*> named[] = {
      {&s.msh, "msh"}, {&s.vtu, "vtu"}, {&s.svg, "svg"}, {&s.json, "json"}, {&s.stl, "stl"}};
  for (const auto& [request, name] : named)
    if (request->wanted && !request->path.empty())
      throw UsageError(std::string("--each: --") + name + "=" + request->path + " names one file for " +
                       std::to_string(s.inputs.size()) + " inputs; give --" + name +
                       " alone to write one beside each input's mesh");
}
}  // namespace

Switches parse_switches(int argc, const char* const* argv, SwitchSource source) {
  Switches s;
  for (int k = 0; k < argc; ++k) s.command_line += (k ? " " : "") + std::string(argv[k]);
  for (int k = 1; k < argc; ++k) {
    const std::string_view word = argv[k];
    if (word.size() > 2 && word[0] == '-' && word[1] == '-') {
      parse_long_option(word, s);
    } else if (word.size() > 1 && word[0] == '-') {
      parse_word(word, s, source);
    } else {
      s.input = std::string(word);
      s.inputs.push_back(s.input);
    }
  }
  refuse_each_combinations(s, source);
  if (s.quality && !(s.min_angle >= 0.0 && s.min_angle < 60.0))
    throw UsageError("-q: the minimum angle must be at least 0 and below 60 degrees");
  if (const char* refused = refused_combination(s.refinement, s.interior_bound, s.quality, s.conforming_delaunay,
                                                s.decline_cluster_splits))
    throw UsageError(refused);
  if (s.refine && s.no_iteration) throw RefusedSwitchError("-I: cannot be combined with -r (the output would overwrite the input)");
  int to_stdout = 0;
  for (const Switches::FileRequest* r : {&s.msh, &s.vtu, &s.svg, &s.json, &s.stl}) to_stdout += r->wanted && r->path == "-";
  if (to_stdout > 1) throw UsageError("-: only one of --msh=-, --vtu=-, --svg=-, --json=- can go to standard output");
  refuse_corner_lopping_combinations(s);
  return s;
}

std::string help_text() {
  std::string out = std::string("deltri: ") + kSummary + "\n" +
      "usage: deltri [-switches] [--options] inputfile\n"
      "  Switches are letters run together after one '-', e.g. deltri -pq30a0.1 box.poly\n"
      "  The input is name.node (points), name.poly (with -p), or name.node + name.ele (with -r);\n"
      "  - reads standard input (a .poly with -p, else a .node).\n\n";
  for (const SwitchRow& row : switch_table()) {
    std::string name = "  " + switch_label(row);
    name.resize(std::max<std::size_t>(name.size() + 1, 14), ' ');
    out += name + row.help + "\n";
  }
  out += "\n";
  for (const LongOption& option : long_option_table()) {
    std::string name = "  " + long_option_label(option);
    name.resize(std::max<std::size_t>(name.size() + 1, 18), ' ');
    out += name + option.help + "\n";
  }
  out += "\nExit status:";
  for (const auto& [code, meaning] : kExitStatus) out += std::string(" ") + code + " " + meaning + ";";
  out.back() = '.';
  out += "\n";
  return out;
}

std::string man_page() {
  std::string out =
      ".\\\" Generated by deltri --man from the switch table (src/options/switch_table.cpp); do not edit.\n"
      ".TH DELTRI 1 \"\" \"deltri " + std::string(version()) + "\" \"User Commands\"\n"
      ".SH NAME\n"
      "deltri \\- " + roff(kSummary) + "\n"
      ".SH SYNOPSIS\n"
      ".B deltri\n"
      "[\\fB\\-\\fIswitches\\fR] [\\fB\\-\\-\\fIoption\\fR[=\\fIFILE\\fR]] ... \\fIinputfile\\fR\n"
      ".SH DESCRIPTION\n"
      "deltri builds Delaunay triangulations, constrained Delaunay triangulations of planar straight-line graphs\n"
      "and quality meshes. It takes the switches of Shewchuk's Triangle and reads and writes the same files.\n"
      ".PP\n"
      "The input is \\fIname\\fR.node (a point set), \\fIname\\fR.poly (with \\fB\\-p\\fR), or \\fB\\-\\fR for standard\n"
      "input (read as a .poly with \\fB\\-p\\fR, else as a .node; the output files are then named stdin.1.*).\n"
      "Output files are written next to the input as \\fIname\\fR.1.node, \\fIname\\fR.1.ele, ... and appear\n"
      "all together or not at all.\n"
      ".SH SWITCHES\n"
      "Switches are letters run together after one dash, numbers written directly after their letter,\n"
      "e.g. \\fB\\-pq30a0.1\\fR.\n";
  for (const SwitchRow& row : switch_table()) out += ".TP\n.B " + roff(switch_label(row)) + "\n" + roff(row.help) + "\n";
  out += ".SH OPTIONS\n"
         "Formats beyond Triangle's are asked for with long options. Without =\\fIFILE\\fR the file is named like the\n"
         "others (\\fIname\\fR.1.msh, .vtu, .svg, .json). With =\\fB\\-\\fR it goes to standard output, after every\n"
         "other file is in place; every message then goes to standard error, and the .node, .ele and .poly files\n"
         "are not written (as with \\fB\\-NEP\\fR).\n";
  for (const LongOption& option : long_option_table())
    out += ".TP\n.B " + roff(long_option_label(option)) + "\n" + roff(option.help) + "\n";
  out += ".SH EXIT STATUS\n";
  for (const auto& [code, meaning] : kExitStatus) out += ".TP\n.B " + std::string(code) + "\n" + roff(meaning) + "\n";
  out += ".SH EXAMPLES\n"
         ".TP\n.B deltri \\-pq30a0.1 box.poly\nquality mesh of box.poly: box.1.node, box.1.ele, box.1.poly\n"
         ".TP\n.B cat box.poly | deltri \\-pq30 \\-\\-msh=\\- \\- > box.msh\nfrom a pipe to a Gmsh file\n"
         ".TP\n.B deltri \\-pq30 \\-\\-svg \\-\\-json box.poly\nalso box.1.svg (a picture) and box.1.json (a report)\n"
         ".SH SEE ALSO\n"
         "docs/manual.md and docs/formats.md in the deltri sources.\n";
  return out;
}

}  // namespace deltri
