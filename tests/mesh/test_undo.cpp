// undo_insertion restores the triangulation, slot for slot, including subsegment records.
#include "harness/check.h"
#include "mesh/operations.h"
#include "mesh/undo.h"
#include "mesh_checks.h"

using namespace deltri;
using namespace meshcheck;

namespace {

struct Inserted {
  VertexId v;
  EdgeRef edge;
  std::vector<EdgeRef> flips;
};

Mesh square_with(std::size_t n, unsigned seed) {
  Mesh m = unit_square();
  Predicates pred;
  for (const Point& p : uniform(n, seed)) insert_vertex(m, pred, m.add_vertex(p, VertexKind::Free), 0);
  return m;
}

// Live slots of `before` must hold exactly the same corners, links and subsegments in `after`.
bool same_live_slots(const Mesh& before, const Mesh& after) {
  for (TriangleId t = 0; t < before.triangle_slots(); ++t) {
    if (!before.is_live(t)) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = 3 * t + i;
      if (before.corner[e] != after.corner[e] || before.link[e] != after.link[e]) return false;
      if (!before.subseg.empty() && before.subseg[e] != after.subseg[e]) return false;
    }
  }
  return before.live_triangles() == after.live_triangles();
}

}  // namespace

TEST(undo_single_insertions) {
  Predicates pred;
  Mesh m = square_with(300, 41);
  int flips_seen = 0;
  std::vector<Point> tries = uniform(200, 42);
  tries.push_back({0.5, 0});      // on a boundary edge
  tries.push_back(m.point(7));    // a duplicate: nothing to undo
  for (const Point& p : tries) {
    const Mesh before = m;
    const VertexId v = m.add_vertex(p, VertexKind::Free);
    std::vector<EdgeRef> flips;
    const InsertResult r = insert_vertex(m, pred, v, 0, true, &flips);
    if (r.status != InsertStatus::Inserted) continue;
    flips_seen += static_cast<int>(flips.size());
    CHECK(triangle_set(m) != triangle_set(before));
    undo_insertion(m, v, r.edge, flips);
    CHECK(triangle_set(m) == triangle_set(before));
    CHECK(same_live_slots(before, m));
    CHECK_EQ(all_faults(m), 0);
  }
  CHECK(flips_seen > 200);
}

TEST(undo_many_insertions_last_in_first_out) {
  Predicates pred;
  Mesh m = square_with(100, 43);
  const Mesh before = m;
  std::vector<Inserted> done;
  for (const Point& p : uniform(60, 44)) {
    Inserted ins{m.add_vertex(p, VertexKind::Free), kNone, {}};
    const InsertResult r = insert_vertex(m, pred, ins.v, 0, true, &ins.flips);
    REQUIRE(r.status == InsertStatus::Inserted);
    ins.edge = r.edge;
    done.push_back(std::move(ins));
  }
  CHECK_EQ(delaunay_faults(m), 0);
  for (auto it = done.rbegin(); it != done.rend(); ++it) undo_insertion(m, it->v, it->edge, it->flips);
  CHECK(triangle_set(m) == triangle_set(before));
  CHECK(same_live_slots(before, m));
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
}

TEST(undo_a_subsegment_split) {
  Predicates pred;
  Mesh m = square_with(50, 45);
  m.enable_subsegments();
  // Random interior points leave the left side (0,0)-(0,1) a single boundary edge; make it a
  // subsegment and split it.
  const EdgeRef left = find_edge(m, 3, 0);
  REQUIRE(left != kNone);
  m.subsegments.push_back({0, 3, 2, 0});
  m.set_subsegment(left, 0);
  const Mesh before = m;
  const VertexId v = m.add_vertex({0, 0.375}, VertexKind::Segment);
  std::vector<EdgeRef> flips;
  const InsertResult r = insert_vertex(m, pred, v, 0, true, &flips);
  REQUIRE(r.status == InsertStatus::Inserted);
  CHECK_EQ(m.subsegments.size(), 2u);
  undo_insertion(m, v, r.edge, flips);
  REQUIRE(m.subsegments.size() == 1u);
  CHECK_EQ(m.subsegments[0].a, 0u);
  CHECK_EQ(m.subsegments[0].b, 3u);
  CHECK(same_live_slots(before, m));
  CHECK(triangle_set(m) == triangle_set(before));
}

TEST(undo_lattice_insertions_on_edges_and_boundary) {
  // Lattice points land on interior edges, on boundary edges and on existing vertices.
  Predicates pred;
  Mesh m = unit_square();
  m.enable_subsegments();
  m.subsegments.push_back({0, 1, 1, 0});
  m.set_subsegment(find_edge(m, 0, 1), 0);
  const Mesh before = m;
  std::vector<Point> pts;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) pts.push_back({i / 8.0, j / 8.0});
  std::shuffle(pts.begin(), pts.end(), std::mt19937(46));
  std::vector<Inserted> done;
  int duplicates = 0;
  for (const Point& p : pts) {
    Inserted ins{m.add_vertex(p, VertexKind::Free), kNone, {}};
    const InsertResult r = insert_vertex(m, pred, ins.v, 0, true, &ins.flips);
    if (r.status == InsertStatus::Duplicate) { ++duplicates; continue; }
    REQUIRE(r.status == InsertStatus::Inserted);
    ins.edge = r.edge;
    done.push_back(std::move(ins));
  }
  CHECK_EQ(duplicates, 4);
  CHECK_EQ(m.live_triangles(), 128u);
  CHECK_EQ(m.subsegments.size(), 8u);
  CHECK_EQ(all_faults(m), 0);
  CHECK_EQ(delaunay_faults(m), 0);
  for (auto it = done.rbegin(); it != done.rend(); ++it) undo_insertion(m, it->v, it->edge, it->flips);
  CHECK(same_live_slots(before, m));
  CHECK_EQ(m.subsegments.size(), 1u);
  CHECK_EQ(m.subsegments[0].b, 1u);
}
