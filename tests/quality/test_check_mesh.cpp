// The -C checker against hand-made meshes: correct ones must pass, and each injected fault must be
// reported as exactly its own kind, with the expected count and example, and nothing else.
#include <map>
#include <set>
#include <string>

#include <cmath>

#include "harness/check.h"
#include "harness/id_literals.h"
#include "mesh/overlap.h"
#include "mesh/topology_writer.h"
#include "quality/check_mesh.h"
#include "quality/mesh_builders.h"

using namespace deltri;
using namespace quality_test;

namespace {

using Expected = std::map<FaultKind, std::uint64_t>;

// True when the report has exactly the expected counts (and zero for every other kind).
bool has_exactly(const CheckReport& r, const Expected& expected) {
  for (std::size_t k = 0; k < kFaultKinds; ++k) {
    const auto kind = static_cast<FaultKind>(k);
    const auto it = expected.find(kind);
    if (r.count(kind) != (it == expected.end() ? 0 : it->second)) return false;
  }
  return true;
}

CheckOptions hull_mode() {
  CheckOptions o;
  o.convex_hull_expected = true;
  return o;
}

std::size_t line_count(const std::string& s) {
  std::size_t n = 0;
  for (const char c : s) n += c == '\n';
  return n;
}

}  // namespace

TEST(delaunay_diamond_passes_every_layer) {
  const Mesh m = diamond_short_diagonal();
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(r.ok());
  CHECK_EQ(r.triangles_checked, 2u);
  CHECK_EQ(r.edges_checked, 5u);
  CHECK_EQ(r.boundary_loops, 1u);
  for (std::size_t l = 0; l < kCheckLayers; ++l) CHECK(!r.skipped[l]);
  CHECK(r.summary().find("consistent") != std::string::npos);
  CHECK_EQ(line_count(r.summary()), 1u);
}

TEST(long_diagonal_is_not_locally_delaunay) {
  const Mesh m = diamond_long_diagonal();
  const CheckReport r = check_mesh(m, CheckOptions{});
  CHECK(!r.ok());
  CHECK(has_exactly(r, {{FaultKind::NotLocallyDelaunay, 1}}));
  CHECK_EQ(r.example(FaultKind::NotLocallyDelaunay), 2u);  // the pair 2/3, named by its smaller edge
  CHECK(r.summary().find(fault_name(FaultKind::NotLocallyDelaunay)) != std::string::npos);
  CHECK_EQ(line_count(r.summary()), 2u);
}

TEST(segment_on_long_diagonal_excuses_it_unless_conforming) {
  Mesh m = diamond_long_diagonal();
  m.enable_subsegments();
  m.subsegments.push_back({0_v, 2_v, 1, 0});
  m.set_subsegment(2_e, 0_s);
  CHECK(check_mesh(m, CheckOptions{}).ok());
  CheckOptions conforming;
  conforming.conforming = true;
  CHECK(has_exactly(check_mesh(m, conforming), {{FaultKind::NotLocallyDelaunay, 1}}));
}

TEST(fan_with_cocircular_spokes_is_a_convex_delaunay_mesh) {
  const Mesh m = square_fan();
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(r.ok());
  CHECK_EQ(r.triangles_checked, 8u);
  CHECK_EQ(r.edges_checked, 16u);
  CHECK_EQ(r.boundary_loops, 1u);
}

TEST(fan_with_a_missing_triangle_has_one_reflex_turn) {
  Mesh m = square_fan();
  m.kill_triangle(7_t);  // (centre, (1,-1), (1,0)): the boundary now dents in at the centre
  CHECK(check_mesh(m, CheckOptions{}).ok());
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(has_exactly(r, {{FaultKind::ReflexBoundaryTurn, 1}}));
  CHECK_EQ(r.example(FaultKind::ReflexBoundaryTurn), 0u);  // the edge centre -> (1,0) turns right
  CHECK_EQ(r.boundary_loops, 1u);
}

