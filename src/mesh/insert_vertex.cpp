// Vertex insertion: locate, split, then Lawson flips until every edge around the new vertex is
// locally Delaunay again. Ghost triangles (corner kGhostVertex) are understood, so the same code
// grows a convex hull during incremental construction.
#include <vector>

#include "mesh/internal.h"
#include "mesh/operations.h"

namespace deltri {
namespace {

// Whether edge e, seen from its triangle whose apex is the new vertex v, must be flipped. The
// circle of a ghost triangle is the open half-plane beyond its real edge, which lets flips widen
// the hull; a point merely collinear with a hull edge never flips it (the triangle would be flat).
bool must_flip(const Mesh& m, Predicates& pred, EdgeRef e, VertexId v) {
  const EdgeRef f = m.link[e];
  if (f == kNone || detail::carries_subsegment(m, e)) return false;
  const VertexId a = m.org(e), b = m.dest(e), d = m.apex(f);
  const Point& p = m.point(v);
  if (a == kGhostVertex) return pred.orient2d(m.point(d), m.point(b), p) > 0;
  if (b == kGhostVertex) return pred.orient2d(m.point(a), m.point(d), p) > 0;
  if (d == kGhostVertex) return false;  // p is inside the hull, on the real side of edge b->a
  return pred.incircle(m.point(b), m.point(a), m.point(d), p) > 0;
}

// The flip stack: a vertex's link is short, so the common case needs no allocation (insertion
// runs once per Steiner point, and the allocator showed in refinement's profile).
class EdgeStack {
 public:
  void push_back(EdgeRef e) {
    if (size_ < kInline) {
      inline_[size_++] = e;
      return;
    }
    spill_.push_back(e);
    ++size_;
  }
  EdgeRef back() const { return size_ > kInline ? spill_.back() : inline_[size_ - 1]; }
  void pop_back() {
    if (size_ > kInline) spill_.pop_back();
    --size_;
  }
  bool empty() const { return size_ == 0; }

 private:
  static constexpr std::size_t kInline = 64;
  EdgeRef inline_[kInline];
  std::size_t size_ = 0;
  std::vector<EdgeRef> spill_;
};

// The edges opposite v in every triangle around it (the fan may be open at the boundary).
void push_link_of(const Mesh& m, EdgeRef out, EdgeStack& stack) {
  EdgeRef e = out;
  do {
    stack.push_back(lnext(e));
    e = m.link[lprev(e)];
  } while (e != kNone && e != out);
  if (e == out) return;
  for (EdgeRef s = m.link[out]; s != kNone; s = m.link[e]) {
    e = lnext(s);
    stack.push_back(lnext(e));
  }
}

// Lawson's flips on the link of v; `must_flip(e)` decides each edge opposite v.
template <class FlipRule>
void restore_delaunay(Mesh& m, VertexId v, EdgeRef out, FlipRule&& must_flip) {
  EdgeStack stack;
  push_link_of(m, out, stack);
  while (!stack.empty()) {
    const EdgeRef e = stack.back();
    stack.pop_back();
    if (m.apex(e) != v || !must_flip(e)) continue;
    const EdgeRef f = m.link[e];
    const EdgeRef g = flip(m, e);  // v -> old apex of f; the link of v is now lnext(g), lprev(f)
    stack.push_back(lnext(g));
    stack.push_back(lprev(f));
  }
}

EdgeRef leaving(const Mesh& m, TriangleId t, VertexId v) {
  return 3 * t + detail::corner_index(m, t, v);
}

// Locates v and splits what it falls in (Inserted: an edge leaving v, no flips yet), or says why
// nothing was changed, as insert_vertex does.
InsertResult split_at(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef hint, bool split_subsegments) {
  const Location loc = locate(mesh, pred, mesh.point(v), hint);
  switch (loc.status) {
    case LocateStatus::OnVertex:
      return {InsertStatus::Duplicate, loc.edge};
    case LocateStatus::Outside:
      // Only a hull edge with a ghost behind it lets the mesh grow outwards.
      if (loc.edge == kNone || mesh.link[loc.edge] == kNone)
        return {InsertStatus::Outside, loc.edge};
      return {InsertStatus::Inserted, split_triangle(mesh, mesh.link[loc.edge], v)};
    case LocateStatus::OnEdge:
      if (!split_subsegments && detail::carries_subsegment(mesh, loc.edge))
        return {InsertStatus::OnSubsegment, loc.edge};
      return {InsertStatus::Inserted, split_edge(mesh, loc.edge, v)};
    case LocateStatus::InTriangle:
      break;
  }
  return {InsertStatus::Inserted, split_triangle(mesh, loc.edge, v)};
}

}  // namespace

InsertResult insert_vertex(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef hint,
                           bool split_subsegments) {
  const InsertResult split = split_at(mesh, pred, v, hint, split_subsegments);
  if (split.status != InsertStatus::Inserted) return split;
  restore_delaunay(mesh, v, split.edge, [&](EdgeRef e) { return must_flip(mesh, pred, e, v); });
  // Flips keep v in the slot that was split.
  return {InsertStatus::Inserted, leaving(mesh, triangle_of(split.edge), v)};
}

InsertResult insert_vertex_into_cavity(Mesh& mesh, Predicates& pred, VertexId v, EdgeRef container,
                                       bool strictly_inside, const KnownCavity& cavity) {
  if (strictly_inside)
    if (const EdgeRef out = detail::fill_star(mesh, pred, v, cavity); out != kNone)
      return {InsertStatus::Inserted, out};
  const InsertResult split = split_at(mesh, pred, v, container, false);
  if (split.status != InsertStatus::Inserted) return split;
  // The triangle beyond a link edge never holds v, so its slot still names an original triangle.
  restore_delaunay(mesh, v, split.edge, [&](EdgeRef e) {
    const EdgeRef f = mesh.link[e];
    return f != kNone && !detail::carries_subsegment(mesh, e) && cavity.contains(triangle_of(f));
  });
  return {InsertStatus::Inserted, leaving(mesh, triangle_of(split.edge), v)};
}

}  // namespace deltri
