// Where to split a bad triangle (Fig. 38 l.13): its circumcentre, or Ungor's off-centre when that
// is nearer the shortest edge (geometry/constructions.h, off_center). Off-centres give fewer
// triangles for the same bound. Above kOptimalAboveDeg (or with --steiner=optimal) the point is
// Erten and Ungor's locally optimal one (PetalSearch below).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/mesh_bounds.h"
#include "geometry/point.h"
#include "geometry/predicates.h"
#include "mesh/mesh.h"

namespace deltri {

// The Steiner point for triangle_of(shortest), `shortest` being its shortest edge; off_center_factor
// is AngleBound::off_center_factor(), or 0 for the circumcentre (-k).
Point steiner_point(const Mesh& mesh, EdgeRef shortest, double off_center_factor);

// The same for a triangle abc (counter-clockwise) that is not in the mesh yet: -Y's look-ahead.
Point steiner_point_of(const Point& a, const Point& b, const Point& c, double off_center_factor);

// How much better than the bound theta the new triangle on the shortest edge is made: the petal is
// that of theta + kPetalMarginDeg, and a candidate is taken when that triangle's smallest angle is
// at least theta + kPetalMarginDeg / 2 (rounding cannot bring it below theta).
inline constexpr double kPetalMarginDeg = 0.1;

// Erten and Ungor's locally optimal Steiner points ("Quality triangulations with locally optimal
// Steiner points", SIAM J. Sci. Comput. 31(3), 2009). For a bad triangle pqr with shortest edge pq,
// the petal of pq is where a point x makes triangle pqx meet the bound: inside the arc through p
// and q from which pq subtends the bound's angle, and inside the rays from p and q at that angle to
// pq. Every point of the petal fixes pqr's shortest edge at once; the best of them is the one
// farthest from the vertices around it, for the new triangles are then as large as the bound
// allows and the refinement that follows has the least to do. The farthest point of a region from
// a set of sites is a Voronoi vertex inside it (the paper's Type IV), a crossing of a Voronoi edge
// with its boundary (Type III; the dual edge of pq gives the off-centre, Types I-II), or a corner
// of the region. PetalSearch gathers the triangles near pq, takes those points as candidates, and
// keeps the one whose nearest vertex is farthest; the off-centre when nothing beats it. A candidate
// must also lie inside pqr's circumcircle (exact incircle), or its insertion would leave pqr.
class PetalSearch {
 public:
  static constexpr std::size_t kSlots = 512;  // the gathered and refused triangles' index table (steiner_point.cpp)
  Point choose(const Mesh& mesh, Predicates& pred, EdgeRef shortest, double theta_deg, double off_center_factor);
  // For a triangle bad only for an angle above --max-angle, `longest` its edge opposite that
  // angle (obtuse_point.cpp): the candidate whose new triangles all meet both bounds, or else
  // `fallback` (its circumcentre).
  Point choose_for_obtuse(const Mesh& mesh, Predicates& pred, EdgeRef longest, const Point& fallback,
                          const AngleBound& angle, const LargestAngleBound& max_angle);
  // What the last search gathered (for tests): how many triangles, and whether t is among them.
  std::size_t gathered_count() const { return triangles_.size(); }
  bool gathered(TriangleId t) const { return index_of(t) >= 0; }
  // The squared distance from x to its nearest vertex as the last search took it for its candidates.
  double nearest2(const Point& x) const { return clearance2(x, reachable_); }

