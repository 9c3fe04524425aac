#include "cdt/segment_inserter.h"

#include <algorithm>
#include <cmath>

#include "cdt/walk.h"
#include "geometry/constructions.h"
#include "geometry/exact_determinants.h"
#include "mesh/subsegments.h"
#include "mesh/vertex_edges.h"
#include "util/prefetch.h"

namespace deltri {

namespace {

// The first step from u in another fan of u. Where the domain pinches at u (a mesh read with -r
// whose region touches itself at a vertex), the triangles around u form several fans with outside
// between them, and the vertex index knows an edge of one only; a piece leaving u through another
// fan was counted "outside every triangle" and lost its marker. Scans the mesh, so it runs only
// for a first step that found no way out of its fan (never in a Delaunay triangulation of the
// convex hull, where every fan is whole).
RayStart start_in_another_fan(const Mesh& mesh, Predicates& pred, VertexId u, VertexId v) {
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    for (EdgeRef e : edges_of(t)) {
      if (mesh.org(e) != u) continue;
      if (const RayStart s = first_step_to_vertex(mesh, pred, e, v); s.kind != RayStart::Kind::Blocked) return s;
    }
  }
  return {};
}

}  // namespace

void SegmentInserter::insert(const Piece& segment) {
  pending_.push_back(segment);
  while (!pending_.empty()) {
    const Piece piece = pending_.back();
    pending_.pop_back();
    if (piece.u != piece.v) process(piece);
  }
}

void SegmentInserter::insert(const Piece& segment, const EdgeFound& found) {
  const Mesh& mesh = ed_.mesh;
  const EdgeRef e = found.edge;
  const bool still = e != kNone && mesh.corner[e] == segment.u && mesh.dest(e) == segment.v &&
                     mesh.apex(e) == found.apex && mesh.link[e] == found.twin &&
                     (found.twin == kNone || mesh.apex(found.twin) == found.twin_apex) &&
                     ed_.leaving(segment.u) != kNone && ed_.leaving(segment.v) != kNone;
  if (!still) return insert(segment);
  // What process() does when first_step_to_vertex finds the edge u->v and no apex beside it is
  // near enough to snap to (near_vertex looks at u, v and the apex only: a fresh segment has no
  // snapped pairs yet).
  record(e, segment);
}

EdgeFound SegmentInserter::look_ahead(const Piece& segment) const {
  const Mesh& mesh = ed_.mesh;
  const EdgeRef out = ed_.leaving(segment.u);
  if (out == kNone || ed_.leaving(segment.v) == kNone) return {};
  EdgeRef edge = kNone;
  for_each_around(mesh, out, [&](EdgeRef e) {
    if (mesh.dest(e) == segment.v) edge = e;
  });
  if (edge == kNone) return {};
  const EdgeRef twin = mesh.link[edge];
  const EdgeFound found{edge, twin, mesh.apex(edge), twin == kNone ? VertexId{kNone} : mesh.apex(twin)};
  if (snap_ && near_vertex(segment, {found.apex, found.twin_apex}) != kNone) return {};
  return found;
}

void SegmentInserter::fetch(const EdgeFound& found) const {
  if (found.edge == kNone) return;
  const Mesh& mesh = ed_.mesh;
  for (const EdgeRef e : {found.edge, found.twin}) {
    if (e == kNone) continue;
    prefetch(mesh.corners_at(triangle_of(e)));
    prefetch(&mesh.link[e]);
    prefetch(mesh.subseg.home_of(e));
  }
}

SubsegmentId SegmentInserter::new_record(const Piece& piece) {
  Mesh& mesh = ed_.mesh;
  mesh.subsegments.push_back({piece.u, piece.v, piece.marker, piece.segment});
  return static_cast<SubsegmentId>(mesh.subsegments.size() - 1);
}

void SegmentInserter::record(EdgeRef e, const Piece& piece) {
  Mesh& mesh = ed_.mesh;
  const SubsegmentId old = mesh.subseg[e];
  if (old == kNone) {
    constrain(mesh, e, {piece.u, piece.v, piece.marker, piece.segment});
    return;
  }
  // Collinear overlap with an earlier segment (or a chain piece recovered twice).
  Subsegment& s = mesh.subsegments[old];
  if (s.marker == 0) s.marker = piece.marker;
  if (last_overlap_ != piece.segment && s.segment != piece.segment) {
    ++counts_.overlaps_merged;
    last_overlap_ = piece.segment;
  }
}

