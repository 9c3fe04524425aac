// Every command-line option travels in one Switches value; nothing else holds settings.
#pragma once

#include <string>
#include <vector>

#include "delaunay/triangulate.h"
#include "refine/algorithm.h"
#include "refine/quality_queue.h"
#include "refine/steiner_policy.h"

namespace deltri {

struct Switches {
  // What to build.
  bool poly = false;             // -p  read a PSLG, build its constrained Delaunay triangulation
  bool refine = false;           // -r  refine a previous mesh
  bool quality = false;          // -q  quality mesh
  double min_angle = 20.0;       //     the -q angle in degrees
  bool fixed_area = false;       // -a<A>
  double max_area = -1.0;
  bool variable_area = false;    // -a  bare: regional or per-triangle areas
  bool user_test = false;        // -u<length>: no edge longer than length
  bool stock_size_test = false;  // bare -u on the command line: Triangle's stock triunsuitable (refine/size_test.h)
  bool caller_size_test = false; // a bare u in a library switch string: the caller's size function
  double max_edge_length = -1.0;
  bool circumcenters_only = false;  // -k: Steiner points at circumcentres, no off-centres
  SteinerPolicy steiner = SteinerPolicy::Automatic;  // --steiner=offcentre|circumcentre|optimal
  QueueOrder queue_order = QueueOrder::ShortestEdge;  // --queue=
  bool decline_cluster_splits = false;               // --decline-cluster-splits
  RefinementAlgorithm refinement = RefinementAlgorithm::Terminator;  // --algorithm=terminator|ruppert|chew
  int interior_bound = 0;                            // --interior-bound=1|2 (Sec. 7.2)
  double max_angle = 0.0;                            // --max-angle=A, 90 <= A < 180; 0: none
  bool range_restricted = false;                     // --range-restricted (Sec. 7.3)
  bool corner_lopping = false;                       // --corner-lopping (Sec. 6.1)
  int smooth_rounds = 0;                             // --smooth[=N]: N rounds of the improvement pass (0: none)
  bool regional_attributes = false;  // -A
  bool convex_hull = false;      // -c
  bool conforming_delaunay = false;  // -D
  bool jettison = false;         // -j
  int no_boundary_steiner = 0;   // -Y (1), -YY (2)
  long max_steiner = -1;         // -S<n>; -1 means unlimited
  bool split_segments = false;   // -s
  bool ignore_holes = false;     // -O
  bool inexact = false;          // -X (accepted; arithmetic stays exact)
  DelaunayAlgorithm algorithm = DelaunayAlgorithm::DivideAndConquer;  // -i, -l
  bool sweepline = false;        // -F (divide and conquer is used instead)

  // What to write.
  bool edges = false;            // -e
  bool voronoi = false;          // -v
  bool neighbors = false;        // -n
  bool geomview = false;         // -g
  bool no_markers = false;       // -B
  bool no_poly = false;          // -P
  bool no_node = false;          // -N
  bool no_ele = false;           // -E
  bool no_iteration = false;     // -I
  bool zero_based = false;       // -z
  int order = 1;                 // -o2

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
  bool exact_input = false;      // --exact-input: no snapping of vertices onto nearby segments
  bool triangle_messages = false;  // --triangle-messages: also Triangle's labelled statistics
  std::string size_field;        // --size-field=FILE: background mesh FILE.node/.ele of wanted edge lengths
  bool man = false;              // --man: print the manual page (roff) and exit
  bool version = false;          // --version: print the version and exit

  // How to run.
  bool check = false;            // -C
  bool quiet = false;            // -Q
  int verbose = 0;               // -V, -VV, ...
  bool help = false;             // -h
  int threads = 0;               // --threads=N; 0: all cores (threads_to_use)
  int progress = 0;              // --progress 1, --no-progress -1; 0: after 2 s of work, not with -Q

  std::string input;             // the input file as given
  std::string command_line;      // every argument, space-separated (for the JSON report)
  std::vector<std::string> notices;  // letters Triangle accepts that deltri reads its own way (-L, -w, -o3, ...)
};

// The threads a run may use: --threads=N, or every core the machine reports (at least one).
int threads_to_use(const Switches& sw);

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
