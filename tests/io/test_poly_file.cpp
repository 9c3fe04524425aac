// .poly reading and writing.
#include "harness/check.h"
#include "harness/id_literals.h"
#include "io/poly_file.h"
#include "io_test_util.h"

using namespace deltri;

namespace {

std::string poly_error(const std::string& name, const std::string& text) {
  const std::string path = iotest::write_file(name, text);
  return iotest::input_error([&] { read_poly_file(path); });
}

std::string where(const std::string& name, int line) {
  return (iotest::scratch_dir() / name).string() + ":" + std::to_string(line) + ":";
}

const char* kSquare =
    "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n"
    "4 1\n1 1 2 5\n2 2 3 0\n3 3 4 0\n4 4 1 0\n"
    "1\n1 0.5 0.5\n";

}  // namespace

TEST(poly_reads_all_sections) {
  const Pslg p = read_poly_file(iotest::write_file("sq.poly", std::string(kSquare) + "2\n1 0.2 0.2 7 0.01\n2 0.8 0.8 9\n"));
  CHECK(p.has_segment_section);
  CHECK_EQ(p.points.size(), 4u);
  REQUIRE(p.segments.size() == 4);
  CHECK(p.has_segment_markers);
  CHECK_EQ(p.segments[0].a, 0u);
  CHECK_EQ(p.segments[0].b, 1u);
  CHECK_EQ(p.segments[0].marker, 5);
  CHECK_EQ(p.segments[3].b, 0u);
  REQUIRE(p.holes.size() == 1);
  CHECK(p.holes[0] == (Point{0.5, 0.5}));
  REQUIRE(p.regions.size() == 2);
  CHECK_EQ(p.regions[0].attribute, 7.0);
  CHECK_EQ(p.regions[0].max_area, 0.01);
  CHECK_EQ(p.regions[1].max_area, 9.0);  // one value serves as both, as in Triangle
}