TEST(one_sided_link_breaks_involution_and_opens_the_boundary) {
  Mesh m = diamond_short_diagonal();
  detail::link_slots(m)[5] = kNone;  // edge 1 still points at 5
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(has_exactly(r, {{FaultKind::LinkNotInvolution, 1}, {FaultKind::OpenBoundary, 2}}));
  CHECK_EQ(r.example(FaultKind::LinkNotInvolution), 1u);
  CHECK_EQ(r.example(FaultKind::OpenBoundary), 1u);  // vertex b: d->b now leaves no partner
  CHECK(r.layer_skipped(CheckLayer::Delaunay));
  CHECK(r.layer_skipped(CheckLayer::ConvexHull));
  CHECK(!r.layer_skipped(CheckLayer::Orientation));
  CHECK(r.summary().find("not checked") != std::string::npos);
  CHECK_EQ(line_count(r.summary()), 4u);  // header, two kinds, skipped layers
}

TEST(link_to_wrong_edge_has_unswapped_endpoints) {
  Mesh m = diamond_short_diagonal();
  m.bond(1_e, 3_e);  // b->d with b->c; edge 5 (d->b) still points at 1
  const CheckReport r = check_mesh(m, CheckOptions{});
  CHECK(has_exactly(r, {{FaultKind::LinkNotInvolution, 1},
                        {FaultKind::LinkEndpoints, 2},
                        {FaultKind::OpenBoundary, 2}}));
  CHECK_EQ(r.example(FaultKind::LinkNotInvolution), 5u);
  CHECK_EQ(r.example(FaultKind::LinkEndpoints), 1u);
}

TEST(link_into_a_dead_slot) {
  Mesh m = diamond_short_diagonal();
  detail::corner_slots(m)[3] = detail::corner_slots(m)[4] = detail::corner_slots(m)[5] = kNone;  // killed without unlinking
  m.free_triangles.push_back(1_t);
  const CheckReport r = check_mesh(m, CheckOptions{});
  CHECK(has_exactly(r, {{FaultKind::LinkToDeadTriangle, 1}, {FaultKind::OpenBoundary, 2}}));
  CHECK_EQ(r.example(FaultKind::LinkToDeadTriangle), 1u);
}

TEST(clockwise_triangle_is_the_only_fault) {
  Mesh m = mesh_of({{0, 0}, {0, 1}, {1, 0}});
  m.add_triangle(0_v, 1_v, 2_v);
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(has_exactly(r, {{FaultKind::ClockwiseTriangle, 1}}));
  CHECK_EQ(r.example(FaultKind::ClockwiseTriangle), 0u);
  CHECK(r.layer_skipped(CheckLayer::Delaunay));
}

TEST(flat_triangle) {
  Mesh m = mesh_of({{0, 0}, {1, 1}, {3, 3}});
  m.add_triangle(0_v, 1_v, 2_v);
  CHECK(has_exactly(check_mesh(m, CheckOptions{}), {{FaultKind::FlatTriangle, 1}}));
}

TEST(orientation_is_exact_near_collinear) {
  // (0.5+2^-52, 0.5) is a hair to the right of the line y = x: a clockwise sliver that a
  // tolerance or a sloppy determinant would call flat.
  Mesh m = mesh_of({{0, 0}, {0.5 + 0x1p-52, 0.5}, {1, 1}});
  m.add_triangle(0_v, 2_v, 1_v);
  CHECK(has_exactly(check_mesh(m, CheckOptions{}), {{FaultKind::ClockwiseTriangle, 1}}));
  Mesh ccw = mesh_of({{0, 0}, {0.5 + 0x1p-52, 0.5}, {1, 1}});
  ccw.add_triangle(0_v, 1_v, 2_v);
  CHECK(check_mesh(ccw, CheckOptions{}).ok());
}

TEST(duplicate_vertex_used_by_a_triangle) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0, 1}});
  const VertexId dup = m.add_vertex({0, 1}, VertexKind::Duplicate);
  m.add_triangle(0_v, 1_v, dup);
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(has_exactly(r, {{FaultKind::DeadVertexUsed, 1}}));
  CHECK_EQ(r.example(FaultKind::DeadVertexUsed), dup);
  CHECK(r.layer_skipped(CheckLayer::ConvexHull));  // vertex 2 unused is not reported on top
}

