// The mesh checks other than segment coverage. Every geometric decision is an exact predicate.
#include <algorithm>
#include <map>

#include "verify.h"

namespace mv {
namespace {

std::string tri_name(const Context& c, int t) { return "triangle " + std::to_string(t + c.out.first); }
std::string vtx_name(const Context& c, int v) { return "vertex " + std::to_string(v + c.out.first); }
std::string edge_name(const Context& c, int a, int b) {
  return "edge " + std::to_string(a + c.out.first) + "-" + std::to_string(b + c.out.first);
}

bool less_xy(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// The input's distinct points.
std::vector<Point> distinct_input_points(const InputPslg& in) {
  std::vector<Point> pts = in.points;
  std::sort(pts.begin(), pts.end(), less_xy);
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  return pts;
}

// Edge a->b lies on the boundary of the convex hull (ccw): no hull vertex strictly to its right.
bool on_hull(deltri::Predicates& pred, const std::vector<Point>& hull, const Point& a, const Point& b) {
  return std::all_of(hull.begin(), hull.end(), [&](const Point& h) { return pred.orient2d(a, b, h) >= 0; });
}

}  // namespace

std::vector<Point> convex_hull(std::vector<Point> pts, deltri::Predicates& pred) {
  std::sort(pts.begin(), pts.end(), less_xy);
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<Point> hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {  // lower hull
    while (k >= 2 && pred.orient2d(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && pred.orient2d(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

void check_triangles_ccw(Context& c, Failures& f) {
  for (std::size_t t = 0; t < c.out.triangles.size(); ++t)
    if (!(c.pred.orient2d(c.tri_point(t, 0), c.tri_point(t, 1), c.tri_point(t, 2)) > 0))
      f.add("orientation", tri_name(c, t) + " is not strictly counter-clockwise");
}

// Each directed edge at most once; the boundary edges (no twin) form closed loops, i.e. every
// vertex starts as many boundary edges as it ends.
void check_edges_and_loops(Context& c, Failures& f) {
  std::map<std::uint64_t, int> seen;
  std::vector<int> balance(c.out.points.size(), 0);
  for (std::size_t t = 0; t < c.out.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = c.out.triangles[t][i], b = c.out.triangles[t][(i + 1) % 3];
      if (++seen[edge_key(a, b)] == 2) f.add("topology", edge_name(c, a, b) + " is used twice in the same direction");
      if (!c.topo.has_twin(a, b)) {
        ++balance[a];
        --balance[b];
      }
    }
  for (std::size_t v = 0; v < balance.size(); ++v)
    if (balance[v] != 0) f.add("topology", "boundary edges at " + vtx_name(c, v) + " do not form closed loops");
}

// An interior vertex (no boundary edge at it) must be surrounded exactly once by its triangles:
// the winding number of its link polygon about it is 1 (Sunday's crossing rule, exact).
void check_vertex_fans(Context& c, Failures& f) {
  std::vector<std::vector<std::pair<int, int>>> link(c.out.points.size());
  std::vector<char> boundary(c.out.points.size(), 0);
  for (const auto& tri : c.out.triangles)
    for (int i = 0; i < 3; ++i) {
      const int v = tri[i], a = tri[(i + 1) % 3], b = tri[(i + 2) % 3];
      link[v].push_back({a, b});
      if (!c.topo.has_twin(v, a)) boundary[v] = boundary[a] = 1;
    }
  for (std::size_t v = 0; v < link.size(); ++v) {
    if (link[v].empty() || boundary[v]) continue;
    const Point& p = c.out.points[v];
    int winding = 0;
    for (const auto& [ia, ib] : link[v]) {
      const Point &a = c.out.points[ia], &b = c.out.points[ib];
      if (a.y <= p.y) {
        if (b.y > p.y && c.pred.orient2d(a, b, p) > 0) ++winding;
      } else if (b.y <= p.y && c.pred.orient2d(a, b, p) < 0) {
        --winding;
      }
    }
    if (winding != 1) f.add("topology", "the triangles around interior " + vtx_name(c, v) + " wind " + std::to_string(winding) + " times");
  }
}

void check_distinct_vertices(Context& c, Failures& f) {
  std::vector<int> used;
  for (std::size_t v = 0; v < c.out.points.size(); ++v)
    if (c.topo.used[v]) used.push_back(static_cast<int>(v));
  std::sort(used.begin(), used.end(), [&](int a, int b) { return less_xy(c.out.points[a], c.out.points[b]); });
  for (std::size_t k = 1; k < used.size(); ++k)
    if (c.out.points[used[k]] == c.out.points[used[k - 1]])
      f.add("duplicates", vtx_name(c, used[k - 1]) + " and " + vtx_name(c, used[k]) + " share coordinates " + fmt(c.out.points[used[k]]));
}

// An input vertex that is not a mesh vertex (compared exactly) must lie outside every closed triangle.
void check_input_vertices(Context& c, Failures& f) {
  for (const Point& p : distinct_input_points(c.in)) {
    if (c.topo.used_at.count(p)) continue;
    for (int t : c.triangles_near(p, p)) {
      const Point a = c.tri_point(t, 0), b = c.tri_point(t, 1), d = c.tri_point(t, 2);
      if (c.pred.orient2d(a, b, p) >= 0 && c.pred.orient2d(b, d, p) >= 0 && c.pred.orient2d(d, a, p) >= 0) {
        f.add("input vertices", "input vertex " + fmt(p) + " lies in " + tri_name(c, t) + " but is not a mesh vertex");
        break;
      }
    }
  }
}

void check_boundary_edges(Context& c, Failures& f) {
  const std::vector<Point> hull = c.convex_hull ? convex_hull(c.in.points, c.pred) : std::vector<Point>{};
  for (const auto& tri : c.out.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = tri[i], b = tri[(i + 1) % 3];
      if (c.topo.has_twin(a, b) || c.segment_edges.count(undirected_key(a, b))) continue;
      if (c.convex_hull && on_hull(c.pred, hull, c.out.points[a], c.out.points[b])) continue;
      f.add("boundary", "boundary " + edge_name(c, a, b) + " lies on no input segment" + (c.convex_hull ? " and not on the convex hull" : ""));
    }
}

// Whether h lies exactly on a closed input segment: such a hole point is ignored (the manual's
// rule, as Triangle's), and refinement may round the segment's chain off it.
bool on_input_segment(Context& c, const Point& h) {
  for (const auto& s : c.in.segments) {
    const Point &a = c.in.points[s.a], &b = c.in.points[s.b];
    if (h.x < std::min(a.x, b.x) || h.x > std::max(a.x, b.x) || h.y < std::min(a.y, b.y) || h.y > std::max(a.y, b.y)) continue;
    if (on_closed_segment(c.pred, a, b, h)) return true;
  }
  return false;
}

// A hole point may not lie inside a triangle nor on an edge that is not a segment.
void check_holes(Context& c, Failures& f) {
  if (c.no_holes) return;
  for (const Point& h : c.in.holes) {
    if (on_input_segment(c, h)) continue;
    for (int t : c.triangles_near(h, h)) {
      double o[3];
      for (int i = 0; i < 3; ++i) o[i] = c.pred.orient2d(c.tri_point(t, i), c.tri_point(t, (i + 1) % 3), h);
      if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
      const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
      bool bad = zeros == 0;
      for (int i = 0; i < 3 && zeros == 1; ++i)
        if (o[i] == 0) bad = !c.segment_edges.count(undirected_key(c.out.triangles[t][i], c.out.triangles[t][(i + 1) % 3]));
      if (bad) f.add("holes", "hole point " + fmt(h) + " lies in " + tri_name(c, t));
    }
  }
}

// Every interior edge that is not part of an input segment is locally Delaunay.
void check_constrained_delaunay(Context& c, Failures& f) {
  for (std::size_t t = 0; t < c.out.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = c.out.triangles[t][i], b = c.out.triangles[t][(i + 1) % 3], apex = c.out.triangles[t][(i + 2) % 3];
      if (a > b || c.segment_edges.count(undirected_key(a, b))) continue;
      const auto twin = c.topo.directed.find(edge_key(b, a));
      if (twin == c.topo.directed.end()) continue;
      const int u = twin->second / 3, j = twin->second % 3;
      const int other = c.out.triangles[u][(j + 2) % 3];
      if (c.pred.incircle(c.out.points[a], c.out.points[b], c.out.points[apex], c.out.points[other]) > 0)
        f.add("delaunay", edge_name(c, a, b) + " is not locally Delaunay");
    }
}

// A point set's triangulation covers its convex hull: 2n - 2 - h triangles for n distinct points,
// h of them on the hull's boundary (0 when they are collinear or fewer than three).
void check_point_set_cover(Context& c, Failures& f) {
  if (c.in.is_poly) return;
  const std::vector<Point> pts = distinct_input_points(c.in);
  const std::vector<Point> hull = convex_hull(pts, c.pred);
  long expected = 0;
  if (hull.size() >= 3) {
    long on_boundary = 0;
    for (const Point& p : pts)
      for (std::size_t k = 0; k < hull.size(); ++k)
        if (on_closed_segment(c.pred, hull[k], hull[(k + 1) % hull.size()], p)) {
          ++on_boundary;
          break;
        }
    expected = 2 * static_cast<long>(pts.size()) - 2 - on_boundary;
  }
  if (static_cast<long>(c.out.triangles.size()) != expected)
    f.add("convex hull", std::to_string(c.out.triangles.size()) + " triangles; a triangulation of the " + std::to_string(pts.size()) +
                             " distinct points has " + std::to_string(expected));
  for (const auto& tri : c.out.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = tri[i], b = tri[(i + 1) % 3];
      if (!c.topo.has_twin(a, b) && !on_hull(c.pred, hull, c.out.points[a], c.out.points[b]))
        f.add("convex hull", "boundary " + edge_name(c, a, b) + " is not on the convex hull");
    }
}

// .neigh: neighbour i lies across the edge opposite corner i. .edge: every mesh edge once, markers
// nonzero on the boundary and zero on interior non-segment edges. .poly: its segments are mesh
// edges and include every boundary edge.
void check_side_files(Context& c, Failures& f) {
  const auto& tris = c.out.triangles;
  if (c.out.neighbors) {
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int i = 0; i < 3; ++i) {
        const int a = tris[t][(i + 1) % 3], b = tris[t][(i + 2) % 3];
        const auto twin = c.topo.directed.find(edge_key(b, a));
        const int expected = twin == c.topo.directed.end() ? -1 : twin->second / 3;
        if ((*c.out.neighbors)[t][i] != expected)
          f.add("neigh", tri_name(c, t) + ": neighbour " + std::to_string(i) + " should be " +
                             std::to_string(expected < 0 ? -1 : expected + c.out.first));
      }
  }
  std::unordered_set<std::uint64_t> mesh_edges;
  for (const auto& tri : tris)
    for (int i = 0; i < 3; ++i) mesh_edges.insert(undirected_key(tri[i], tri[(i + 1) % 3]));
  if (c.out.edges) {
    std::unordered_set<std::uint64_t> listed;
    for (const EdgeLine& e : *c.out.edges) {
      const std::uint64_t key = undirected_key(e.a, e.b);
      if (!mesh_edges.count(key)) f.add("edge", edge_name(c, e.a, e.b) + " in the .edge is not a mesh edge");
      if (!listed.insert(key).second) f.add("edge", edge_name(c, e.a, e.b) + " is listed twice in the .edge");
      if (!e.marker) continue;
      const bool boundary = !c.topo.has_twin(e.a, e.b) || !c.topo.has_twin(e.b, e.a);
      if (boundary && *e.marker == 0) f.add("edge", "boundary " + edge_name(c, e.a, e.b) + " has marker 0");
      if (!boundary && !c.segment_edges.count(key) && *e.marker != 0)
        f.add("edge", "interior non-segment " + edge_name(c, e.a, e.b) + " has marker " + std::to_string(*e.marker));
    }
    if (listed.size() != mesh_edges.size())
      f.add("edge", "the .edge lists " + std::to_string(listed.size()) + " edges; the mesh has " + std::to_string(mesh_edges.size()));
  }
  if (c.out.poly_segments) {
    std::unordered_set<std::uint64_t> listed;
    for (const EdgeLine& e : *c.out.poly_segments) {
      listed.insert(undirected_key(e.a, e.b));
      if (!mesh_edges.count(undirected_key(e.a, e.b))) f.add("poly", "output segment " + edge_name(c, e.a, e.b) + " is not a mesh edge");
    }
    for (const auto& tri : tris)
      for (int i = 0; i < 3; ++i) {
        const int a = tri[i], b = tri[(i + 1) % 3];
        if (!c.topo.has_twin(a, b) && !listed.count(undirected_key(a, b)))
          f.add("poly", "boundary " + edge_name(c, a, b) + " is missing from the output .poly");
      }
  }
}

}  // namespace mv
