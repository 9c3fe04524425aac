// The subsegment side of the Terminator: Fig. 39, SPLITENCROACHEDSUBSEGMENTS.
#include <algorithm>
#include <cmath>

#include "geometry/constructions.h"
#include "geometry/encroachment.h"
#include "geometry/lattice.h"
#include "mesh/delete_vertex.h"
#include "mesh/operations.h"
#include "refine/bottom_scale.h"
#include "refine/concentric_shells.h"
#include "refine/lawson.h"
#include "refine/mirrored_split.h"
#include "refine/termination_guard.h"
#include "refine/terminator.h"
#include "util/invariant.h"

namespace deltri {

std::uint64_t Terminator::split_encroached_subsegments(bool queue_triangles, bool owed_to_size) {
  std::uint64_t splits = 0;
  while (!encroached_.empty()) {  // Fig. 39 l.36
    const EncroachedSubsegment entry = encroached_.pop();  // Fig. 39 l.37
    const EdgeRef s = current_edge(entry);  // Fig. 39 l.38
    if (s == kNone) continue;
    if (!budget_left()) {
      encroached_.clear();
      break;
    }
    if (split_subsegment(s, queue_triangles, owed_to_size)) ++splits;
  }
  return splits;
}

bool Terminator::uses_lenses() const { return opt_.lenses && !opt_.conforming_delaunay; }

// The length of the shortest edge that splitting s at p would make, now and once Chew's step (with
// lenses) has deleted the free vertices it deletes: a free vertex a rounding error from s's
// midpoint once made a split owed to a size bound look like a new edge of 1e-15.
Terminator::SplitRadius Terminator::split_radius(EdgeRef s, const Point& p) {
  const double now = split_insertion_radius(mesh_, pred_, s, p, marks_);
  if (!uses_lenses() || marks_.boundary().empty()) return {now, now};
  const Point& pa = mesh_.point(mesh_.org(s));
  const Point& pb = mesh_.point(mesh_.dest(s));
  double nearest2 = HUGE_VAL;
  for (EdgeRef e : marks_.boundary()) {  // the cavity's vertices are its boundary's
    const VertexId w = mesh_.org(e);
    const Point& q = mesh_.point(w);
    if (mesh_.kind[w] == VertexKind::Free && strictly_inside_diametral_circle(pa, pb, q) && too_close_to_split(w, p))
      continue;
    nearest2 = std::min(nearest2, squared_distance(q, p));
  }
  return {now, std::sqrt(nearest2)};
}

// Whether Chew's step deletes the free vertex w, inside the diametral circle of a subsegment about
// to be split at p: when p is nearer to w than w's nearest neighbour is. Chew deletes every free
// vertex in the circle, so that p's nearest visible neighbours are the subsegment's ends and no
// short edge appears (Sec. 4.2, proof of Lemma 5). A vertex at least as far from p as from its
// nearest neighbour x makes no edge at p shorter than the edge wx it already has; deleting it only
// undid refinement that was then done again: the side of a unit plate split late, its circle
// reaching a 1e-4 wide slit in the middle, deleted 41 vertices of the slit's grading, most of them
// far from p, and they were put back as before or finer. With the rule, p's insertion radius is at
// least wx (or the paper's radius if no vertex is kept), and of w and x the younger has an
// insertion radius at most wx: Lemma 5's relation r_v >= r_p cos(theta) holds with that vertex as
// parent (with the factor 1), and no edge shorter than those already there appears, which is what
// Theorem 4's argument for termination uses. Measured in docs/refinement.md ("Chew's deletion").
bool Terminator::too_close_to_split(VertexId w, const Point& p) {
  const Point& q = mesh_.point(w);
  const EdgeRef out = finder_.leaving(mesh_, w);
  if (out == kNone) return true;
  double nearest2 = HUGE_VAL;
  for_each_around(mesh_, out, [&](EdgeRef e) { nearest2 = std::min(nearest2, squared_distance(q, mesh_.point(mesh_.dest(e)))); });
  return squared_distance(q, p) < nearest2;
}

// Fig. 39 l.40-43, Chew's step: the free vertices inside the diametral circle of s that the two
// triangles beside s can see (a search that never crosses a subsegment) and that the split point p
// would come too close to (too_close_to_split) are deleted before s is split at p, so that with
// lenses no short edge appears at p. Returns the edge that now carries s (deletions rewrite slots),
// or kNone.
EdgeRef Terminator::delete_free_vertices_near(EdgeRef s, const Point& p, bool queue_triangles) {
  const VertexId a = mesh_.org(s), b = mesh_.dest(s);
  const Point& pa = mesh_.point(a);
  const Point& pb = mesh_.point(b);
  const auto inside = [&](VertexId w) { return strictly_inside_diametral_circle(pa, pb, mesh_.point(w)); };
  marks_.begin();
  std::vector<TriangleId> todo{triangle_of(s)};
  marks_.mark(todo[0]);
  if (mesh_.link[s] != kNone && marks_.mark(triangle_of(mesh_.link[s]))) todo.push_back(triangle_of(mesh_.link[s]));
  std::vector<VertexId> doomed;
  for (std::size_t k = 0; k < todo.size() && k < kDeletionSearchLimit; ++k) {
    const TriangleId t = todo[k];
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      const VertexId w = mesh_.org(e);
      const bool w_inside = w != a && w != b && inside(w);
      if (w_inside && mesh_.kind[w] == VertexKind::Free &&
          std::find(doomed.begin(), doomed.end(), w) == doomed.end() && too_close_to_split(w, p))
        doomed.push_back(w);
      const EdgeRef twin = mesh_.link[e];
      if (twin == kNone || mesh_.subseg[e] != kNone) continue;
      // Go on only through edges with an end inside the circle: the circle is convex, so the
      // triangles reached cover everything in it that the start can see.
      const VertexId x = mesh_.dest(e);
      if ((w_inside || (x != a && x != b && inside(x))) && marks_.mark(triangle_of(twin)))
        todo.push_back(triangle_of(twin));
    }
  }
  std::vector<TriangleId> created;
  for (VertexId w : doomed) {
    const EdgeRef out = finder_.leaving(mesh_, w);
    created.clear();
    if (out == kNone || !delete_vertex(mesh_, pred_, out, created)) continue;
    ++report_.vertices_deleted;
    // s moves only when w was the apex beside it, and then into one of the new triangles (a
    // finder could miss it at a vertex where two fans touch).
    if (!mesh_.is_live(triangle_of(s)) || mesh_.org(s) != a || mesh_.dest(s) != b) {
      s = kNone;
      for (TriangleId t : created)
        for (unsigned i = 0; i < 3; ++i)
          if (mesh_.org(edge_of(t, i)) == a && mesh_.dest(edge_of(t, i)) == b) s = edge_of(t, i);
      if (s == kNone) return kNone;  // cannot happen: the star's link keeps its edges
    }
    for (TriangleId t : created) {
      for (unsigned i = 0; i < 3; ++i) finder_.note(mesh_, edge_of(t, i));
      if (queue_triangles) enqueue_if_bad(t);  // Fig. 39 l.41-43
    }
  }
  return s;
}