TEST(unused_duplicate_is_fine_but_unused_input_is_not_in_hull_mode) {
  Mesh m = mesh_of({{0, 0}, {4, 0}, {0, 4}});
  m.add_vertex({0, 4}, VertexKind::Duplicate);
  m.add_triangle(0_v, 1_v, 2_v);
  CHECK(check_mesh(m, hull_mode()).ok());
  const VertexId inner = m.add_vertex({1, 1}, VertexKind::Input);
  CHECK(check_mesh(m, CheckOptions{}).ok());
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(has_exactly(r, {{FaultKind::UnusedVertex, 1}}));
  CHECK_EQ(r.example(FaultKind::UnusedVertex), inner);
}

TEST(no_triangles_is_right_only_for_collinear_input) {
  Mesh line = mesh_of({{0, 0}, {1, 1}, {2, 2}, {1, 1}});
  CHECK(check_mesh(line, hull_mode()).ok());
  Mesh plane = mesh_of({{0, 0}, {1, 1}, {2, 2}, {1, 0}});
  CHECK(has_exactly(check_mesh(plane, hull_mode()), {{FaultKind::UnusedVertex, 4}}));
  CHECK(check_mesh(Mesh{}, hull_mode()).ok());
}

TEST(two_separate_triangles_are_two_boundary_loops) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0, 1}, {5, 0}, {6, 0}, {5, 1}});
  m.add_triangle(0_v, 1_v, 2_v);
  m.add_triangle(3_v, 4_v, 5_v);
  CHECK(check_mesh(m, CheckOptions{}).ok());
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(has_exactly(r, {{FaultKind::ExtraBoundaryLoop, 1}}));
  CHECK_EQ(r.boundary_loops, 2u);
  CHECK_EQ(r.example(FaultKind::ExtraBoundaryLoop), 3u);
}

TEST(hole_in_a_point_set_mesh_shows_as_reflex_turns) {
  // Square ring around a triangular hole; the hole's loop runs clockwise and turns right 3 times.
  Mesh m = mesh_of({{0, 0}, {6, 0}, {6, 6}, {0, 6}, {2, 2}, {4, 2}, {3, 4}});
  const VertexId a{0}, b{1}, c{2}, d{3}, p{4}, q{5}, r{6};
  for (const auto& t : {std::array<VertexId, 3>{a, b, q}, {a, q, p}, {b, c, q}, {q, c, r},
                        {c, d, r}, {d, p, r}, {d, a, p}})
    m.add_triangle(t[0], t[1], t[2]);
  bond_all(m);
  const CheckReport plain = check_mesh(m, CheckOptions{});
  CHECK(!plain.count(FaultKind::ClockwiseTriangle));
  CHECK(!plain.count(FaultKind::OpenBoundary));
  const CheckReport hull = check_mesh(m, hull_mode());
  CHECK_EQ(hull.count(FaultKind::ReflexBoundaryTurn), 3u);
  CHECK_EQ(hull.count(FaultKind::ExtraBoundaryLoop), 1u);
}

TEST(repeated_directed_edge) {
  Mesh m = mesh_of({{0, 0}, {2, 0}, {1, 1}, {1, 2}});
  m.add_triangle(0_v, 1_v, 2_v);
  m.add_triangle(0_v, 1_v, 3_v);  // overlaps the first, both with a->b
  const CheckReport r = check_mesh(m, CheckOptions{});
  CHECK(has_exactly(r, {{FaultKind::DuplicateEdge, 1}}));
  CHECK_EQ(r.example(FaultKind::DuplicateEdge), 3u);
}

TEST(subsegment_on_one_twin_only) {
  Mesh m = diamond_short_diagonal();
  m.enable_subsegments();
  m.subsegments.push_back({1_v, 3_v, 1, 0});
  detail::subseg_slots(m).set(1, 0_s);
  CHECK(has_exactly(check_mesh(m, CheckOptions{}), {{FaultKind::SubsegmentMismatch, 1}}));
  detail::subseg_slots(m).set(5, 0_s);
  CHECK(check_mesh(m, CheckOptions{}).ok());
  m.subsegments[0] = {0_v, 2_v, 1, 0};  // a-c, but lying on b-d
  const CheckReport r = check_mesh(m, CheckOptions{});
  CHECK(has_exactly(r, {{FaultKind::SubsegmentEndpoints, 1}}));
  CHECK_EQ(r.example(FaultKind::SubsegmentEndpoints), 1u);
}

