// Every option of a switch string or a command line travels in one Switches value: the Options the
// pipeline and the library read (options.h), and the command line's own files and messages.
#pragma once

#include <string>
#include <vector>

#include "options/options.h"

namespace deltri {

struct Switches : Options {
  // Formats beyond Triangle's, asked for by long options (--msh, --vtu, --svg, --json).
  struct FileRequest {
    bool wanted = false;
    std::string path;  // empty: <output base>.<extension>; "-": standard output
  };
  FileRequest msh, vtu, svg, json;
  FileRequest stl;               // --stl: ASCII STL of a surface mesh (facets in 3-D only)
  int msh_version = 22;          // --msh-format=2.2|4.1[,binary]
  bool msh_binary = false;
  long long domain_tag = 0;      // --domain-tag=N; 0: the rule's own (io/physical_groups.h)
  bool vtu_binary = false;       // --vtu-format=ascii|binary
  bool svg_numbers = false;      // --svg-numbers: vertex numbers in the picture
  bool strict = false;           // --strict: exit status 3 when triangles miss the bounds not forced by the input, or none exist
  bool triangle_messages = false;  // --triangle-messages: also Triangle's labelled statistics
  std::string size_field;        // --size-field=FILE: background mesh FILE.node/.ele of wanted edge lengths
  bool man = false;              // --man: print the manual page (roff) and exit
  bool version = false;          // --version: print the version and exit
  bool help = false;             // -h

  std::string input;             // the input file as given (the last one named, as Triangle takes it)
  std::vector<std::string> inputs;  // every input named, in order
  bool each = false;             // --each: mesh every input named, one after the other
  std::string command_line;      // every argument, space-separated (for the JSON report)
  std::vector<std::string> notices;  // letters Triangle accepts that deltri reads its own way (-L, -w, -o3, ...)
};

// Who gives the switches: on the command line a bare -u is Triangle's stock size test;
// the library takes it as asking for the caller's size function (caller_size_test).
enum class SwitchSource { CommandLine, Library };

// Parses Triangle-style arguments: switch words start with '-' and hold any number of letters,
// a letter's number follows it directly; the last other argument names the input.
// Throws UsageError on an unknown letter or a malformed number.
Switches parse_switches(int argc, const char* const* argv, SwitchSource source = SwitchSource::CommandLine);

// The -h text and the man page (docs/deltri.1), made from the same tables the parser uses.
std::string help_text();
std::string man_page();

// Whether some output goes to standard output (then every message goes to standard error).
bool uses_standard_output(const Switches& s);

}  // namespace deltri
