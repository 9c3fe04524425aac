// Checks of the files derived from the triangulation: -o2 midpoints, the -v Voronoi diagram and the
// -g .off. Each is compared with the .node/.ele of the same run and with geometry computed here.
#include <cmath>
#include <map>

#include "verify.h"

namespace mv {
namespace {

// The circumcentre in long double, from the formula relative to a (independent of deltri's
// construction code).
Point circumcentre(const Point& a, const Point& b, const Point& c, long double& radius) {
  const long double bx = static_cast<long double>(b.x) - a.x, by = static_cast<long double>(b.y) - a.y;
  const long double cx = static_cast<long double>(c.x) - a.x, cy = static_cast<long double>(c.y) - a.y;
  const long double d = 2 * (bx * cy - by * cx);
  const long double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const long double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  radius = std::sqrt(ux * ux + uy * uy);
  return {static_cast<double>(a.x + ux), static_cast<double>(a.y + uy)};
}

std::string num(int i, const Context& c) { return std::to_string(i + c.out.first); }

}  // namespace

void check_midpoints(Context& c, Failures& f) {
  if (c.out.midpoints.empty()) return;
  // Every edge has one midpoint node, shared by the triangles beside it, placed at its middle, and
  // never a corner of a triangle.
  std::map<std::uint64_t, int> node_of_edge;
  for (std::size_t t = 0; t < c.out.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = c.out.triangles[t][(k + 1) % 3], b = c.out.triangles[t][(k + 2) % 3];
      const int m = c.out.midpoints[t][k];
      const Point &pa = c.out.points[a], &pb = c.out.points[b], &pm = c.out.points[m];
      if (pm.x != 0.5 * (pa.x + pb.x) || pm.y != 0.5 * (pa.y + pb.y))
        f.add("midpoints", "triangle " + num(static_cast<int>(t), c) + ": node " + std::to_string(k + 4) + " (" +
                               num(m, c) + ") is not the midpoint of the side opposite corner " + std::to_string(k + 1));
      if (c.topo.used[m]) f.add("midpoints", "midpoint node " + num(m, c) + " is also a triangle corner");
      const auto [it, fresh] = node_of_edge.emplace(undirected_key(a, b), m);
      if (!fresh && it->second != m)
        f.add("midpoints", "edge " + num(a, c) + "-" + num(b, c) + " has two midpoint nodes " + num(it->second, c) + " and " + num(m, c));
    }
  std::map<int, int> uses;
  for (const auto& [edge, m] : node_of_edge) ++uses[m];
  for (const auto& [m, n] : uses)
    if (n > 1) f.add("midpoints", "node " + num(m, c) + " is the midpoint of " + std::to_string(n) + " edges");
}

void check_voronoi(Context& c, Failures& f) {
  if (!c.out.voronoi_points) return;
  const auto& vp = *c.out.voronoi_points;
  const std::size_t nt = c.out.triangles.size();
  if (vp.size() != nt) {
    f.add("voronoi", std::to_string(vp.size()) + " Voronoi vertices for " + std::to_string(nt) + " triangles");
    return;
  }
  // Vertex t is the circumcentre of triangle t: to within 1e-9 of the circumradius (plus the
  // coordinates' own magnitude, for tiny circles far from the origin).
  for (std::size_t t = 0; t < nt; ++t) {
    long double radius = 0;
    const Point cc = circumcentre(c.tri_point(t, 0), c.tri_point(t, 1), c.tri_point(t, 2), radius);
    const double scale = static_cast<double>(radius) + std::fabs(cc.x) + std::fabs(cc.y);
    if (std::hypot(vp[t].x - cc.x, vp[t].y - cc.y) > 1e-9 * scale)
      f.add("voronoi", "Voronoi vertex " + num(static_cast<int>(t), c) + " " + fmt(vp[t]) + " is not the circumcentre " + fmt(cc) +
                           " of triangle " + num(static_cast<int>(t), c));
  }
  // Each mesh edge has exactly one dual: a Voronoi edge between the two triangles sharing it, or a
  // ray from the triangle on the boundary, perpendicular to the edge and pointing away from it.
  std::map<std::uint64_t, std::vector<int>> triangles_of_edge;
  for (std::size_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i)
      triangles_of_edge[undirected_key(c.out.triangles[t][i], c.out.triangles[t][(i + 1) % 3])].push_back(static_cast<int>(t));
  std::map<std::pair<int, int>, int> pairs;          // neighbour pairs still to be matched
  std::map<int, std::vector<std::pair<int, int>>> hull_sides;  // triangle -> its boundary edges (a->b, ccw)
  for (std::size_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = c.out.triangles[t][i], b = c.out.triangles[t][(i + 1) % 3];
      const auto& owners = triangles_of_edge[undirected_key(a, b)];
      if (owners.size() == 1) hull_sides[static_cast<int>(t)].push_back({a, b});
      else if (owners.size() == 2 && owners[0] == static_cast<int>(t)) ++pairs[{owners[0], owners[1]}];
    }
  std::size_t rays = 0;
  for (std::size_t k = 0; k < c.out.voronoi_edges.size(); ++k) {
    const auto& e = c.out.voronoi_edges[k];
    const std::string name = "Voronoi edge " + num(static_cast<int>(k), c);
    if (e.b >= 0) {
      const auto key = std::make_pair(std::min(e.a, e.b), std::max(e.a, e.b));
      const auto it = pairs.find(key);
      if (it == pairs.end() || it->second == 0) {
        f.add("voronoi", name + " joins triangles " + num(e.a, c) + " and " + num(e.b, c) + ", which share no edge (or it is listed twice)");
        continue;
      }
      --it->second;
      continue;
    }
    ++rays;
    auto& sides = hull_sides[e.a];
    bool matched = false;
    for (std::size_t s = 0; s < sides.size() && !matched; ++s) {
      const Point &p = c.out.points[sides[s].first], &q = c.out.points[sides[s].second];
      const double ex = q.x - p.x, ey = q.y - p.y;
      const double len = std::hypot(ex, ey) * std::hypot(e.dx, e.dy);
      // Perpendicular, and to the right of the ccw edge a->b (the outside of its triangle).
      if (std::fabs(ex * e.dx + ey * e.dy) <= 1e-12 * len && ex * e.dy - ey * e.dx < 0) {
        sides.erase(sides.begin() + static_cast<long>(s));
        matched = true;
      }
    }
    if (!matched) f.add("voronoi", name + " is a ray from triangle " + num(e.a, c) + " that is not the outward normal of one of its boundary edges");
  }
  for (const auto& [key, left] : pairs)
    if (left > 0) f.add("voronoi", "triangles " + num(key.first, c) + " and " + num(key.second, c) + " share an edge but no Voronoi edge joins them");
  for (const auto& [t, sides] : hull_sides)
    if (!sides.empty()) f.add("voronoi", "a boundary edge of triangle " + num(t, c) + " has no Voronoi ray");
  (void)rays;
}

void check_off(Context& c, Failures& f) {
  if (!c.out.off_points) return;
  if (*c.out.off_points != c.out.points) f.add("off", "the .off vertices differ from the .node's (count or coordinates)");
  if (c.out.off_faces != c.out.triangles) f.add("off", "the .off faces differ from the .ele's triangles (numbered from 0)");
}

}  // namespace mv