TEST(storage_faults_stop_the_later_layers) {
  Mesh m = diamond_long_diagonal();  // not Delaunay, but that must not be reached
  detail::corner_slots(m)[4] = 9_v;
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(has_exactly(r, {{FaultKind::CornerOutOfRange, 1}}));
  CHECK_EQ(r.example(FaultKind::CornerOutOfRange), 1u);
  for (std::size_t l = 1; l < kCheckLayers; ++l) CHECK(r.skipped[l]);
  CHECK_EQ(line_count(r.summary()), 3u);
}

TEST(repeated_corner) {
  Mesh m = diamond_short_diagonal();
  detail::corner_slots(m)[4] = m.corner[3];
  CHECK(has_exactly(check_mesh(m, CheckOptions{}), {{FaultKind::RepeatedCorner, 1}}));
}

TEST(free_list_faults) {
  Mesh m = diamond_short_diagonal();
  m.free_triangles.push_back(0_t);  // live
  m.free_triangles.push_back(7_t);  // no such slot
  CHECK(has_exactly(check_mesh(m, CheckOptions{}), {{FaultKind::BadFreeListEntry, 2}}));
  Mesh n = diamond_short_diagonal();
  n.kill_triangle(1_t);
  CHECK(check_mesh(n, CheckOptions{}).ok());
  n.free_triangles.push_back(1_t);  // listed twice
  CHECK(has_exactly(check_mesh(n, CheckOptions{}), {{FaultKind::BadFreeListEntry, 1}}));
  n.free_triangles.clear();
  const CheckReport r = check_mesh(n, CheckOptions{});
  CHECK(has_exactly(r, {{FaultKind::UnlistedDeadSlot, 1}}));
  CHECK_EQ(r.example(FaultKind::UnlistedDeadSlot), 1u);
}

TEST(ids_out_of_range) {
  Mesh m = diamond_short_diagonal();
  detail::link_slots(m)[0] = 6_e;
  m.enable_subsegments();
  detail::subseg_slots(m).set(2, 0_s);  // there are no subsegments
  CHECK(has_exactly(check_mesh(m, CheckOptions{}),
                    {{FaultKind::LinkOutOfRange, 1}, {FaultKind::SubsegmentOutOfRange, 1}}));
}

TEST(array_sizes) {
  Mesh m = diamond_short_diagonal();
  detail::link_slots(m).pop_back();
  m.kind.push_back(VertexKind::Input);
  const CheckReport r = check_mesh(m, CheckOptions{});
  CHECK(has_exactly(r, {{FaultKind::ArraySize, 2}}));
  CHECK_EQ(r.example(FaultKind::ArraySize), kNone);
  CHECK_EQ(r.triangles_checked, 0u);
}

TEST(cocircular_grid_passes_in_hull_mode) {
  const Mesh m = grid(60);
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(r.ok());
  CHECK_EQ(r.triangles_checked, 2u * 60 * 60);
  CHECK_EQ(r.edges_checked, 3u * 60 * 60 + 2 * 60);
  CHECK_EQ(r.boundary_loops, 1u);
}

TEST(grid_with_a_pushed_vertex_loses_delaunay_edges) {
  Mesh m = grid(4);
  // Moving (2,2) to (1.9,1.9) takes it out of the circle of the square [2,3]^2, whose diagonal
  // from it to (3,3) is then not Delaunay, nor by symmetry its diagonals to (1,3) and (3,1);
  // orientation is unharmed.
  m.points[2 * 5 + 2] = {1.9, 1.9};
  const CheckReport r = check_mesh(m, hull_mode());
  CHECK(r.count(FaultKind::NotLocallyDelaunay) >= 3);
  CHECK_EQ(r.total_faults(), r.count(FaultKind::NotLocallyDelaunay));
}