 private:
  struct Petal {
    Point p, q, r;
    Point top;                    // the petal's point on pq's bisector, farthest from pq
    Point arc_centre;             // the arc's circle
    double arc_radius = 0.0;
    Point ray_p, ray_q;           // the far ends of the rays from p and q, beyond the arc
    double sin2_min = 0.0;        // what triangle pqx must meet
    Point holder;                 // the disk from which pq subtends the bound itself: it holds the petal
    double holder_radius = 0.0;
  };
  struct Box {
    double x_lo, x_hi, y_lo, y_hi;
    // Disjoint from segment ab's bounding box for certain. An edge with a NaN or infinite end may
    // count as disjoint either way: its crossings are not finite, and admissible() refuses them.
    bool misses(const Point& a, const Point& b) const {
      return std::max(a.x, b.x) < x_lo || std::min(a.x, b.x) > x_hi || std::max(a.y, b.y) < y_lo ||
             std::min(a.y, b.y) > y_hi;
    }
    bool holds(const Point& x) const { return x.x >= x_lo && x.x <= x_hi && x.y >= y_lo && x.y <= y_hi; }  // not a NaN
  };
  struct Reach {  // pqr's circumcircle, the holder disk (both widened) and the fallback
    Point circle;
    double circle_radius;
    Point holder;
    double holder_radius;
    Point fallback;
    Point p, q, inward_p, inward_q;  // the lines through p and q at theta to pq, unit normals into the petal
    double rounding;                 // an absolute slack for the lines
    bool near(const Point& o, double r2) const;  // a circle (centre, squared radius) may hold such a point
    bool misses(const Point& a, const Point& b) const;
    // How far x is on the petal's side of the line at p, or at q, plus `pad` and the slack (below
    // 0: beyond it).
    double inside_p(const Point& x, double pad = 0.0) const { return inside(p, inward_p, x, pad); }
    double inside_q(const Point& x, double pad = 0.0) const { return inside(q, inward_q, x, pad); }
    double inside(const Point& on, const Point& inward, const Point& x, double pad) const {
      return inward.x * (x.x - on.x) + inward.y * (x.y - on.y) + pad + rounding;
    }
  };
  Reach reach_{};  // the last gather_near's
  struct Trig {  // of theta and phi = theta + kPetalMarginDeg
    double theta_deg = NAN;
    double tan_half_phi, tan_phi, sin_phi, cos_phi, tan_theta, sin_theta, cos_theta, sin_half_theta;
    double sin2_min;  // Petal::sin2_min
  };
  const Trig& trig_for(double theta_deg);
  Reach reach_of(const Petal& petal, const Point& fallback, const Trig& trig) const;
  static Petal petal_of(const Point& p, const Point& q, const Point& r, const Trig& trig);
  void gather(const Mesh& mesh, TriangleId t, const Point& centre, double reach);
  void describe_gathered(const Mesh& mesh, std::size_t explored);
  void note_vertex(const Mesh& mesh, VertexId v);
  void propose_corners(const Petal& petal);
  void propose_voronoi(const Petal& petal, const Box& near);
  Box admissible_box(const Petal& petal, const Point& fallback) const;
  Box gather_near(const Mesh& mesh, TriangleId t, const Petal& petal, const Point& fallback, const Trig& trig);
  void start_gathering(const Mesh& mesh, TriangleId t);
  void describe(std::size_t i);
  void note_vertices_and_rim(const Mesh& mesh, bool near_only);
  bool admissible(Predicates& pred, const Petal& petal, const Point& x) const;
  bool in_gathered(const Point& x) const;
  // Whether triangle t (counter-clockwise, closed) holds x, in floating point.
  static bool holds(const std::array<Point, 3>& t, const Point& x) {
    const auto left_of = [&](const Point& a, const Point& b) {
      return (b.x - a.x) * (x.y - a.y) - (b.y - a.y) * (x.x - a.x) >= 0.0;
    };
    return left_of(t[0], t[1]) && left_of(t[1], t[2]) && left_of(t[2], t[0]);
  }
  bool star_meets(const Point& x, double bound_sin2, bool in_box);
  enum class Verdict { Outside, Bad, Good };
  Verdict judge(const Point& x, double bound_sin2);
  void mark_cavity(const Point& x, const std::vector<int>& looked_at);
  bool marked_star_meets(const Point& x, double bound_sin2, const std::vector<int>& looked_at) const;
  void note_reachable_vertices(const Petal& petal, const Trig& trig);
  static double clearance2(const Point& x, const std::vector<Point>& vertices);
  std::size_t slot_of(TriangleId t) const;
  int index_of(TriangleId t) const;  // in triangles_, kRefused, or -1 (not looked at yet)
  void remember(TriangleId t, const Mesh::CornerPoints& at);
  int look_across(const Mesh& mesh, bool walls, std::size_t i, unsigned side, TriangleId& u) const;
  static constexpr int kWall = -3;
  void propose_obtuse(const Point& p, const Point& q, const Point& fallback);
  double star_margin(const Point& x, const AngleBound& angle, const LargestAngleBound& max_angle);
  int container_of(const Point& x) const;  // the gathered triangle holding x, or -1
  void mark_walls(const Mesh& mesh);
  void refuse(TriangleId t);  // looked at by gather and left out
  static constexpr int kRefused = -2;

  std::vector<TriangleId> triangles_;
  std::vector<Point> centres_;  // the circumcentres of triangles_: the Voronoi vertices near pq
  std::vector<double> radii2_;  // their squared circumradii
  std::vector<std::array<Point, 3>> corners_;  // per gathered triangle, counter-clockwise
  std::vector<std::array<int, 3>> neighbours_;  // per gathered triangle: the index across each side, or -1
  std::vector<char> in_cavity_;  // all 0 between star_meets' calls
  std::vector<int> near_;        // the gathered triangles whose circumcircles or corners may meet the admissible box
  std::vector<char> expanded_;   // per gathered triangle: its sides were looked across while gathering
  static constexpr char kLeftNear = 2;  // in expanded_ while gathering: a near one not gone through yet
  std::vector<int> all_;         // 0, 1, ... for star_meets outside that box
  std::vector<Point> vertices_;       // the gathered triangles' corners, each once
  std::vector<Point> reachable_;      // those an admissible candidate can have nearest (note_reachable_vertices)
  std::vector<std::uint32_t> seen_;   // per vertex id: the search that last noted it (note_vertex)
  std::uint32_t search_ = 0;
  std::vector<TriangleId> slots_;     // index_of's table: kSlots triangles or kNone
  std::vector<int> slot_index_ = std::vector<int>(kSlots, -1);
  std::vector<Point> candidates_;
  std::vector<std::array<bool, 3>> walls_;  // per gathered triangle: which sides are subsegments
  std::vector<int> stack_;
  Trig trig_;
};

}  // namespace deltri