bool Terminator::split_subsegment(EdgeRef s, bool queue_triangles, bool owed_to_size) {
  const VertexId a = mesh_.org(s), b = mesh_.dest(s);
  const Point& pa = mesh_.point(a);
  const Point& pb = mesh_.point(b);
  Point p;  // Fig. 39 l.39, across a thin wedge aligned with the vertex opposite (mirrored_split.h)
  if (!mirrored_split_point(mesh_, s, pieces_.of_subsegment[mesh_.subseg[s]], pieces_, p))
    p = shell_split_point(pa, pb, apices_.uses_shells(a), apices_.uses_shells(b));
  // Out of precision: p rounds onto an end, or a neighbour is flush with s there (unless it is one
  // that Chew's step below deletes; checked again after). Then, and at the bottom of double
  // precision, the doubles near p are tried (bottom_scale_split); if none will do, s is locked.
  const auto out_of_precision = [&](const Point& q) {
    // A split point that overflowed (segments spanning most of the double range) is no point.
    return !std::isfinite(q.x) || !std::isfinite(q.y) || q == pa || q == pb ||
           !split_keeps_orientation(s, q, uses_lenses());
  };
  if ((bottom_possible_ && at_bottom_scale(squared_distance(pa, pb), pa)) || out_of_precision(p)) {
    p = bottom_scale_split(s, p, uses_lenses());
    if (out_of_precision(p)) {
      lock(s);
      return false;
    }
  }
  const double floor = owed_to_size ? precision_floor(p) : floor_at(p);
  const SplitRadius radius = split_radius(s, p);
  if (radius.after_chew < floor) {
    refuse_by_guard();
    return false;
  }
  if (uses_lenses()) {  // Fig. 39 l.40-43
    s = delete_free_vertices_near(s, p, queue_triangles);
    if (s == kNone) return false;
    if (!split_keeps_orientation(s, p, false)) p = bottom_scale_split(s, p, false);
    if (!split_keeps_orientation(s, p, false)) {
      lock(s);
      return false;
    }
    // A free vertex in the circle that the deletion's search could not reach is still there.
    if (radius.now < floor && split_insertion_radius(mesh_, pred_, s, p, marks_) < floor) {
      refuse_by_guard();
      return false;
    }
  }
  const VertexId v = add_segment_vertex(p, s);
  const PieceEnds piece = pieces_.of_subsegment[mesh_.subseg[s]];
  EdgeRef out = split_edge(mesh_, s, v);  // Fig. 39 l.44
  pieces_.record_split(mesh_, v, piece);
  out = restore_delaunay_around(mesh_, pred_, v, out);
  DELTRI_ASSERT(mesh_.org(out) == v);  // new_vertex walks v's star from out
  ++report_.segment_steiner;
  ++report_.encroached_splits;
  new_vertex(out, queue_triangles);  // Fig. 39 l.45
  for_each_around(mesh_, out, [&](EdgeRef e) {  // Fig. 39 l.46-49: the halves s1 and s2
    for (EdgeRef half : {e, lprev(e)})
      if (mesh_.subseg[half] != kNone && is_splittable(half) && is_encroached(mesh_, pred_, half, rule_))
        enqueue_subsegment(half);
  });
  return true;
}