void SegmentInserter::process(const Piece& piece) {
  Mesh& mesh = ed_.mesh;
  Predicates& pred = ed_.pred;
  const EdgeRef from_u = ed_.leaving(piece.u);
  if (from_u == kNone || ed_.leaving(piece.v) == kNone) {
    ++counts_.unrecovered;
    return;
  }
  const Point& pu = mesh.point(piece.u);
  const Point& pv = mesh.point(piece.v);
  RayStart start = first_step_to_vertex(mesh, pred, from_u, piece.v);
  if (start.kind == RayStart::Kind::Blocked) start = start_in_another_fan(mesh, pred, piece.u, piece.v);
  if (start.kind == RayStart::Kind::Blocked) {
    ++counts_.unrecovered;  // impossible in a valid triangulation of the convex hull
    return;
  }
  if (start.kind == RayStart::Kind::Vertex) {
    // The piece runs along an existing edge: a vertex a few ulps off it is an apex beside it.
    if (snap_) {
      const Piece along{piece.u, start.vertex, piece.marker, piece.segment};
      VertexId w = near_vertex(along, {mesh.apex(start.edge)});
      if (w == kNone && mesh.link[start.edge] != kNone) w = near_vertex(along, {mesh.apex(mesh.link[start.edge])});
      if (w != kNone) {
        ++counts_.snapped;
        snapped_pairs_.insert((std::uint64_t{piece.segment} << 32) | w);
        pending_.push_back({w, piece.v, piece.marker, piece.segment});
        pending_.push_back({piece.u, w, piece.marker, piece.segment});
        return;
      }
    }
    record(start.edge, {piece.u, start.vertex, piece.marker, piece.segment});
    if (start.vertex != piece.v) {
      ++counts_.split_at_vertices;
      pending_.push_back({start.vertex, piece.v, piece.marker, piece.segment});
    }
    return;
  }
  crossed_.clear();
  EdgeRef g = start.edge;
  while (true) {
    if (snap_) {
      if (const VertexId w = near_vertex(piece, {mesh.org(g), mesh.dest(g)}); w != kNone) {
        // Split the piece at w and start both halves afresh (their walks differ from this one).
        ++counts_.snapped;
        snapped_pairs_.insert((std::uint64_t{piece.segment} << 32) | w);
        pending_.push_back({w, piece.v, piece.marker, piece.segment});
        pending_.push_back({piece.u, w, piece.marker, piece.segment});
        return;
      }
    }
    if (mesh.subseg.has(g)) return split_crossing(piece, g);
    crossed_.push_back(g);
    const RayStep step = next_step(mesh, pred, g, pu, pv);
    if (step.kind == RayStep::Kind::Boundary) {
      ++counts_.unrecovered;
      return;
    }
    if (step.kind == RayStep::Kind::Cross) {
      g = step.edge;
      continue;
    }
    const VertexId w = step.vertex;
    if (w != piece.v) {
      ++counts_.split_at_vertices;
      pending_.push_back({w, piece.v, piece.marker, piece.segment});
    }
    if (conform_ && split_at_midpoint(piece, w)) return;
    const Piece first{piece.u, w, piece.marker, piece.segment};
    const SubsegmentId id = new_record(first);
    if (recovery_.recover(piece.u, w, crossed_, id) == kNone) {
      mesh.subsegments[id].a = kNone;  // cannot happen in a valid mesh; leave a dead record
      ++counts_.unrecovered;
    }
    return;
  }
}

bool SegmentInserter::split_at_midpoint(const Piece& piece, VertexId w) {
  Mesh& mesh = ed_.mesh;
  const Point a = mesh.point(piece.u), b = mesh.point(w);
  const Point m{a.x + 0.5 * (b.x - a.x), a.y + 0.5 * (b.y - a.y)};
  if ((m.x == a.x && m.y == a.y) || (m.x == b.x && m.y == b.y)) return false;
  const PointLocation at = walk_to_point(mesh, ed_.pred, ed_.leaving(piece.u), m);
  if (at.kind == PointLocation::Kind::Outside || at.kind == PointLocation::Kind::OnVertex) return false;
  const VertexId x = mesh.add_vertex(m, VertexKind::Segment);
  mesh.interpolate_attributes(x, piece.u, w);
  if (at.kind == PointLocation::Kind::InTriangle) {
    ed_.insert_in_triangle(at.edge, x);
  } else {
    // Rounding put the midpoint on an edge, perhaps a subsegment: that one is split there too.
    const bool released = mesh.subseg.has(at.edge);
    if (released) release(at.edge, x);
    ed_.insert_on_edge(at.edge, x);
    // The mesh was constrained Delaunay with that subsegment only: its halves (which a snap may
    // leave unconstrained) and the other edges at x are legalized too.
    if (released) ed_.legalize_star(x);
  }
  ++counts_.midpoints;
  pending_.push_back({x, w, piece.marker, piece.segment});
  pending_.push_back({piece.u, x, piece.marker, piece.segment});
  return true;
}

