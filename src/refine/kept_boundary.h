// -Y / -YY as refinement sees them: the subsegments kept whole (every boundary one with -Y, every
// one with -YY) and the rules that keep the triangles on them from being spoiled by points that
// nothing can then split (kept_boundary.cpp). Chosen once from RefineOptions; without -Y every
// question answers no at the cost of one test, and the Terminator's core asks them the same way
// whether -Y was given or not. The mending once the queue is empty is its own policy (mending.h).
#pragma once

#include <vector>

#include "geometry/point.h"
#include "mesh/mesh.h"
#include "refine/candidate_probe.h"

namespace deltri {

struct RefineOptions;
class Terminator;

// Whether -Y or -YY keep subsegments whole (the Steiner policy's choice reads it: steiner_policy.h).
bool keeps_boundary(const RefineOptions& opt);

class KeptBoundary {
 public:
  explicit KeptBoundary(const RefineOptions& opt);
  // Rule (0)'s floor, from the mesh the Terminator starts from.
  void start(const Mesh& mesh, bool size_bounds);
  bool active() const { return level_ != 0; }
  // Whether the subsegment on e is kept whole.
  bool keeps(const Mesh& mesh, EdgeRef e) const { return level_ >= 2 || (level_ == 1 && mesh.link[e] == kNone); }
  // sin^2 of the angle bound, of the least lens without -q.
  double bound_sin2() const { return bound_sin2_; }
  // Fig. 38 l.15-17: is the point c, just probed for bad triangle t, refused?
  bool refuses_insertion(Terminator& term, const Point& c, TriangleId t) { return active() && refuses(term, c, t); }
  // Fig. 39 l.39: is the split of interior subsegment s at p, just probed, refused?
  bool refuses_split(Terminator& term, EdgeRef s, const Point& p) { return checks_splits_ && spoils_split(term, s, p); }
  // Whether refuses_split reads the cavity of the split's radius search.
  bool checks_splits() const { return checks_splits_; }

 private:
  bool refuses(Terminator& term, const Point& c, TriangleId t);
  bool spoils_split(Terminator& term, EdgeRef s, const Point& p);
  // Would c make a triangle below `below` (sin^2) whose own Steiner point no insertion can use?
  bool would_strand(Terminator& term, const Point& c, double below);
  bool stranded_point(Terminator& term, TriangleId from, const Point& p);
  double smallest_made_sine2(Terminator& term, const Point& c) const;  // over the triangles c makes
  double smallest_replaced_sine2(Terminator& term) const;              // over the cavity's triangles

  int level_ = 0;               // 0, 1 (-Y) or 2 (-YY)
  bool checks_splits_ = false;  // -Y without -D, which needs every encroached subsegment split
  double bound_sin2_ = 0.0;
  // sin^2 of min(that angle, the initial mesh's smallest), of half that angle without a size
  // bound, where every subsegment is kept; else 0.
  double floor_sin2_ = 0.0;
  CavityMarks lookahead_marks_;  // would_strand's probes, which must not disturb the Terminator's
};

}  // namespace deltri