// split_edge joins p to the apices on both sides of s. p is rounded, so it is rarely exactly on s;
// when an apex lies within rounding distance of s (a vertex flush with a segment, beyond what
// doubles resolve), p can land on the far side of the line through that apex and a clockwise
// triangle would appear. Such a split is refused, like one whose point rounds onto an endpoint.
bool Terminator::split_keeps_orientation(EdgeRef s, const Point& p, bool chew_pending) {
  for (EdgeRef e : {s, mesh_.link[s]}) {
    if (e == kNone) continue;
    const Point& o = mesh_.point(mesh_.org(e));
    const Point& d = mesh_.point(mesh_.dest(e));
    const VertexId apex = mesh_.apex(e);
    const Point& c = mesh_.point(apex);
    if (chew_pending && mesh_.kind[apex] == VertexKind::Free && strictly_inside_diametral_circle(o, d, c)) continue;
    if (pred_.orient2d(o, p, c) <= 0 || pred_.orient2d(p, d, c) <= 0) return false;
  }
  return true;
}

void Terminator::enqueue_subsegment(EdgeRef e) {
  DELTRI_ASSERT(mesh_.subseg[e] != kNone);
  encroached_.push({e, mesh_.org(e), mesh_.dest(e)});
}

EdgeRef Terminator::current_edge(const EncroachedSubsegment& entry) {
  const auto is_it = [&](EdgeRef e) {
    if (e == kNone || e >= mesh_.corner.size() || !mesh_.is_live(triangle_of(e))) return false;
    if (mesh_.subseg[e] == kNone) return false;
    const VertexId o = mesh_.org(e), d = mesh_.dest(e);
    return (o == entry.a && d == entry.b) || (o == entry.b && d == entry.a);
  };
  if (is_it(entry.edge)) return entry.edge;
  const EdgeRef found = finder_.find(mesh_, entry.a, entry.b);
  return is_it(found) ? found : kNone;
}

bool Terminator::is_splittable(EdgeRef e) const {
  if (kept_by_switch(e)) return false;
  const SubsegmentId id = mesh_.subseg[e];
  if (id == kSeamEdge) return false;
  return id >= locked_.size() || !locked_[id];
}

bool Terminator::kept_by_switch(EdgeRef e) const {
  return opt_.no_steiner_on_segments >= 2 || (opt_.no_steiner_on_segments == 1 && mesh_.link[e] == kNone);
}

// The probe just made recorded the subsegments on the cavity's boundary (CavityMarks). c would
// make a triangle with each of them; one that c encroaches and -Y/-YY keeps whole refuses c only
// if that triangle would be no better than t. Refusing every such c leaves the triangles along a
// long kept segment as they are, and points inserted beyond its diametral circle then cut them
// into slivers against the short edges near its ends (river.poly: 0.72 degrees where 3 were
// possible); a c that makes a better triangle than the one it removes only improves the mesh.
bool Terminator::encroaches_kept_boundary(const Point& c, TriangleId t) {
  if (opt_.no_steiner_on_segments == 0) return false;
  const EdgeRef e0 = edge_of(t, 0);
  const double worst = smallest_angle_sine2(mesh_.point(mesh_.org(e0)), mesh_.point(mesh_.dest(e0)),
                                            mesh_.point(mesh_.apex(e0)));
  for (EdgeRef e : marks_.boundary_subsegments()) {
    const Point& a = mesh_.point(mesh_.org(e));
    const Point& b = mesh_.point(mesh_.dest(e));
    if (kept_by_switch(e) && encroaches(pred_, a, b, c, rule_) && smallest_angle_sine2(a, b, c) <= worst)
      return true;
  }
  return false;
}

// A subsegment that doubles cannot split (the split point rounds onto an end, or a neighbour lies
// flush with it there) is treated as -Y treats the boundary from then on. Trying again only
// repeated the failure, and where Chew's step had deleted free vertices first, their triangles came
// back with new ones: robustness1.node at -a0.93 went round that loop 177,000 times, to the Steiner
// cap (361,425 points, 354,083 deletions).
void Terminator::lock(EdgeRef s) {
  const SubsegmentId id = mesh_.subseg[s];
  if (id >= locked_.size()) locked_.resize(mesh_.subsegments.size(), 0);
  locked_[id] = 1;
  ++report_.locked_subsegments;
}

// A segment vertex takes the segment's marker and attributes interpolated along the subsegment.
VertexId Terminator::add_segment_vertex(const Point& p, EdgeRef s) {
  const VertexId a = mesh_.org(s), b = mesh_.dest(s);
  const VertexId v = mesh_.add_vertex(p, VertexKind::Segment);
  if (!mesh_.marker.empty()) mesh_.marker[v] = mesh_.subsegments[mesh_.subseg[s]].marker;
  mesh_.interpolate_attributes(v, a, b);
  return v;
}

}  // namespace deltri