TEST(poly_without_regions_and_zero_based) {
  const Pslg p = read_poly_file(iotest::write_file("z.poly", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 2\n0\n"));
  CHECK_EQ(p.first_index, 0);
  REQUIRE(p.segments.size() == 1);
  CHECK_EQ(p.segments[0].b, 2u);
  CHECK(!p.has_segment_markers);
  CHECK(p.holes.empty());
  CHECK(p.regions.empty());
}

TEST(poly_takes_vertices_from_node_file) {
  iotest::write_file("sep.node", "3 2 0 1\n0 0 0 3\n1 1 0 3\n2 0 1 3\n");
  const Pslg p = read_poly_file(iotest::write_file("sep.poly", "0 2 0 0\n1 0\n0 0 1\n0\n"));
  CHECK_EQ(p.points.size(), 3u);
  CHECK_EQ(p.first_index, 0);
  CHECK(p.has_markers);
  CHECK_EQ(p.segments.size(), 1u);
  CHECK(poly_error("nosep.poly", "0 2 0 0\n0\n0\n").find("nosep.node") != std::string::npos);
}

TEST(poly_errors_name_file_and_line) {
  const std::string base = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n";
  CHECK(poly_error("p1.poly", base).starts_with(where("p1.poly", 5) + " unexpected end of file: the segment header"));
  CHECK(read_poly_file(iotest::write_file("p4.poly", base + "1 0\n1 2 2\n0\n")).segments.size() == 1u);  // zero length: legal, ignored later
  CHECK(poly_error("p6.poly", base + "2 0\n1 1 2\n").starts_with(where("p6.poly", 7) + " unexpected end of file"));
  CHECK(poly_error("p7.poly", base + "1 0\n1 1 2\n").starts_with(where("p7.poly", 7) + " unexpected end of file: the hole header"));
  CHECK(poly_error("p8.poly", base + "1 0\n1 1 2\n1\n1 x 0\n").starts_with(where("p8.poly", 9) + " hole 1: x coordinate is not a number: 'x'"));
  CHECK(poly_error("p9.poly", base + "1 0\n1 1 2\n0\n1\n1 0 0\n").starts_with(where("p9.poly", 10) + " region 1: attribute is missing"));
  CHECK(poly_error("p10.poly", base + "1 0\n1 1 2\n0\n2\n1 0 0 1 1\n").starts_with(where("p10.poly", 10) + " unexpected end of file"));
}

// As in Triangle: a segment naming no vertex is dropped, a missing trailing segment marker is 0,
// each with a warning naming the line. Vertex indices out of sequence are an error once segments
// refer to vertices by number.
TEST(poly_lenient_reading_warns) {
  const std::string base = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n";
  const std::string p2 = iotest::write_file("p2.poly", base + "3 1\n1 1 5 0\n2 0 2 4\n3 2 3\n0\n");
  const Pslg p = read_poly_file(p2);
  REQUIRE(p.segments.size() == 1u);
  CHECK_EQ(p.segments[0].a, 1u);
  CHECK_EQ(p.segments[0].b, 2u);
  CHECK_EQ(p.segments[0].marker, 0);
  REQUIRE(p.read_warnings.size() == 2u);
  CHECK(p.read_warnings[0].starts_with(p2 + ":7: segment 1: second endpoint 5 is not a vertex (vertices are numbered 1 to 4): "
                                       "2 segments naming no vertex dropped"));
  CHECK(p.read_warnings[1].starts_with(p2 + ":9: 1 segment has no boundary marker: 0 assumed"));
  const std::string gap = "3 2 0 0\n1 0 0\n2 1 0\n4 0 1\n";
  CHECK(poly_error("gap.poly", gap + "1 0\n1 1 2\n0\n").starts_with(where("gap.poly", 4) + " vertex index 4 is out of sequence: expected 3 (the segments name"));
  CHECK(read_poly_file(iotest::write_file("gap0.poly", gap + "0 0\n0\n")).read_warnings.size() == 1u);
  // "010" names vertex ten.
  std::string ten = "10 2 0 0\n";
  for (int i = 1; i <= 10; ++i) ten += std::to_string(i) + " " + std::to_string(i) + " " + std::to_string(i * i) + "\n";
  const Pslg t = read_poly_file(iotest::write_file("ten.poly", ten + "1 0\n1 1 010\n0\n"));
  REQUIRE(t.segments.size() == 1u);
  CHECK_EQ(t.segments[0].b, 9u);
  CHECK(t.read_warnings.empty());
}

TEST(poly_writer_lists_live_subsegments_once) {
  Mesh m = iotest::two_triangles();
  m.enable_subsegments();
  m.subsegments = {{0_v, 1_v, 0, 0}, {1_v, 2_v, 4, 1}, {2_v, 0_v, 0, 2}, {9_v, 9_v, 3, 3}};  // the last is gone
  m.set_subsegment(edge_of(0_t, 0), 0_s);
  m.set_subsegment(edge_of(0_t, 1), 1_s);
  m.set_subsegment(edge_of(0_t, 2), 2_s);  // the shared diagonal: interior, marker 0
  std::string text;
  write_poly_file(text, m, {1, true, nullptr, false}, {{0.25, 0.75}}, {{{0.5, 0.25}, 2.0, -1.0}});
  CHECK_EQ(text,
           "0 2 0 1\n"
           "3 1\n1 1 2 1\n2 2 3 4\n3 3 1 0\n"
           "1\n1 0.25 0.75\n"
           "1\n1 0.5 0.25 2 -1\n");
  text.clear();
  write_poly_file(text, m, {0, false, nullptr, true}, {});
  CHECK_EQ(text, "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n3 0\n0 0 1\n1 1 2\n2 2 0\n0\n");
  const Pslg back = read_poly_file(iotest::write_file("back.poly", text));
  CHECK_EQ(back.segments.size(), 3u);
  CHECK_EQ(back.points.size(), 4u);
}
