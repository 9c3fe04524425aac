#include "options/switch_table.h"

#include <array>
#include <limits>
#include <string_view>
#include <utility>

#include "util/errors.h"

namespace deltri {
namespace {

using S = Switches;

void set_q(S& s, bool has, double v) {
  s.quality = true;
  if (has) s.min_angle = v;
}
void set_a(S& s, bool has, double v) {
  if (!has) {
    s.variable_area = true;
    return;
  }
  if (!(v > 0.0)) throw RefusedSwitchError("-a: the maximum area must be a positive number, e.g. -a0.1");
  s.fixed_area = true;
  s.max_area = v;
}
void set_u(S& s, bool has, double v) {
  if (!has) return;  // bare -u: the parser has chosen the stock or the caller's test
  if (!(v > 0.0)) throw UsageError("-u: give the maximum edge length, e.g. -u0.05");
  s.user_test = true;
  s.max_edge_length = v;
}
// A count past what a long holds (-S2000777777777777777777) is no limit in practice; casting
// such a double to long is undefined behaviour (fuzz_library, run F14), so it is clamped first.
void set_S(S& s, bool has, double v) {
  constexpr double kLongLimit = 9.2e18;  // just below 2^63
  s.max_steiner = !has ? 0 : v < kLongLimit ? static_cast<long>(v) : std::numeric_limits<long>::max();
}
void set_o(S& s, bool has, double v) {
  if (has && v == 2.0) {
    s.order = 2;
    return;
  }
  // Triangle ignores any other -o; so does deltri, saying so.
  s.notices.push_back("-o" + (has ? std::to_string(static_cast<long long>(v)) : std::string()) +
                      ": only -o2 (six-node triangles) exists; ignored (three-node triangles)");
}

constexpr std::array kTable = {
    SwitchRow{'p', ArgKind::None, "", "read a PSLG (.poly) and build its constrained Delaunay triangulation",
              [](S& s, bool, double) { s.poly = true; }},
    SwitchRow{'r', ArgKind::None, "", "refine a previous mesh (.node and .ele)",
              [](S& s, bool, double) { s.refine = true; }},
    SwitchRow{'q', ArgKind::OptionalReal, "angle", "quality mesh: no angle below `angle` degrees (default 20)", set_q},
    SwitchRow{'a', ArgKind::OptionalReal, "area", "maximum triangle area; bare: regional or .area constraints", set_a},
    SwitchRow{'u', ArgKind::OptionalReal, "length",
              "size test: no edge longer than `length`; bare: Triangle's stock test (split while the longest edge squared "
              "exceeds 0.05 (x^2 + y^2) + 0.02 at every corner (x, y))", set_u},
    SwitchRow{'k', ArgKind::None, "", "Steiner points at circumcentres only (no off-centres)",
              [](S& s, bool, double) { s.circumcenters_only = true; }},
    SwitchRow{'A', ArgKind::None, "", "give each triangle the attribute of its region",
              [](S& s, bool, double) { s.regional_attributes = true; }},
    SwitchRow{'c', ArgKind::None, "", "keep the convex hull: enclose it with segments",
              [](S& s, bool, double) { s.convex_hull = true; }},
    SwitchRow{'D', ArgKind::None, "", "conforming Delaunay: every triangle truly Delaunay",
              [](S& s, bool, double) { s.conforming_delaunay = true; }},
    SwitchRow{'j', ArgKind::None, "", "jettison vertices no triangle uses from the output .node",
              [](S& s, bool, double) { s.jettison = true; }},
    SwitchRow{'e', ArgKind::None, "", "write the edges (.edge)",
              [](S& s, bool, double) { s.edges = true; }},
    SwitchRow{'v', ArgKind::None, "", "write the Voronoi diagram (.v.node, .v.edge)",
              [](S& s, bool, double) { s.voronoi = true; }},
    SwitchRow{'n', ArgKind::None, "", "write the neighbours of each triangle (.neigh)",
              [](S& s, bool, double) { s.neighbors = true; }},
    SwitchRow{'g', ArgKind::None, "", "write the mesh for Geomview (.off)",
              [](S& s, bool, double) { s.geomview = true; }},
    SwitchRow{'B', ArgKind::None, "", "no boundary markers in the output files",
              [](S& s, bool, double) { s.no_markers = true; }},
    SwitchRow{'P', ArgKind::None, "", "do not write the output .poly",
              [](S& s, bool, double) { s.no_poly = true; }},
    SwitchRow{'N', ArgKind::None, "", "do not write the output .node",
              [](S& s, bool, double) { s.no_node = true; }},
    SwitchRow{'E', ArgKind::None, "", "do not write the output .ele",
              [](S& s, bool, double) { s.no_ele = true; }},
    SwitchRow{'I', ArgKind::None, "", "no iteration numbers: write name.ele rather than name.1.ele",
              [](S& s, bool, double) { s.no_iteration = true; }},
    SwitchRow{'O', ArgKind::None, "", "ignore the holes of the .poly",
              [](S& s, bool, double) { s.ignore_holes = true; }},
    SwitchRow{'X', ArgKind::None, "", "accepted for compatibility; arithmetic stays exact",
              [](S& s, bool, double) { s.inexact = true; }},
    SwitchRow{'z', ArgKind::None, "", "number everything from zero",
              [](S& s, bool, double) { s.zero_based = true; }},
    SwitchRow{'o', ArgKind::OptionalInt, "2", "-o2: six-node (quadratic) triangles", set_o},
    SwitchRow{'Y', ArgKind::None, "", "no Steiner points on boundary segments; -YY: on no segment",
              [](S& s, bool, double) { ++s.no_boundary_steiner; }},
    SwitchRow{'S', ArgKind::OptionalInt, "n", "at most n Steiner points (bare: none)", set_S},
    SwitchRow{'i', ArgKind::None, "", "incremental Delaunay triangulation instead of divide and conquer",
              [](S& s, bool, double) { s.algorithm = DelaunayAlgorithm::Incremental; }},
    SwitchRow{'F', ArgKind::None, "", "Fortune's sweepline Delaunay triangulation instead of divide and conquer",
              [](S& s, bool, double) {
                s.sweepline = true;
                s.algorithm = DelaunayAlgorithm::Sweepline;
              }},
    SwitchRow{'l', ArgKind::None, "", "divide and conquer with vertical cuts only",
              [](S& s, bool, double) { s.algorithm = DelaunayAlgorithm::VerticalCuts; }},
    SwitchRow{'s', ArgKind::None, "", "insert segments by splitting them at midpoints (conforming), not by flips",
              [](S& s, bool, double) { s.split_segments = true; }},
    SwitchRow{'C', ArgKind::None, "", "check the final mesh for consistency and the Delaunay property",
              [](S& s, bool, double) { s.check = true; }},
    SwitchRow{'Q', ArgKind::None, "", "quiet: no summary, notices or report; warnings and errors still go to stderr",
              [](S& s, bool, double) { s.quiet = true; }},
    SwitchRow{'V', ArgKind::None, "", "verbose: stage timings, counts, quality statistics, predicate counters",
              [](S& s, bool, double) { ++s.verbose; }},
    SwitchRow{'h', ArgKind::None, "", "print this help and exit",
              [](S& s, bool, double) { s.help = true; }},
};

void request(Switches::FileRequest& r, const std::string* value, const char* option) {
  if (value && value->empty()) throw UsageError(std::string("--") + option + "=: give a file name, or - for standard output");
  r.wanted = true;
  r.path = value ? *value : std::string();
}

void set_queue(S& s, const std::string* v) {
  static constexpr std::pair<std::string_view, QueueOrder> kOrders[] = {
      {"ratio", QueueOrder::Ratio}, {"paper", QueueOrder::Paper},         {"edge", QueueOrder::Edge},
      {"fifo", QueueOrder::Fifo},   {"heap", QueueOrder::RatioHeap}, {"paper-heap", QueueOrder::PaperHeap}};
  for (const auto& [name, order] : kOrders)
    if (*v == name) {
      s.queue_order = order;
      return;
    }
  throw UsageError("--queue=" + *v + ": the order is ratio, paper, edge, fifo, heap or paper-heap");
}

void set_msh_format(S& s, const std::string* v) {
  const std::string& f = *v;
  const std::size_t comma = f.find(',');
  const std::string version = f.substr(0, comma), encoding = comma == std::string::npos ? "" : f.substr(comma + 1);
  if ((version != "2.2" && version != "4.1") || (comma != std::string::npos && encoding != "binary" && encoding != "ascii"))
    throw UsageError("--msh-format=" + f + ": give 2.2 or 4.1, optionally followed by ,binary (e.g. --msh-format=4.1,binary)");
  s.msh_version = version == "2.2" ? 22 : 41;
  s.msh_binary = encoding == "binary";
}

// The value of a switch argument that is only decimal digits, at most max_digits of them; -1 for
// anything else (a sign, a point, an empty or longer text).
long long whole_number(const std::string& text, std::size_t max_digits) {
  const bool digits = !text.empty() && text.size() <= max_digits && text.find_first_not_of("0123456789") == std::string::npos;
  return digits ? std::stoll(text) : -1;
}

void set_domain_tag(S& s, const std::string* v) {
  const std::string& n = *v;
  const long long tag = whole_number(n, 10);
  if (tag < 1 || tag > 2147483647) throw UsageError("--domain-tag=" + n + ": give a whole number from 1 to 2147483647");
  s.domain_tag = tag;
}

void set_vtu_format(S& s, const std::string* v) {
  if (*v != "ascii" && *v != "binary") throw UsageError("--vtu-format=" + *v + ": give ascii or binary");
  s.vtu_binary = *v == "binary";
}

void set_threads(S& s, const std::string* v) {
  const std::string& n = *v;
  const int threads = static_cast<int>(whole_number(n, 4));
  if (threads < 1) throw UsageError("--threads=" + n + ": give a whole number of threads from 1 to 9999");
  s.threads = threads;
}

void set_algorithm(S& s, const std::string* v) {
  static constexpr std::pair<std::string_view, RefinementAlgorithm> kNames[] = {
      {"terminator", RefinementAlgorithm::Terminator}, {"ruppert", RefinementAlgorithm::Ruppert},
      {"chew", RefinementAlgorithm::Chew}};
  for (const auto& [name, algorithm] : kNames)
    if (*v == name) {
      s.refinement = algorithm;
      return;
    }
  throw UsageError("--algorithm=" + *v + ": the algorithm is terminator, ruppert or chew");
}

void set_interior_bound(S& s, const std::string* v) {
  if (*v != "1" && *v != "2") throw UsageError("--interior-bound=" + *v + ": give 1 or 2 (Sec. 7.2's two strategies)");
  s.interior_bound = *v == "1" ? 1 : 2;
}

void set_smooth(S& s, const std::string* v) {
  if (!v) {
    s.smooth_rounds = 3;
    return;
  }
  const int rounds = static_cast<int>(whole_number(*v, 4));
  if (rounds < 1) throw UsageError("--smooth=" + *v + ": give a whole number of rounds from 1 to 9999");
  s.smooth_rounds = rounds;
}

// A >= 90: below it the bound would forbid right angles that inputs such as a square need, and
// refinement is not known to reach it.
void set_max_angle(S& s, const std::string* v) {
  const std::string& a = *v;
  const bool number = !a.empty() && a.size() <= 24 && a.find_first_not_of("0123456789.") == std::string::npos &&
                      a.find('.') == a.rfind('.') && a != ".";
  const double degrees = number ? std::stod(a) : -1.0;
  if (!number || !(degrees >= 90.0 && degrees < 180.0))
    throw UsageError("--max-angle=" + a + ": give the largest angle in degrees, at least 90 and below 180");
  s.max_angle = degrees;
}

void set_steiner(S& s, const std::string* v) {
  static constexpr std::pair<std::string_view, SteinerPolicy> kNames[] = {
      {"offcentre", SteinerPolicy::OffCentre}, {"circumcentre", SteinerPolicy::Circumcentre},
      {"optimal", SteinerPolicy::Optimal}};
  for (const auto& [name, policy] : kNames)
    if (*v == name) {
      s.steiner = policy;
      s.circumcenters_only = s.circumcenters_only || policy == SteinerPolicy::Circumcentre;
      return;
    }
  throw UsageError("--steiner=" + *v + ": the policy is offcentre, circumcentre or optimal");
}

constexpr std::array kLongOptions = {
    LongOption{"msh", "FILE", true, "also write the mesh as Gmsh MSH (version and encoding: --msh-format); FILE - is standard output",
               [](S& s, const std::string* v) { request(s.msh, v, "msh"); }},
    LongOption{"msh-format", "FORMAT", false,
               "the --msh version and encoding: 2.2 (default; GetDP and FreeFem++ read it), 4.1, "
               "2.2,binary or 4.1,binary",
               set_msh_format},
    LongOption{"domain-tag", "N", false,
               "the --msh physical tag of the domain (default 1000000000, which no marker's tag can be); with -A "
               "attribute a is tag N + a. Refused when a marker's tag is the same",
               set_domain_tag},
    LongOption{"vtu", "FILE", true, "also write the mesh as VTK XML unstructured grid (.vtu); FILE - is standard output",
               [](S& s, const std::string* v) { request(s.vtu, v, "vtu"); }},
    LongOption{"vtu-format", "ENCODING", false, "the --vtu encoding: ascii (default) or binary (raw appended data)",
               set_vtu_format},
    LongOption{"svg", "FILE", true, "also draw the mesh as SVG, triangles shaded by smallest angle; FILE - is standard output",
               [](S& s, const std::string* v) { request(s.svg, v, "svg"); }},
    LongOption{"svg-numbers", "", false, "number the vertices in the SVG picture",
               [](S& s, const std::string*) { s.svg_numbers = true; }},
    LongOption{"stl", "FILE", true, "for facets in 3-D (TetGen .poly/.smesh): also write the surface as ASCII STL; FILE - is standard output",
               [](S& s, const std::string* v) { request(s.stl, v, "stl"); }},
    LongOption{"json", "FILE", true, "also write a JSON report of the run; FILE - is standard output",
               [](S& s, const std::string* v) { request(s.json, v, "json"); }},
    LongOption{"each", "", false,
               "mesh every input file named, one after the other, each as if it were alone on the command line "
               "(without it the last one named is the input, as in Triangle); the exit status is the first "
               "non-zero one, and the inputs that failed are counted at the end",
               [](S& s, const std::string*) { s.each = true; }},
    LongOption{"strict", "", false, "exit with status 3 when triangles miss the -q/-a/-u bounds for a reason other than a small "
               "input angle, when -D leaves subsegments not Delaunay, or when the mesh is empty (files are still written)",
               [](S& s, const std::string*) { s.strict = true; }},
    LongOption{"exact-input", "", false,
               "take every coordinate exactly as written: a vertex within 4 ulps of a segment is not "
               "placed on it (by default it is, and the segment is split there, with a warning)",
               [](S& s, const std::string*) { s.exact_input = true; }},
    LongOption{"triangle-messages", "", false,
               "after the summary, print the counts in Triangle's words (Input vertices:, Mesh triangles:, "
               "Mesh edges:, ...) and, with -V, its quality statistics (Smallest angle:, ...)",
               [](S& s, const std::string*) { s.triangle_messages = true; }},
    LongOption{"size-field", "FILE", false,
               "refine to the background size field FILE.node (first vertex attribute: the wanted edge length h) "
               "and FILE.ele: a triangle is split while its area exceeds sqrt(3)/4 h^2, h interpolated at its centroid",
               [](S& s, const std::string* v) { s.size_field = *v; }},
    LongOption{"queue", "ORDER", false,
               "which bad triangle refinement splits first: ratio (default: shortest edge first, eight "
               "levels per octave of its length, 32 above -q30), paper (worst radius-edge ratio first, as Shewchuk 2001), "
               "edge (shortest edge first at a coarser resolution, as Triangle 1.6), fifo, "
               "heap or paper-heap (exact heaps of the default and paper keys)",
               set_queue},
    LongOption{"decline-cluster-splits", "", false,
               "let SPLITPERMITTED (Shewchuk 2001, Fig. 38) decline to split subsegment clusters",
               [](S& s, const std::string*) { s.decline_cluster_splits = true; }},
    LongOption{"algorithm", "NAME", false,
               "the refinement algorithm of Shewchuk 2001: terminator (default; Sec. 6.3-6.4), ruppert (Sec. 3: "
               "diametral circles, midpoints; proven to -q20.7) or chew (Sec. 4: constrained Delaunay; proven to -q26.5)",
               set_algorithm},
    LongOption{"interior-bound", "N", false,
               "with ruppert or chew, 30 degrees away from segments (Sec. 7.2): 1 for triangles with no vertex in a "
               "segment interior, 2 by splitting only subsegments whose midpoint is no closer than the triangle's shortest edge",
               set_interior_bound},
    LongOption{"max-angle", "A", false,
               "refine until every triangle's largest angle is at most A degrees (90 <= A < 180; with -q, -a, -u), "
               "apart from angles between two input segments that are larger still",
               set_max_angle},
    LongOption{"range-restricted", "", false,
               "range-restricted segment splitting (Shewchuk 2001, Sec. 7.3): subsegment lengths c 2^x, "
               "c in [1, sqrt 3) with lenses (with -D or ruppert: [1, sqrt 2)); an illegal length is split once, unevenly",
               [](S& s, const std::string*) { s.range_restricted = true; }},
    LongOption{"corner-lopping", "", false,
               "with -p: corner-lopping (Shewchuk 2001, Sec. 6.1): shield each input angle under 60 degrees at "
               "radius lfs/3, refine around the shields, fill the lopped corners with fans",
               [](S& s, const std::string*) { s.corner_lopping = true; }},
    LongOption{"smooth", "N", true,
               "after refinement, N rounds (default 3) of moving the free interior vertices towards their optimal "
               "Delaunay position, each move kept only if its star's smallest angle rises and every bound and the "
               "constrained Delaunay property still hold",
               set_smooth},
    LongOption{"steiner", "POLICY", false,
               "where a skinny triangle's new vertex goes: offcentre (Ungor's off-centre; the default below -q33, "
               "and up to -q34 with -Y/-YY), circumcentre (as -k) or optimal (Erten and Ungor's locally optimal "
               "point in the petal of the shortest edge; the default from -q33)",
               set_steiner},
    LongOption{"threads", "N", false,
               "refine large meshes (and build the triangulation, write the files) on up to N threads (default: all cores); "
               "the output is the same for every N",
               set_threads},
    LongOption{"progress", "", false,
               "show progress on standard error from the start, also with -Q (by default: after 2 s of work, "
               "not with -Q); in place on a terminal, else one line per stage",
               [](S& s, const std::string*) { s.progress = 1; }},
    LongOption{"no-progress", "", false, "show no progress on standard error",
               [](S& s, const std::string*) { s.progress = -1; }},
    LongOption{"man", "", false, "print the manual page (roff) and exit",
               [](S& s, const std::string*) { s.man = true; }},
    LongOption{"version", "", false, "print the version and exit",
               [](S& s, const std::string*) { s.version = true; }},
    LongOption{"help", "", false, "print this help and exit (as -h)",
               [](S& s, const std::string*) { s.help = true; }},
};

}  // namespace

std::span<const SwitchRow> switch_table() { return kTable; }
std::span<const LongOption> long_option_table() { return kLongOptions; }

}  // namespace deltri