// Each kind's layer and subject as check_mesh.h documents them (the enum's layer groups and the
// subject in each kind's comment), and a name of its own: the tables in check_mesh.cpp must agree
// with the header kind by kind, so a row out of place or a copied name fails.
TEST(fault_tables_are_complete) {
  using L = CheckLayer;
  using K = FaultKind;
  struct Documented {
    FaultKind kind;
    CheckLayer layer;
    const char* subject;
  };
  const std::vector<Documented> documented{
      {K::ArraySize, L::Storage, ""},
      {K::CornerOutOfRange, L::Storage, "triangle"},
      {K::RepeatedCorner, L::Storage, "triangle"},
      {K::BadFreeListEntry, L::Storage, "triangle"},
      {K::UnlistedDeadSlot, L::Storage, "triangle"},
      {K::LinkOutOfRange, L::Storage, "edge"},
      {K::SubsegmentOutOfRange, L::Storage, "edge"},
      {K::LinkToDeadTriangle, L::Topology, "edge"},
      {K::LinkNotInvolution, L::Topology, "edge"},
      {K::LinkEndpoints, L::Topology, "edge"},
      {K::DuplicateEdge, L::Topology, "edge"},
      {K::SubsegmentMismatch, L::Topology, "edge"},
      {K::SubsegmentEndpoints, L::Topology, "edge"},
      {K::DeadVertexUsed, L::Topology, "vertex"},
      {K::ClockwiseTriangle, L::Orientation, "triangle"},
      {K::FlatTriangle, L::Orientation, "triangle"},
      {K::OpenBoundary, L::Boundary, "vertex"},
      {K::NotLocallyDelaunay, L::Delaunay, "edge"},
      {K::ReflexBoundaryTurn, L::ConvexHull, "edge"},
      {K::ExtraBoundaryLoop, L::ConvexHull, "edge"},
      {K::UnusedVertex, L::ConvexHull, "vertex"},
      {K::OverlappingTriangles, L::Orientation, "triangle"},
  };
  CHECK_EQ(documented.size(), kFaultKinds);
  std::set<std::string> names;
  for (std::size_t k = 0; k < documented.size(); ++k) {
    const Documented& d = documented[k];
    CHECK_EQ(static_cast<std::size_t>(d.kind), k);  // the list follows the enum
    CHECK(fault_layer(d.kind) == d.layer);
    CHECK_EQ(std::string(fault_subject(d.kind)), std::string(d.subject));
    const std::string name = fault_name(d.kind);
    CHECK(!name.empty());
    CHECK(names.insert(name).second);  // no two kinds share a description
  }
  // The names that say what the kind is in the header's own words.
  CHECK(std::string(fault_name(K::ClockwiseTriangle)).find("clockwise") != std::string::npos);
  CHECK(std::string(fault_name(K::FlatTriangle)).find("collinear") != std::string::npos);
  CHECK(std::string(fault_name(K::LinkNotInvolution)).find("involution") != std::string::npos);
  CHECK(std::string(fault_name(K::NotLocallyDelaunay)).find("Delaunay") != std::string::npos);
  CHECK(std::string(fault_name(K::OverlappingTriangles)).find("overlap") != std::string::npos);
  CHECK_EQ(std::string(layer_name(CheckLayer::Delaunay)), std::string("Delaunay"));
  CHECK_EQ(std::string(fault_subject(FaultKind::ClockwiseTriangle)), std::string("triangle"));
}

// Issue 17: two counter-clockwise triangles that cross without sharing an edge pass every local
// check (twins, orientation, closed boundaries); only the overlap test sees them.
TEST(crossing_triangles_overlap) {
  Mesh m = mesh_of({{0, 0}, {1, 0}, {0, 1}, {0.2, 0.2}, {1.2, 0.2}, {0.2, 1.2}});
  m.add_triangle(0_v, 1_v, 2_v);
  m.add_triangle(3_v, 4_v, 5_v);
  const CheckReport r = check_mesh(m, CheckOptions{});
  CHECK(has_exactly(r, {{FaultKind::OverlappingTriangles, 1}}));
  CHECK_EQ(r.example(FaultKind::OverlappingTriangles), 1u);
}

// A corner of one triangle on the edge of another (a T-junction) is no triangulation either,
// though the interiors are disjoint.
TEST(corner_on_an_edge_is_reported) {
  Mesh m = mesh_of({{0, 0}, {2, 0}, {1, 1}, {1, 0}, {2, -1}});
  m.add_triangle(0_v, 1_v, 2_v);
  m.add_triangle(3_v, 4_v, 1_v);
  const CheckReport r = check_mesh(m, CheckOptions{});
  CHECK(has_exactly(r, {{FaultKind::OverlappingTriangles, 1}}));
}

