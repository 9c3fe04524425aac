// .ele reading/writing and .area reading.
#include "harness/check.h"
#include "harness/id_literals.h"
#include "io/area_file.h"
#include "io/ele_file.h"
#include "io_test_util.h"

using namespace deltri;

namespace {
std::string where(const std::string& name, int line) {
  return (iotest::scratch_dir() / name).string() + ":" + std::to_string(line) + ":";
}
}  // namespace

TEST(ele_writer_live_triangles_in_slot_order) {
  Mesh m = iotest::two_triangles();
  const TriangleId extra = m.add_triangle(1_v, 2_v, 3_v);
  m.num_triangle_attributes = 1;
  m.triangle_attributes = {0.5, 7, -1.25};
  std::string text;
  write_ele_file(text, m, {1, nullptr, nullptr});
  CHECK_EQ(text, "3 3 1\n1 1 2 3 0.5\n2 1 3 4 7\n3 2 3 4 -1.25\n");
  m.kill_triangle(0_t);
  (void)extra;
  text.clear();
  write_ele_file(text, m, {0, nullptr, nullptr});
  CHECK_EQ(text, "2 3 1\n0 0 2 3 7\n1 1 2 3 -1.25\n");
}

TEST(ele_writer_second_order_and_jettison) {
  Mesh m = iotest::two_triangles();
  const std::vector<VertexId> mid{4_v, 5_v, 6_v, 7_v, 8_v, 9_v};
  for (int i = 0; i < 6; ++i) m.add_vertex({0.5, 0.5}, VertexKind::Free);
  std::string text;
  write_ele_file(text, m, {0, nullptr, &mid});
  CHECK_EQ(text, "2 6 0\n0 0 1 2 4 5 6\n1 0 2 3 7 8 9\n");
  const std::vector<std::uint32_t> renumber{0, 1, 2, 3, kNone, kNone, kNone, kNone, kNone, kNone};
  text.clear();
  write_ele_file(text, iotest::two_triangles(), {1, &renumber, nullptr});
  CHECK_EQ(text, "2 3 0\n1 1 2 3\n2 1 3 4\n");
}

TEST(ele_round_trip_and_reader_errors) {
  std::string text;
  write_ele_file(text, iotest::two_triangles(), {1, nullptr, nullptr});
  const EleData e = read_ele_file(iotest::write_file("rt.ele", text), 1, 4);
  CHECK_EQ(e.nodes_per_triangle, 3u);
  CHECK_EQ(e.triangle_count(), 2u);
  CHECK(e.corners == (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  const EleData six = read_ele_file(iotest::write_file("six.ele", "1 6 1\n0 0 1 2 3 4 5 2.5\n"), 0, 6);
  CHECK_EQ(six.corners.size(), 6u);
  CHECK(six.attributes == std::vector<double>{2.5});
  auto error = [](const std::string& name, const std::string& body, int first, std::uint32_t n) {
    const std::string path = iotest::write_file(name, body);
    return iotest::input_error([&] { read_ele_file(path, first, n); });
  };
  CHECK(error("b1.ele", "1 3 0\n1 1 2 5\n", 1, 4).starts_with(where("b1.ele", 2) + " triangle 1: node 3 is 5, not a vertex"));
  CHECK(error("b2.ele", "1 3 0\n0 0 1 2\n", 1, 4).starts_with(where("b2.ele", 2)));
  CHECK(error("b3.ele", "1 4 0\n", 1, 4).starts_with(where("b3.ele", 1) + " triangle header: nodes per triangle must be 3 or 6"));
  CHECK(error("b4.ele", "# x\n2 3 0\n1 1 2 3\n", 1, 4).starts_with(where("b4.ele", 3) + " unexpected end of file"));
  CHECK(error("b5.ele", "1 3 1\n1 1 2 3\n", 1, 4).starts_with(where("b5.ele", 2) + " triangle 1: attribute 1 is missing"));
}

TEST(area_reader) {
  const auto areas = read_area_file(iotest::write_file("a.area", "3\n1 0.5\n2 -1\n3 1e-3 # c\n"), 3);
  CHECK(areas == (std::vector<double>{0.5, -1, 1e-3}));
  const std::string path = iotest::write_file("b.area", "2\n1 0.5\n2 x\n");
  CHECK(iotest::input_error([&] { read_area_file(path); }).starts_with(where("b.area", 3) + " triangle 2: maximum area is not a number"));
  const std::string count = iotest::write_file("c.area", "2\n1 0.5\n2 1\n");
  CHECK(iotest::input_error([&] { read_area_file(count, 3); }).starts_with(where("c.area", 1)));
}
