// Refinement at the bottom of double precision: inputs whose vertices are an ulp or two apart
// (robustness tests of other triangulators) need triangles a few ulps across. There the ideal
// Steiner point is still computed accurately (relative to a corner), but rounding it to doubles
// moves it by up to half an ulp in each coordinate, which at that scale can turn a good triangle
// into a sliver, or leave the bad one as it was. Below kBottomScaleUlps refinement therefore:
//  - refuses a triangle at once if no double can make a good triangle with its shortest edge
//    (hopeless_edge, geometry/lattice.h);
//  - otherwise tries the doubles near the ideal point (lattice_neighbourhood) and inserts the one
//    whose new triangles are best, those up to twice t's shortest edge first, among the points
//    whose cavity holds t, whose insertion radius is at least kBottomRadius2 (squared) of t's
//    shortest edge (so no shorter scale is started), and whose new triangles with no edge as long
//    as sqrt(2) times t's shortest are good, better than t, or no worse than the triangle they
//    replace on that edge (so bad triangles cannot spread at one scale); if there is none, no
//    point is inserted for t (the rounded ideal point may still ask for the subsegments it
//    encroaches upon to be split; otherwise it is a guard refusal), so a triangle that no nearby
//    double improves does not start a cascade;
//  - splits a subsegment at the double near its midpoint closest to the line of its segment piece
//    that keeps the triangles beside it counter-clockwise (BottomScale::split), which is also
//    tried at any scale when the rounded midpoint fails (a neighbour flush with the subsegment),
//    before the subsegment is locked;
//  - refuses the splits in strips narrower than an ulp and the splits that would creep along a
//    long piece one lattice step at a time (in_strip_below_an_ulp, creeping_split).
// These rules are the policy object BottomScale, fixed when a Terminator is built and owned by it;
// the Terminator asks it one question per decision. Ordinary meshes never get there: possible()
// is false when the feature floor is above the bottom scale everywhere, and then this costs one
// comparison per split.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <optional>
#include <vector>

#include "geometry/box.h"
#include "geometry/constructions.h"
#include "geometry/encroachment.h"
#include "geometry/point.h"
#include "geometry/predicates.h"
#include "mesh/mesh.h"
#include "refine/candidate_probe.h"
#include "refine/criteria.h"
#include "refine/termination_guard.h"

namespace deltri {

inline constexpr double kBottomScaleUlps = 64.0;
// How far from the ideal point the search goes, in steps of each axis's lattice.
inline constexpr int kBottomScaleSteps = 2;
// The shortest edge a bottom-scale insertion may make, squared, relative to the bad triangle's
// shortest edge: (1/sqrt 2)^2, the legs of a right isosceles triangle on it.
inline constexpr double kBottomRadius2 = 0.5;

// Is an edge of squared length `length2` at p shorter than kBottomScaleUlps units in the last
// place of p's larger coordinate (within a factor of two)?
inline bool at_bottom_scale(double length2, const Point& p) {
  const double bottom = ulps_at(magnitude(p), kBottomScaleUlps);
  return length2 < bottom * bottom;
}

// The edges of `mesh` at the bottom scale that no double can give a triangle with angles of at
// least theta (sin2_theta = sin^2 theta; 0 counts none). With `threads` 2 or more, a large mesh's
// two halves of the edges are counted at once.
std::uint64_t count_hopeless_edges(const Mesh& mesh, double sin2_theta, int threads = 1);

struct AlgorithmPolicy;
struct RefineOptions;
class Terminator;

class BottomScale {
 public:
  // From the mesh a Terminator starts on: the bottom scale is within reach when a size bound is
  // given or the guard's edge floor is below kBottomScaleUlps of the largest coordinate of
  // `extent`; then the initial edges no double can give a good triangle are counted (or taken
  // from `known_hopeless` when it is not negative).
  BottomScale(const Mesh& mesh, const RefineOptions& opt, const AlgorithmPolicy& policy, double guard_floor,
              const Box& extent, std::int64_t known_hopeless);
  // The initial edges no double can give a good triangle (report.hopeless_edges).
  std::uint64_t hopeless_edges() const { return hopeless_edges_; }
  // Is an edge of squared length length2 at p at the bottom scale, in a run that can get there?
  bool reached(double length2, const Point& p) const { return possible_ && at_bottom_scale(length2, p); }
  // The precision floor at p: precision_floor_at, or the coarse floor where an initial edge is
  // hopeless (the bottom scale cannot meet the bound there). The coarse floor
  // (2^-kCoarsePrecisionOctaves of the coordinates) is precision_floor_at times
  // 2^(kPrecisionOctaves - kCoarsePrecisionOctaves), exactly: one multiplication instead of a
  // branch on the hot path.
  double precision_floor(const Point& p) const { return precision_floor_at(p) * precision_scale_; }
  // The rule for strips: s, longer than the bottom scale, is encroached upon by the apex of a
  // triangle on it that is narrower than an ulp (or than a few ulps along a long s).
  bool in_strip_below_an_ulp(const Mesh& mesh, Predicates& pred, EdgeRef s) const;
  // Would splitting s (pa-pb, on the segment piece A-B) at p creep along the piece?
  static bool creeping_split(const Point& pa, const Point& pb, const Point& p, const Point& A, const Point& B);
  // The double near `ideal` whose insertion makes the best triangles, if they beat the worst one
  // it destroys; bad triangle t (assessed as a) must be among those.
  std::optional<Point> point(Terminator& term, TriangleId t, const Point& ideal, const Assessment& a);
  // The double near `ideal` that splits s best; `ideal` itself if none qualifies.
  Point split(Terminator& term, EdgeRef s, const Point& ideal, bool chew_pending);

 private:
  struct Score {
    double near, all;  // the smallest angle sines of the new triangles near t's scale, and of all
  };
  std::optional<Score> rate(Terminator& term, const Point& c, const KnownCavity& cavity, double l2, double t_sine2) const;
  bool beyond_boundary(Terminator& term, EdgeRef s, const Point& c) const;

  bool possible_ = false;  // whether any split can come within kBottomScaleUlps of the coordinates
  std::uint64_t hopeless_edges_ = 0;
  // 2^18 when an initial edge is hopeless: then the coarse precision floor applies everywhere.
  double precision_scale_ = 1.0;
  double good2_ = 0.0;               // sin^2 of the angle bound
  bool keeps_splits_inside_ = false;  // AlgorithmPolicy::keeps_splits_inside
  EncroachRule rule_;                 // AlgorithmPolicy::rule, for the strips
  std::vector<Point> scratch_;        // the candidates of point() and split()
};

}  // namespace deltri
