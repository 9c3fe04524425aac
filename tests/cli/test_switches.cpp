// The switch parser against Triangle's syntax: letters run together, numbers glued to their
// letter, repeated letters, and clear errors for what is not a switch.
#include <limits>
#include <string>
#include <vector>

#include "options/switch_table.h"
#include "options/switches.h"
#include "harness/check.h"
#include "util/errors.h"

using namespace deltri;

namespace {

Switches parse(std::vector<const char*> args) {
  args.insert(args.begin(), "deltri");
  return parse_switches(static_cast<int>(args.size()), args.data());
}

std::string usage_error(std::vector<const char*> args) {
  try {
    parse(std::move(args));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(letters_and_numbers_run_together) {
  const Switches s = parse({"-pq30a0.1eznQ", "box.poly"});
  CHECK(s.poly);
  CHECK(s.quality);
  CHECK_EQ(s.min_angle, 30.0);
  CHECK(s.fixed_area);
  CHECK_EQ(s.max_area, 0.1);
  CHECK(s.edges);
  CHECK(s.zero_based);
  CHECK(s.neighbors);
  CHECK(s.quiet);
  CHECK_EQ(s.input, std::string("box.poly"));
}

TEST(defaults_and_bare_letters) {
  const Switches s = parse({"-q", "x"});
  CHECK(s.quality);
  CHECK_EQ(s.min_angle, 20.0);
  const Switches bare_a = parse({"-pa", "x"});
  CHECK(bare_a.variable_area);
  CHECK(!bare_a.fixed_area);
  const Switches both = parse({"-a0.5", "-a", "x"});
  CHECK(both.variable_area && both.fixed_area);
  CHECK_EQ(parse({"-S", "x"}).max_steiner, 0L);
  CHECK_EQ(parse({"-S25", "x"}).max_steiner, 25L);
  CHECK_EQ(parse({"x"}).max_steiner, -1L);
  // Past a long's range: no limit in practice, not a cast out of range (fuzz_library F14).
  CHECK_EQ(parse({"-S2000777777777777777777", "x"}).max_steiner, std::numeric_limits<long>::max());
  CHECK_EQ(parse({"-S9223372036854775807", "x"}).max_steiner, std::numeric_limits<long>::max());
}

TEST(exponent_only_when_a_digit_follows) {
  CHECK_EQ(parse({"-a1e-5", "x"}).max_area, 1e-5);
  const Switches s = parse({"-a0.1e", "x"});
  CHECK_EQ(s.max_area, 0.1);
  CHECK(s.edges);
  const Switches t = parse({"-q30e", "x"});
  CHECK_EQ(t.min_angle, 30.0);
  CHECK(t.edges);
}

TEST(repeated_letters_count) {
  const Switches s = parse({"-YYVVV", "x"});
  CHECK_EQ(s.no_boundary_steiner, 2);
  CHECK_EQ(s.verbose, 3);
}

TEST(algorithms_and_order) {
  CHECK(parse({"-i", "x"}).algorithm == DelaunayAlgorithm::Incremental);
  CHECK(parse({"-l", "x"}).algorithm == DelaunayAlgorithm::VerticalCuts);
  CHECK(parse({"x"}).algorithm == DelaunayAlgorithm::DivideAndConquer);
  CHECK(parse({"-F", "x"}).sweepline);
  CHECK_EQ(parse({"-o2", "x"}).order, 2);
}

TEST(last_name_wins_and_switch_words_split) {
  const Switches s = parse({"-p", "a.poly", "-e", "b.poly"});
  CHECK(s.poly && s.edges);
  CHECK_EQ(s.input, std::string("b.poly"));
}

TEST(errors_name_the_switch) {
  CHECK(usage_error({"-p2", "x"}).rfind("-2: unknown switch", 0) == 0);
  CHECK(usage_error({"-px", "x"}).rfind("-x:", 0) == 0);
  CHECK(usage_error({"-a0", "x"}).rfind("-a:", 0) == 0);
  CHECK(usage_error({"-q75", "x"}).rfind("-q:", 0) == 0);
  CHECK(usage_error({"-u0", "x"}).rfind("-u:", 0) == 0);
  CHECK(usage_error({"-rI", "x"}).rfind("-I:", 0) == 0);
  CHECK(usage_error({"-p", "x"}).empty());
}

// Issue 46: what Triangle 1.6 accepts runs, with a notice where deltri reads it its own way.
TEST(letters_triangle_accepts_run_with_a_notice) {
  const Switches u = parse({"-pqu", "x"});
  CHECK(u.stock_size_test && !u.user_test && u.notices.empty());  // bare -u: Triangle's stock test
  const Switches length = parse({"-pqu0.05", "x"});
  CHECK(!length.stock_size_test && length.user_test && length.max_edge_length == 0.05);  // deltri's -u<length>
  const Switches l = parse({"-pL", "x"});
  CHECK(l.conforming_delaunay && l.notices.size() == 1);  // Triangle 1.6's synonym of -D
  CHECK_EQ(parse({"-pw", "x"}).notices.size(), std::size_t{1});
  CHECK_EQ(parse({"-pW", "x"}).notices.size(), std::size_t{1});
  const Switches o3 = parse({"-po3", "x"});
  CHECK(o3.order == 1 && o3.notices.size() == 1);
  const Switches s25 = parse({"-pS2.5q", "x"});
  CHECK(s25.max_steiner == 2 && s25.quality && s25.notices.size() == 1);
  CHECK_EQ(s25.notices[0], std::string("-S2.5: read as -S2, as Triangle does (a whole number)"));
  const Switches qdot = parse({"-pq.", "x"});
  CHECK(qdot.quality && qdot.min_angle == 0.0 && qdot.notices.size() == 1);
  CHECK(parse({"-H"}).help && parse({"-?"}).help);
}

// The library's switch strings go through this parser too: there a bare u asks for the caller's
// size function, and the long options are read as options (their letters are no switches).
TEST(library_source_takes_a_bare_u_and_long_options) {
  const char* args[] = {"deltri", "-pqu", "--range-restricted", "--threads=2", "input"};
  const Switches s = parse_switches(5, args, SwitchSource::Library);
  CHECK(s.poly && s.quality && s.caller_size_test && !s.user_test);
  CHECK(s.range_restricted && s.threads == 2);
  CHECK(!s.refine && !s.voronoi);
  const char* sized[] = {"deltri", "-pu0.5", "input"};
  const Switches t = parse_switches(3, sized, SwitchSource::Library);
  CHECK(t.user_test && !t.caller_size_test && t.max_edge_length == 0.5);
}

TEST(help_lists_every_switch_of_the_table) {
  const std::string help = help_text();
  for (const SwitchRow& row : switch_table()) {
    CHECK(help.find(std::string("  -") + row.letter) != std::string::npos);
    CHECK(help.find(row.help) != std::string::npos);
  }
}

TEST(long_options_with_and_without_a_file) {
  const Switches s = parse({"-pq30", "--msh", "--vtu=out.vtu", "--svg=-", "--svg-numbers", "--json", "--strict", "-", "x"});
  CHECK(s.msh.wanted && s.msh.path.empty());
  CHECK(s.vtu.wanted && s.vtu.path == "out.vtu");
  CHECK(s.svg.wanted && s.svg.path == "-");
  CHECK(s.svg_numbers && s.strict);
  CHECK(s.json.wanted && s.json.path.empty());
  CHECK(uses_standard_output(s));
  CHECK(!uses_standard_output(parse({"--msh=a.msh", "x"})));
  CHECK(!parse({"x"}).msh.wanted);
  // "-" alone is the input (standard input), not a switch word.
  CHECK_EQ(parse({"-p", "-"}).input, std::string("-"));
  CHECK(parse({"--man"}).man);
  CHECK(parse({"--help"}).help);
}

TEST(queue_orders_by_name_and_the_ratio_default) {
  CHECK(parse({"x"}).queue_order == QueueOrder::ShortestEdge);
  CHECK(parse({"--queue=paper", "x"}).queue_order == QueueOrder::Paper);
  CHECK(parse({"--queue=edge", "x"}).queue_order == QueueOrder::Edge);
  CHECK(parse({"--queue=fifo", "x"}).queue_order == QueueOrder::Fifo);
  CHECK(parse({"--queue=heap", "x"}).queue_order == QueueOrder::ShortestEdgeHeap);
  CHECK(parse({"--queue=paper-heap", "x"}).queue_order == QueueOrder::PaperHeap);
  CHECK(parse({"--queue=edge", "--queue=ratio", "x"}).queue_order == QueueOrder::ShortestEdge);
  CHECK(usage_error({"--queue=worst", "x"}).find("ratio, paper, edge, fifo, heap or paper-heap") != std::string::npos);
}

TEST(steiner_policies_by_name) {
  CHECK(parse({"x"}).steiner == SteinerPolicy::Automatic);
  CHECK(parse({"--steiner=optimal", "x"}).steiner == SteinerPolicy::Optimal);
  CHECK(parse({"--steiner=offcentre", "x"}).steiner == SteinerPolicy::OffCentre);
  CHECK(!parse({"--steiner=offcentre", "x"}).circumcenters_only);
  CHECK(parse({"--steiner=circumcentre", "x"}).circumcenters_only);  // as -k
  CHECK(usage_error({"--steiner=best", "x"}).find("offcentre, circumcentre or optimal") != std::string::npos);
  // Automatic: the off-centres below -q33, locally optimal points from it (above -q34 under -Y/-YY).
  CHECK(resolved_policy(SteinerPolicy::Automatic, 32.9, false) == SteinerPolicy::OffCentre);
  CHECK(resolved_policy(SteinerPolicy::Automatic, 33.0, false) == SteinerPolicy::Optimal);
  CHECK(resolved_policy(SteinerPolicy::Automatic, 34.0, false) == SteinerPolicy::Optimal);
  CHECK(resolved_policy(SteinerPolicy::Automatic, 34.0, true) == SteinerPolicy::OffCentre);
  CHECK(resolved_policy(SteinerPolicy::Automatic, 34.5, true) == SteinerPolicy::Optimal);
  CHECK(resolved_policy(SteinerPolicy::Automatic, 34.5, false) == SteinerPolicy::Optimal);
  CHECK(resolved_policy(SteinerPolicy::OffCentre, 40.0, false) == SteinerPolicy::OffCentre);
}

TEST(long_option_errors) {
  CHECK_EQ(usage_error({"--mesh", "x"}), std::string("--mesh: unknown option (see deltri -h)"));
  CHECK_EQ(usage_error({"--strict=1", "x"}), std::string("--strict: takes no value"));
  CHECK(usage_error({"--msh=", "x"}).rfind("--msh=:", 0) == 0);
  CHECK(usage_error({"--msh=-", "--json=-", "x"}).find("only one of") != std::string::npos);
}

TEST(help_and_man_page_list_every_long_option) {
  const std::string help = help_text(), man = man_page();
  for (const LongOption& option : long_option_table()) {
    CHECK(help.find(std::string("  --") + option.name) != std::string::npos);
    CHECK(help.find(option.help) != std::string::npos);
    std::string escaped;  // roff writes every dash as \-
    for (const char* c = option.name; *c; ++c) escaped += *c == '-' ? std::string("\\-") : std::string(1, *c);
    CHECK(man.find(".B \\-\\-" + escaped) != std::string::npos);
  }
  for (const SwitchRow& row : switch_table()) CHECK(man.find(std::string(".B \\-") + row.letter) != std::string::npos);
  CHECK(man.rfind(".\\\"", 0) == 0);
  CHECK(man.find("\n.TH DELTRI 1") != std::string::npos);
}

TEST(the_last_input_named_is_the_input_and_each_takes_them_all) {
  const Switches s = parse({"-p", "a.poly", "b.poly"});
  CHECK(s.input == "b.poly");  // Triangle's rule
  CHECK(!s.each);
  const Switches e = parse({"-p", "--each", "a.poly", "b.poly", "--json"});
  CHECK(e.each);
  REQUIRE(e.inputs.size() == 2u);
  CHECK(e.inputs[0] == "a.poly" && e.inputs[1] == "b.poly");
  CHECK(usage_error({"-p", "--each", "--json=r.json", "a.poly", "b.poly"}).find("--each: --json=r.json names one file") == 0);
  CHECK(usage_error({"-p", "--each", "--msh=-", "a.poly", "b.poly"}).find("--each: --msh=- names one file") == 0);
  CHECK(usage_error({"-p", "--each", "--json=r.json", "a.poly"}).empty());  // one input: one file
  bool refused = false;
  try {
    const char* args[] = {"deltri", "-p", "--each"};
    parse_switches(3, args, SwitchSource::Library);
  } catch (const UsageError&) {
    refused = true;
  }
  CHECK(refused);
}
