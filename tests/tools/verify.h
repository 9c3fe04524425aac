// deltri_mesh_verify: an independent end-to-end checker of deltri's output files.
//
// Everything here is written for the tests and shares nothing with deltri but the exact predicates
// (src/geometry/predicates.h): the files are read by our own parser so that deltri's readers and
// writers are checked too. The checks are those of an independent mesh checker's list (items 1-8, 12, and
// the quality item with --min-angle / --max-area).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "geometry/predicates.h"

namespace mv {

using deltri::Point;

// Collects failures: one line per failure, at most kShownPerKind lines per kind of check.
class Failures {
 public:
  void add(const std::string& kind, const std::string& message);
  bool empty() const { return counts_.empty(); }
  void print() const;  // to stdout

 private:
  static constexpr int kShownPerKind = 10;
  std::vector<std::string> lines_;
  std::map<std::string, int> counts_;
};

// ---- files (verify_files.cpp) ----

struct Segment {
  int a = 0, b = 0;  // zero-based positions in the vertex list
  int marker = 0;
};

// The input PSLG (a .node is a PSLG without segments and holes).
struct InputPslg {
  bool is_poly = false;
  std::vector<Point> points;
  std::vector<Segment> segments;  // only those with both endpoints in range
  std::vector<Point> holes;
};

struct EdgeLine {
  int a = 0, b = 0;  // zero-based
  std::optional<int> marker;
};

// deltri's output: OUTBASE.node and .ele, and .edge/.neigh/.poly when present.
struct OutputMesh {
  int first = 0;  // the .node's first index
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;  // zero-based
  std::optional<std::vector<EdgeLine>> edges;
  std::optional<std::vector<std::array<int, 3>>> neighbors;  // zero-based, -1 for none
  std::optional<std::vector<EdgeLine>> poly_segments;
  // -o2: nodes 4, 5, 6 of each .ele line (zero-based), the midpoints opposite corners 1, 2, 3.
  std::vector<std::array<int, 3>> midpoints;
  // -v: OUTBASE.v.node and OUTBASE.v.edge.
  struct VoronoiEdge {
    int a = 0, b = -1;  // zero-based Voronoi vertices; b == -1 for a ray
    double dx = 0, dy = 0;
  };
  std::optional<std::vector<Point>> voronoi_points;
  std::vector<VoronoiEdge> voronoi_edges;
  // -g: OUTBASE.off.
  std::optional<std::vector<Point>> off_points;
  std::vector<std::array<int, 3>> off_faces;
};

// Both return false (after adding failures of kind "parse") when the files cannot be used.
bool read_input(const std::string& path, InputPslg& in, Failures& f);
bool read_output(const std::string& base, OutputMesh& out, Failures& f);

// ---- topology and geometry helpers (verify_mesh.cpp) ----

inline std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
inline std::uint64_t undirected_key(int a, int b) { return a < b ? edge_key(a, b) : edge_key(b, a); }

// Exact coordinates as a hash key (-0 is folded into +0).
struct PointHash {
  std::size_t operator()(const Point& p) const;
};
using PointIndex = std::unordered_map<Point, int, PointHash>;

// A uniform grid over a bounding box, holding item ids (vertices or triangles) per cell.
class Grid {
 public:
  Grid(const std::vector<Point>& bbox_points, std::size_t items);
  void insert(int id, const Point& lo, const Point& hi);
  // Ids of every item whose box may meet the box [lo, hi] (may repeat ids).
  std::vector<int> query(const Point& lo, const Point& hi) const;

 private:
  int cell_x(double x) const;
  int cell_y(double y) const;
  double min_x_ = 0, min_y_ = 0, cell_w_ = 1, cell_h_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
};

struct Topology {
  std::unordered_map<std::uint64_t, int> directed;  // edge a->b -> 3 * triangle + corner of a
  std::vector<char> used;                           // vertex is a triangle corner
  std::vector<std::vector<int>> adjacent;           // vertex -> neighbouring vertices
  PointIndex used_at;                               // coordinates -> used vertex
  bool has_twin(int a, int b) const { return directed.count(edge_key(b, a)) != 0; }
};

struct Context {
  const InputPslg& in;
  const OutputMesh& out;
  Topology topo;
  deltri::Predicates pred;
  Grid triangle_grid;
  Grid vertex_grid;
  std::unordered_set<std::uint64_t> segment_edges;  // undirected mesh edges covering input segments
  std::vector<std::vector<int>> segments_at;        // mesh vertex -> input segments through it
  bool convex_hull = false;  // boundary edges may lie on the convex hull instead of segments
  bool no_holes = false;     // -O: the hole points were ignored
  bool refined = false;      // -q/-a: points split off segments are rounded, as crossings are

  Context(const InputPslg& input, const OutputMesh& output);
  Point tri_point(int t, int corner) const { return out.points[out.triangles[t][corner]]; }
  // Triangles whose bounding box meets the box of the two points.
  std::vector<int> triangles_near(const Point& p, const Point& q) const;
  // True if the open segment pq meets the interior of some triangle.
  bool open_segment_meets_mesh(const Point& p, const Point& q);
};

std::string fmt(const Point& p);

// p lies on the closed segment ab (exact).
bool on_closed_segment(deltri::Predicates& pred, const Point& a, const Point& b, const Point& p);
// The segments ab and de cross at a single point inside both (exact).
bool properly_cross(deltri::Predicates& pred, const Point& a, const Point& b, const Point& d, const Point& e);

// ---- the checks (verify_checks.cpp, verify_segments.cpp) ----

void check_triangles_ccw(Context& c, Failures& f);
void check_edges_and_loops(Context& c, Failures& f);
void check_vertex_fans(Context& c, Failures& f);
void check_distinct_vertices(Context& c, Failures& f);
void check_input_vertices(Context& c, Failures& f);
void check_segments(Context& c, Failures& f);  // fills c.segment_edges
void check_boundary_edges(Context& c, Failures& f);
void check_holes(Context& c, Failures& f);
void check_constrained_delaunay(Context& c, Failures& f);
void check_point_set_cover(Context& c, Failures& f);
void check_side_files(Context& c, Failures& f);
// verify_quality.cpp: angles and areas of a refined mesh (after check_segments).
void check_quality(Context& c, Failures& f, double min_angle_deg, double max_area);
// verify_dual.cpp: -o2 midpoints, the -v Voronoi files, the -g .off file.
void check_midpoints(Context& c, Failures& f);
void check_voronoi(Context& c, Failures& f);
void check_off(Context& c, Failures& f);

// Convex hull of the distinct points, counter-clockwise, without collinear points (verify_checks.cpp).
std::vector<Point> convex_hull(std::vector<Point> points, deltri::Predicates& pred);

}  // namespace mv
