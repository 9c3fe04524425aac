#include "cdt/convex_hull.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "geometry/constructions.h"
#include "mesh/subsegments.h"

namespace deltri {

std::size_t enclose_convex_hull(Mesh& mesh) { return constrain_boundary(mesh, 1); }

namespace {

bool is_hull_edge(const Mesh& mesh, EdgeRef e) {
  if (mesh.corner[e] == kNone || mesh.link[e] != kNone || !mesh.subseg.has(e)) return false;
  return mesh.subsegments[mesh.subseg[e]].segment == kNone;
}

// The boundary edge that leaves dest(e), for a boundary edge e: turn clockwise around dest(e).
EdgeRef next_boundary_edge(const Mesh& mesh, EdgeRef e) {
  EdgeRef g = lnext(e);
  for (std::size_t guard = 0; mesh.link[g] != kNone; ++guard) {
    if (guard > mesh.corner.size()) return kNone;
    g = lnext(mesh.link[g]);
  }
  return g;
}

// Whether v has a boundary edge among those around it (e leaves v).
bool on_boundary(const Mesh& mesh, EdgeRef e) {
  EdgeRef g = e;
  for (std::size_t guard = 0; guard <= mesh.corner.size(); ++guard) {
    const EdgeRef back = lprev(g);  // into v
    if (mesh.link[back] == kNone || mesh.link[g] == kNone) return true;
    g = mesh.link[back];  // onext: the next edge counter-clockwise around v
    if (g == e) return false;
  }
  return true;
}

struct Run {
  VertexId a, b;  // the strictly convex hull vertices at the ends of a collinear run of hull edges
};

}  // namespace

std::size_t absorb_near_hull_vertices(Mesh& mesh, Predicates& pred) {
  if (!mesh.has_subsegments()) return 0;
  std::vector<EdgeRef> hull;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
    if (is_hull_edge(mesh, e)) hull.push_back(e);
  if (hull.size() < 3) return 0;
  // straight[e]: the hull edge after e when the hull goes on straight through dest(e).
  std::unordered_map<EdgeRef, EdgeRef> straight;
  std::unordered_set<EdgeRef> continues_a_run;
  for (EdgeRef e : hull) {
    const EdgeRef n = next_boundary_edge(mesh, e);
    if (n == kNone || !is_hull_edge(mesh, n)) continue;
    if (pred.orient2d(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), mesh.point(mesh.dest(n))) != 0) continue;
    straight[e] = n;
    continues_a_run.insert(n);
  }
  std::unordered_map<EdgeRef, Run> run_of;
  std::vector<EdgeRef> work;
  for (EdgeRef first : hull) {
    if (continues_a_run.count(first)) continue;  // first begins at a corner
    std::vector<EdgeRef> run{first};
    for (auto it = straight.find(first); it != straight.end() && run.size() <= hull.size();
         it = straight.find(it->second))
      run.push_back(it->second);
    const Run r{mesh.org(run.front()), mesh.dest(run.back())};
    for (EdgeRef g : run) {
      run_of[g] = r;
      work.push_back(g);
    }
  }
  std::size_t absorbed = 0;
  while (!work.empty()) {
    const EdgeRef e = work.back();
    work.pop_back();
    const auto it = run_of.find(e);
    if (it == run_of.end() || !is_hull_edge(mesh, e)) continue;
    const Run r = it->second;
    const VertexId a = mesh.org(e), b = mesh.dest(e), v = mesh.apex(e);
    const Point &pa = mesh.point(a), &pb = mesh.point(b), &pv = mesh.point(v);
    const Point &ra = mesh.point(r.a), &rb = mesh.point(r.b);
    const double dx = rb.x - ra.x, dy = rb.y - ra.y;
    const double length = std::hypot(dx, dy);
    const double off = std::fabs(dx * (pv.y - ra.y) - dy * (pv.x - ra.x)) / length;
    if (!(off <= ulps_at(std::max(magnitude(ra), magnitude(rb)), kHullAbsorbUlps))) continue;
    // v must lie between a and b along the edge, and inside the hull (not on its boundary).
    const double ex = pb.x - pa.x, ey = pb.y - pa.y;
    if (!((pv.x - pa.x) * ex + (pv.y - pa.y) * ey > 0.0) || !((pb.x - pv.x) * ex + (pb.y - pv.y) * ey > 0.0))
      continue;
    if (on_boundary(mesh, lprev(e))) continue;
    const auto [av, vb] = peel_boundary_triangle(mesh, e);
    run_of[av] = r;
    run_of[vb] = r;
    work.push_back(av);
    work.push_back(vb);
    ++absorbed;
  }
  return absorbed;
}

}  // namespace deltri
