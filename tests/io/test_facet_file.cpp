// TetGen facet files (.poly with a 3-D node section, .smesh).
#include "harness/check.h"
#include "io/facet_file.h"
#include "io_test_util.h"

using namespace deltri;

namespace {

std::string facet_error(const std::string& name, const std::string& text) {
  const std::string path = iotest::write_file(name, text);
  return iotest::input_error([&] { read_facet_file(path); });
}

std::string where(const std::string& name, int line) {
  return (iotest::scratch_dir() / name).string() + ":" + std::to_string(line) + ":";
}

const char* kPoints = "5 3 0 1\n1 0 0 0 7\n2 1 0 0 7\n3 1 1 0 7\n4 0 1 0 7\n5 0.5 0.5 2 8\n";

}  // namespace

TEST(facet_poly_reads_polygons_holes_markers) {
  const std::string text = std::string(kPoints) +
                           "2 1\n"
                           "3 1 4\n4 1 2 3 4\n2 1 3\n1 5\n1 0.5 0.5 0\n"  // 3 polygons, 1 hole, marker 4
                           "1 0 9\n3 1 2 5\n";
  const FacetInput in = read_facet_file(iotest::write_file("f.poly", text));
  CHECK_EQ(in.points.size(), 5u);
  CHECK(in.has_markers);
  CHECK_EQ(in.markers[4], 8);
  CHECK_EQ(in.first_index, 1);
  CHECK(in.points[4] == (Point3{0.5, 0.5, 2}));
  REQUIRE(in.facets.size() == 2);
  const FacetInput::Facet& f = in.facets[0];
  CHECK_EQ(f.marker, 4);
  CHECK_EQ(f.line, 8);
  REQUIRE(f.polygons.size() == 3);
  CHECK_EQ(f.polygons[0].size(), 4u);
  CHECK_EQ(f.polygons[0][3], 3u);
  CHECK_EQ(f.polygons[1].size(), 2u);
  CHECK_EQ(f.polygons[2].size(), 1u);
  CHECK_EQ(f.polygons[2][0], 4u);
  REQUIRE(f.holes.size() == 1);
  CHECK(f.holes[0] == (Point3{0.5, 0.5, 0}));
  CHECK_EQ(in.facets[1].marker, 9);
  CHECK_EQ(in.facets[1].polygons[0][2], 4u);
}

TEST(facet_smesh_reads_one_polygon_per_line) {
  iotest::write_file("s.node", "4 3\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  const FacetInput in = read_facet_file(iotest::write_file("s.smesh", "0 3 0 0\n2 1\n3 0 1 2 5\n3 0 1 3 6\n"));
  CHECK_EQ(in.first_index, 0);
  REQUIRE(in.facets.size() == 2);
  CHECK_EQ(in.facets[0].marker, 5);
  CHECK_EQ(in.facets[1].polygons[0][2], 3u);
  CHECK(is_facet_file(iotest::write_file("d3.poly", "4 3 0 0\n")));
  CHECK(!is_facet_file(iotest::write_file("d2.poly", "# c\n\n4 2 0 0\n")));
  CHECK(!is_facet_file(iotest::write_file("d0.poly", "4\n")));
}

TEST(facet_errors_name_file_and_line) {
  const std::string pts = kPoints;
  CHECK(facet_error("e1.poly", pts + "1 0\n1\n4 1 2 3 6\n").starts_with(where("e1.poly", 9) + " facet 1: corner 6 is not a point"));
  CHECK(facet_error("e2.poly", pts + "2 0\n1\n3 1 2 3\n").starts_with(where("e2.poly", 9) + " unexpected end of file: 2 facets announced, 1 complete"));
  CHECK(facet_error("e3.poly", pts + "1 0\n1\n4 1 2 3\n").starts_with(where("e3.poly", 9) + " facet 1: the polygon announces 4 corners, 3 found"));
  CHECK(facet_error("e4.poly", pts + "1 0\n1 1\n3 1 2 3\n1 0 0\n").starts_with(where("e4.poly", 10) + " facet hole 1: z coordinate is missing"));
  CHECK(facet_error("e5.poly", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1\n1\n").starts_with(where("e5.poly", 4) + " point 3: z coordinate is missing"));
  CHECK(facet_error("e6.smesh", "3 2 0 0\n").starts_with(where("e6.smesh", 1) + " node header: dimension must be 3"));
  CHECK(facet_error("e7.poly", pts + "0 0\n").starts_with(where("e7.poly", 7) + " facet header: number of facets"));
}