// Neighbours across an edge and around a vertex are not overlaps.
TEST(a_sound_fan_has_no_overlap) { CHECK(check_mesh(square_fan(), CheckOptions{}).ok()); }

namespace {

// A fan of n - 2 long slivers: vertex 0 and n - 1 more on an arc of a unit circle, triangles
// (0, i, i + 1). Every triangle's bounding box meets most of the others', so the overlap test's
// grid cells are crowded (open finding 10 of docs/reliability.md).
Mesh arc_fan(std::uint32_t n) {
  std::vector<Point> points;
  for (std::uint32_t i = 0; i < n; ++i) {
    const double a = 3.0 * static_cast<double>(i) / n;  // 0 to 3 radians: a convex arc
    points.push_back({std::cos(a), std::sin(a)});
  }
  Mesh m = mesh_of(points);
  for (VertexId i{1}; i + 1 < n; ++i) m.add_triangle(0_v, i, VertexId{i + 1});
  return m;
}

}  // namespace

// A sound fan of slivers has no overlap; a small triangle inside any one of them (a second sheet
// of one triangle) overlaps exactly that one, and must be found wherever it lies in the grid.
TEST(overlap_in_a_crowded_fan_is_found_wherever_it_is) {
  Predicates pred;
  CHECK(!find_overlap(arc_fan(400), pred).has_value());
  for (const std::uint32_t k : {0u, 1u, 57u, 199u, 311u, 397u}) {
    Mesh m = arc_fan(400);
    const Point a = m.point(0_v), b = m.point(VertexId{k + 1}), c = m.point(VertexId{k + 2});
    const auto inside = [&](double wa, double wb, double wc) {
      return Point{wa * a.x + wb * b.x + wc * c.x, wa * a.y + wb * b.y + wc * c.y};
    };
    const VertexId v = m.add_vertex(inside(0.6, 0.2, 0.2), VertexKind::Input);
    m.add_vertex(inside(0.2, 0.6, 0.2), VertexKind::Input);
    m.add_vertex(inside(0.2, 0.2, 0.6), VertexKind::Input);
    const TriangleId extra = m.add_triangle(v, VertexId{v + 1}, VertexId{v + 2});
    const auto found = find_overlap(m, pred);
    CHECK(found.has_value());
    if (!found) continue;
    CHECK_EQ(found->first, k);
    CHECK_EQ(found->second, extra);
    CHECK(found->interiors_overlap);
  }
}

// Two slivers crossing like a plus sign among many small disjoint triangles (so that the grid is
// fine): neither box's lower-left cell is the cell where the boxes' intersection begins, so the
// pair is found only among the triangles that begin in that cell's row and column.
TEST(crossing_slivers_among_many_triangles_are_found) {
  Mesh m;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const double x = 0.05 * i + 0.01, y = 0.05 * j + 0.01;  // off the lines x = 0.5, y = 0.5
      const VertexId v = m.add_vertex({x, y}, VertexKind::Input);
      m.add_vertex({x + 0.01, y}, VertexKind::Input);
      m.add_vertex({x, y + 0.01}, VertexKind::Input);
      m.add_triangle(v, VertexId{v + 1}, VertexId{v + 2});
    }
  const VertexId h = m.add_vertex({0.003, 0.5}, VertexKind::Input);
  m.add_vertex({0.997, 0.5}, VertexKind::Input);
  m.add_vertex({0.5, 0.5005}, VertexKind::Input);
  const TriangleId horizontal = m.add_triangle(h, VertexId{h + 1}, VertexId{h + 2});
  const VertexId w = m.add_vertex({0.5003, 0.002}, VertexKind::Input);
  m.add_vertex({0.5004, 0.998}, VertexKind::Input);
  m.add_vertex({0.4996, 0.4}, VertexKind::Input);
  const TriangleId vertical = m.add_triangle(w, VertexId{w + 1}, VertexId{w + 2});
  Predicates pred;
  const auto found = find_overlap(m, pred);
  CHECK(found.has_value());
  if (!found) return;
  CHECK_EQ(found->first, horizontal);
  CHECK_EQ(found->second, vertical);
}