VertexId SegmentInserter::near_vertex(const Piece& piece, std::initializer_list<VertexId> candidates) const {
  const Mesh& mesh = ed_.mesh;
  const Point& a = mesh.point(piece.u);
  const Point& b = mesh.point(piece.v);
  const double dx = b.x - a.x, dy = b.y - a.y;
  for (const VertexId w : candidates) {
    if (w == kNone || w == piece.u || w == piece.v) continue;
    const Point& p = mesh.point(w);
    // Strictly between the ends along the segment, then close to its line.
    if (!((p.x - a.x) * dx + (p.y - a.y) * dy > 0.0) || !((p.x - b.x) * -dx + (p.y - b.y) * -dy > 0.0)) continue;
    // Rounding each coordinate to a double moves a point by up to half an ulp per axis, so the
    // tolerance is kSnapUlps ulps of each axis's largest coordinate, projected on the normal
    // of the segment; times length, as an area like orient2d: |dy| ulp_x + |dx| ulp_y.
    const double ulp_x = std::max(ulps_at(std::max({std::fabs(a.x), std::fabs(b.x), std::fabs(p.x)}), 1.0), 0x1p-1074);
    const double ulp_y = std::max(ulps_at(std::max({std::fabs(a.y), std::fabs(b.y), std::fabs(p.y)}), 1.0), 0x1p-1074);
    const double limit = kSnapUlps * (std::fabs(dy) * ulp_x + std::fabs(dx) * ulp_y);
    const double plain = (a.x - p.x) * (b.y - p.y) - (a.y - p.y) * (b.x - p.x);
    if (std::fabs(plain) > 4.0 * limit) continue;
    const double area2 = std::fabs(exact::orient2d_value(a, b, p));
    if (area2 != 0.0 && area2 <= limit &&
        !snapped_pairs_.contains((std::uint64_t{piece.segment} << 32) | w))
      return w;
  }
  return kNone;
}

void SegmentInserter::release(EdgeRef e, VertexId w) {
  const Subsegment s = unconstrain(ed_.mesh, e);
  pending_.push_back({w, s.b, s.marker, s.segment});
  pending_.push_back({s.a, w, s.marker, s.segment});
}

// The new vertex's attributes are interpolated along the earlier segment's piece it splits, as
// for any vertex on a segment (Triangle interpolates along the subsegment it splits, too).
VertexId SegmentInserter::place_crossing(const Piece& piece, const Subsegment& old, const Point& p) {
  Mesh& mesh = ed_.mesh;
  const PointLocation at = walk_to_point(mesh, ed_.pred, ed_.leaving(old.a), p);
  switch (at.kind) {
    case PointLocation::Kind::OnVertex:
      return mesh.org(at.edge);
    case PointLocation::Kind::InTriangle: {
      const VertexId w = mesh.add_vertex(p, VertexKind::Segment);
      mesh.interpolate_attributes(w, old.a, old.b);
      ed_.insert_in_triangle(at.edge, w);
      return w;
    }
    case PointLocation::Kind::OnEdge: {
      const VertexId w = mesh.add_vertex(p, VertexKind::Segment);
      mesh.interpolate_attributes(w, old.a, old.b);
      // A third segment through the very same point: it is split there too.
      const bool released = mesh.subseg.has(at.edge);
      if (released) release(at.edge, w);
      ed_.insert_on_edge(at.edge, w);
      // The mesh was constrained Delaunay with that subsegment only: its halves (which a snap may
      // leave unconstrained) and the other edges at w are legalized too.
      if (released) ed_.legalize_star(w);
      return w;
    }
    case PointLocation::Kind::Outside:
      break;
  }
  // Rounding pushed the crossing out of the mesh (only possible next to the hull): use the
  // nearest of the four endpoints, a displacement of the order of that rounding.
  const VertexId candidates[4] = {piece.u, piece.v, old.a, old.b};
  VertexId best = candidates[0];
  for (const VertexId c : candidates)
    if (squared_distance(mesh.point(c), p) < squared_distance(mesh.point(best), p)) best = c;
  return best;
}

void SegmentInserter::split_crossing(const Piece& piece, EdgeRef g) {
  Mesh& mesh = ed_.mesh;
  ++counts_.crossings;
  const Point p = segment_intersection(mesh.point(piece.u), mesh.point(piece.v),
                                       mesh.point(mesh.org(g)), mesh.point(mesh.dest(g)));
  // Unconstrain g first so that the new vertex may flip it away (its halves are queued below),
  // and make the triangulation Delaunay without it: the new vertex may well miss g, and vertex
  // insertion restores the Delaunay property only if it held before.
  const Subsegment old = unconstrain(mesh, g);
  ed_.legalize_from(g);
  const VertexId w = place_crossing(piece, old, p);
  pending_.push_back({w, piece.v, piece.marker, piece.segment});
  pending_.push_back({piece.u, w, piece.marker, piece.segment});
  pending_.push_back({w, old.b, old.marker, old.segment});
  pending_.push_back({old.a, w, old.marker, old.segment});
}

}  // namespace deltri
