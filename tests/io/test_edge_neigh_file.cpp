// .edge and .neigh writers.
#include "harness/check.h"
#include "harness/id_literals.h"
#include "io/edge_file.h"
#include "io/neigh_file.h"
#include "io_test_util.h"

using namespace deltri;

TEST(edge_writer_each_edge_once_with_markers) {
  Mesh m = iotest::two_triangles();
  std::string text;
  write_edge_file(text, m, {1, true, nullptr});
  // Triangle 0 sides 0 (1-2), 1 (2-3) and 2 (3-1, shared, written here); triangle 1 sides 1, 2.
  CHECK_EQ(text, "5 1\n1 1 2 1\n2 2 3 1\n3 3 1 0\n4 3 4 1\n5 4 1 1\n");
  m.enable_subsegments();
  m.subsegments = {{0_v, 1_v, 8, 0}, {2_v, 0_v, 0, 1}, {2_v, 3_v, 6, 2}};
  m.set_subsegment(edge_of(0_t, 0), 0_s);
  m.set_subsegment(edge_of(0_t, 2), 1_s);
  m.set_subsegment(edge_of(1_t, 1), 2_s);
  text.clear();
  write_edge_file(text, m, {0, true, nullptr});
  CHECK_EQ(text, "5 1\n0 0 1 8\n1 1 2 1\n2 2 0 0\n3 2 3 6\n4 3 0 1\n");
  text.clear();
  write_edge_file(text, m, {0, false, nullptr});
  CHECK_EQ(text, "5 0\n0 0 1\n1 1 2\n2 2 0\n3 2 3\n4 3 0\n");
}

TEST(neigh_writer_opposite_corners_and_dead_slots) {
  Mesh m = iotest::two_triangles();
  std::string text;
  write_neigh_file(text, m, 1);
  // Triangle 1 (0,1,2): across corner 1 (vertex 1) is the diagonal -> triangle 2.
  CHECK_EQ(text, "2 3\n1 -1 2 -1\n2 -1 -1 1\n");
  text.clear();
  write_neigh_file(text, m, 0);
  CHECK_EQ(text, "2 3\n0 -1 1 -1\n1 -1 -1 0\n");
  // A dead slot in front: the numbering skips it, as the .ele does.
  Mesh d;
  for (Point p : {Point{0, 0}, Point{1, 0}, Point{1, 1}, Point{0, 1}}) d.add_vertex(p, VertexKind::Input);
  const TriangleId dead = d.add_triangle(0_v, 1_v, 3_v);
  const TriangleId a = d.add_triangle(0_v, 1_v, 2_v);
  const TriangleId b = d.add_triangle(0_v, 2_v, 3_v);
  d.bond(edge_of(a, 2), edge_of(b, 0));
  d.kill_triangle(dead);
  text.clear();
  write_neigh_file(text, d, 0);
  CHECK_EQ(text, "2 3\n0 -1 1 -1\n1 -1 -1 0\n");
}
