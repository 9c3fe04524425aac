// .node reading and writing.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "harness/check.h"
#include "io/node_file.h"
#include "io_test_util.h"

using namespace deltri;

namespace {

std::string node_error(const std::string& name, const std::string& text) {
  const std::string path = iotest::write_file(name, text);
  return iotest::input_error([&] { read_node_file(path); });
}

bool starts_at(const std::string& message, const std::string& name, int line) {
  return message.starts_with((iotest::scratch_dir() / name).string() + ":" + std::to_string(line) + ":");
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(node_reads_all_fields_one_based) {
  const std::string path = iotest::write_file("full.node",
                                              "# a comment\n4 2 2 1\n1 0 0 10 11 5\n2 1.5 0 12 13 0\n"
                                              "3 1 1 14 15 -2  # end\n\n4, 0, 1, 16, 17, 7\n");
  const Pslg p = read_node_file(path);
  CHECK_EQ(p.first_index, 1);
  REQUIRE(p.points.size() == 4);
  CHECK(p.points[1] == (Point{1.5, 0}));
  CHECK_EQ(p.num_attributes, 2);
  CHECK(p.attributes == (std::vector<double>{10, 11, 12, 13, 14, 15, 16, 17}));
  CHECK(p.has_markers);
  CHECK(p.markers == (std::vector<int>{5, 0, -2, 7}));
  CHECK_EQ(p.source_name, path);
}

TEST(node_zero_based_and_short_header) {
  const Pslg p = read_node_file(iotest::write_file("short.node", "3\n0 0 0\n1 1 0\n2 0 1 99\n"));
  CHECK_EQ(p.first_index, 0);
  CHECK_EQ(p.points.size(), 3u);
  CHECK_EQ(p.num_attributes, 0);
  CHECK(!p.has_markers);
  CHECK(p.markers.empty());
}

TEST(node_errors_name_file_and_line) {
  CHECK(starts_at(node_error("e1.node", "3 3 0 0\n1 0 0\n2 1 0\n3 0 1\n"), "e1.node", 1));
  CHECK(starts_at(node_error("e2.node", "3 2 0 0\n1 0 0\n# c\n2 1\n3 0 1\n"), "e2.node", 4));
  CHECK(node_error("e2.node", "3 2 0 0\n1 0 0\n# c\n2 1\n3 0 1\n").find("vertex 2: y coordinate is missing") != std::string::npos);
  CHECK(starts_at(node_error("e5.node", "3 2 0 0\n1 0 0\n2 1 0\n"), "e5.node", 3));
  CHECK(node_error("e5.node", "3 2 0 0\n1 0 0\n2 1 0\n").find("unexpected end of file") != std::string::npos);
  CHECK(starts_at(node_error("e6.node", "3 2 1 0\n1 0 0 5\n2 1 0\n3 0 1 5\n"), "e6.node", 3));
  CHECK(starts_at(node_error("e7.node", "3 2 0 1\n1 0 0 1\n2 1 0 1.5\n3 0 1 1\n"), "e7.node", 3));
  CHECK(starts_at(node_error("e8.node", "3 2 0 2\n"), "e8.node", 1));
  CHECK(starts_at(node_error("e9.node", "\n\n2 2 0 0\n1 0 0\n2 1 0\n"), "e9.node", 3));
  CHECK(starts_at(node_error("e10.node", "3 2 0 0\n1 0 0\n2 1 nan\n3 0 1\n"), "e10.node", 3));
  CHECK(starts_at(node_error("e11.node", "-3 2 0 0\n"), "e11.node", 1));
  CHECK(starts_at(node_error("e12.node", "4000000000 2 0 0\n1 0 0\n"), "e12.node", 2));
  CHECK(node_error("e13.node", "") == (iotest::scratch_dir() / "e13.node").string() +
                                          ": unexpected end of file: the node header is missing");
}

// Read as Triangle reads them, with a warning naming the line: indices out of sequence (the
// vertices are numbered by their order), a first index other than 0 or 1 (the output numbering is
// then -z's), a missing trailing marker (0).
TEST(node_lenient_reading_warns) {
  const std::string gap = iotest::write_file("gap.node", "3 2 0 0\n1 0 0\n2 1 0\n4 0 1\n");
  const Pslg g = read_node_file(gap);
  CHECK_EQ(g.points.size(), 3u);
  CHECK_EQ(g.points[2].y, 1.0);
  CHECK(g.numbered_by_file);
  CHECK_EQ(g.irregular_index_line, 4);
  REQUIRE(g.read_warnings.size() == 1u);
  CHECK(g.read_warnings[0].starts_with(gap + ":4: vertex index 4 is out of sequence: expected 3"));
  const Pslg five = read_node_file(iotest::write_file("five.node", "3 2 0 0\n5 0 0\n6 1 0\n7 0 1\n"));
  CHECK(!five.numbered_by_file);
  CHECK_EQ(five.irregular_index_line, 2);
  REQUIRE(five.read_warnings.size() == 1u);
  CHECK(five.read_warnings[0].find("numbered 5, not 0 or 1") != std::string::npos);
  const std::string unmarked = iotest::write_file("unmarked.node", "3 2 1 1\n1 0 0 7 2\n2 1 0 8\n3 0 1 9\n");
  const Pslg m = read_node_file(unmarked);
  CHECK_EQ(m.markers.size(), 3u);
  CHECK_EQ(m.markers[0], 2);
  CHECK_EQ(m.markers[1], 0);
  CHECK_EQ(m.markers[2], 0);
  CHECK_EQ(m.attributes[1], 8.0);
  REQUIRE(m.read_warnings.size() == 1u);
  CHECK(m.read_warnings[0].starts_with(unmarked + ":3: 2 vertices have no boundary marker: 0 assumed"));
  // A regular file gives no warning; "010" is ten (decimal, not Triangle's octal).
  const Pslg ten = read_node_file(iotest::write_file("ten.node", "3 2 0 0\n0 010 0\n1 1 0\n2 0 1\n"));
  CHECK(ten.read_warnings.empty());
  CHECK_EQ(ten.points[0].x, 10.0);
}

TEST(node_round_trip_is_bit_exact) {
  std::mt19937_64 rng(7);
  Mesh m;
  m.num_attributes = 1;
  m.marker.assign(0, 0);
  std::vector<double> specials{-0.0, 0.0, 1e300, -1e300, 4.9e-324, 2.2250738585072014e-308, 2.225073858507201e-308,
                               std::numeric_limits<double>::max(), 0.1, 1.0 / 3.0, 123456789012345678.0, 5e-324};
  for (int i = 0; i < 2000; ++i) {
    double x, y;
    if (i < static_cast<int>(specials.size())) {
      x = specials[i];
      y = -specials[i];
    } else {
      std::uint64_t bx = rng(), by = rng();
      std::memcpy(&x, &bx, 8);
      std::memcpy(&y, &by, 8);
      if (!std::isfinite(x)) x = 1.5;
      if (!std::isfinite(y)) y = -2.5;
    }
    m.add_vertex({x, y}, VertexKind::Input);
    m.attributes.back() = x * 0.5;
  }
  m.marker.assign(m.vertex_count(), 0);
  m.marker[3] = -17;
  std::string text;
  write_node_file(text, m, {0, true, nullptr});
  const Pslg p = read_node_file(iotest::write_file("round.node", text));
  REQUIRE(p.points.size() == m.points.size());
  CHECK_EQ(p.first_index, 0);
  bool all_same = true;
  for (std::size_t i = 0; i < p.points.size(); ++i)
    all_same = all_same && same_bits(p.points[i].x, m.points[i].x) && same_bits(p.points[i].y, m.points[i].y) &&
               same_bits(p.attributes[i], m.attributes[i]);
  CHECK(all_same);
  CHECK_EQ(p.markers[3], -17);
}

TEST(node_writer_layout_numbering_and_jettison) {
  Mesh m = iotest::two_triangles();
  std::string text;
  write_node_file(text, m, {1, true, nullptr});
  CHECK_EQ(text, "4 2 0 1\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n");
  const std::vector<std::uint32_t> keep{0, kNone, 1, 2};
  text.clear();
  write_node_file(text, m, {0, false, &keep});
  CHECK_EQ(text, "3 2 0 0\n0 0 0\n1 1 1\n2 0 1\n");
}

TEST(node_large_file_parallel_path_matches_serial) {
  // Large enough for the split parse; errors in the second half must be reported as usual.
  std::string text = "# big\n200000 2 1 1\n";
  for (int i = 1; i <= 200000; ++i) {
    text += std::to_string(i) + " " + std::to_string(i * 0.25) + " " + std::to_string(-i) + " " +
            std::to_string(i % 7) + " " + std::to_string(i % 3) + "\n";
    if (i % 1000 == 0) text += "# comment\n\n";
  }
  const std::string path = iotest::write_file("big.node", text);
  const Pslg p = read_node_file(path);
  REQUIRE(p.points.size() == 200000);
  CHECK_EQ(p.points[150000].x, 150001 * 0.25);
  CHECK_EQ(p.points[199999].y, -200000.0);
  CHECK_EQ(p.attributes[123456], static_cast<double>(123457 % 7));
  CHECK_EQ(p.markers[199998], 199999 % 3);
  std::string broken = text;
  const std::size_t at = broken.find("\n180000 ");
  broken.replace(at + 1, 6, "180001");
  const long line = 1 + static_cast<long>(std::count(broken.begin(), broken.begin() + static_cast<long>(at) + 1, '\n'));
  // Out of sequence is read (numbered by position) with a warning naming the line.
  const std::string broken_path = iotest::write_file("big_broken.node", broken);
  const Pslg b = read_node_file(broken_path);
  CHECK_EQ(b.points.size(), 200000u);
  CHECK_EQ(b.points[179999].x, 180000 * 0.25);
  REQUIRE(b.read_warnings.size() == 1u);
  CHECK(b.read_warnings[0].starts_with(broken_path + ":" + std::to_string(line) +
                                       ": vertex index 180001 is out of sequence: expected 180000"));
  // One thread (--threads=1) reads the file whole and must find what the two halves found.
  for (const auto& [file, two] : {std::pair{path, &p}, std::pair{broken_path, &b}}) {
    const Pslg one = read_node_file(file, 1);
    REQUIRE(one.points.size() == two->points.size());
    bool same = one.attributes == two->attributes && one.markers == two->markers &&
                one.read_warnings == two->read_warnings;
    for (std::size_t i = 0; i < one.points.size(); ++i)
      same = same && one.points[i].x == two->points[i].x && one.points[i].y == two->points[i].y;
    CHECK(same);
  }
  const std::string truncated = text.substr(0, text.rfind("\n200000 ") + 1);
  const std::string short_message = node_error("big_short.node", truncated);
  CHECK(short_message.find("unexpected end of file: 200000 vertices announced, 199999 found") != std::string::npos);
}

TEST(node_parallel_path_reports_error_in_last_needed_vertex) {
  // A bad marker on the very last announced vertex, read by the second thread: the error must be
  // reported (not the vertex half-stored), and a good vertex beyond the count must not matter.
  std::string text = "150000 2 1 1\n";
  for (int i = 1; i <= 150000; ++i)
    text += std::to_string(i) + " " + std::to_string(i) + ".5 -" + std::to_string(i) + " 0.25 " + std::to_string(i % 5) + "\n";
  const std::string good = text + "150001 0 0 0 0\n";
  const Pslg p = read_node_file(iotest::write_file("big_extra.node", good));
  CHECK_EQ(p.points.size(), 150000u);
  CHECK_EQ(p.markers.size(), 150000u);
  CHECK_EQ(p.attributes.size(), 150000u);
  CHECK_EQ(p.markers[149999], 0);
  std::string bad_marker = text;
  bad_marker.replace(bad_marker.rfind(" 0\n"), 3, " x\n");
  const std::string message = node_error("big_bad_marker.node", bad_marker);
  CHECK(starts_at(message, "big_bad_marker.node", 150001));
  CHECK(message.find("vertex 150000: boundary marker is not an integer") != std::string::npos);
  std::string bad_attribute = text;
  bad_attribute.replace(bad_attribute.rfind(" 0.25 "), 6, " 0.2.5 ");
  CHECK(starts_at(node_error("big_bad_attribute.node", bad_attribute), "big_bad_attribute.node", 150001));
}

TEST(node_writer_many_attributes_round_trip) {
  // More fields than one TextWriter::Line may hold take the field-by-field path.
  Mesh m;
  m.num_attributes = 300;
  for (int v = 0; v < 3; ++v) {
    m.add_vertex({v * 0.1, -v / 3.0}, VertexKind::Input);
    for (int a = 0; a < m.num_attributes; ++a) m.attributes[static_cast<std::size_t>(v) * 300 + a] = a * 1e-7 + v;
  }
  std::string text;
  write_node_file(text, m, {1, true, nullptr});
  const Pslg p = read_node_file(iotest::write_file("wide.node", text));
  CHECK(p.points == m.points);
  CHECK(p.attributes == m.attributes);
  CHECK(p.markers == (std::vector<int>{0, 0, 0}));
}
