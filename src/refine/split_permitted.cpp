#include "refine/split_permitted.h"

#include <cmath>

namespace deltri {
namespace {

double edge_length(const Mesh& mesh, EdgeRef e) {
  const Point& a = mesh.point(mesh.org(e));
  const Point& b = mesh.point(mesh.dest(e));
  return std::hypot(b.x - a.x, b.y - a.y);
}

// The cluster at org(e) if org(e) is an apex, else an empty one.
Cluster cluster_at_origin(const Mesh& mesh, const SegmentApices& apices, EdgeRef e) {
  if (!apices.is_apex(mesh.org(e))) return Cluster{};
  return subsegment_cluster(mesh, e);
}

// The same subsegment seen from its other endpoint: the twin, or, on the domain boundary, the
// edge found by turning around the destination.
EdgeRef reversed(const Mesh& mesh, EdgeRef e) {
  if (mesh.link[e] != kNone) return mesh.link[e];
  // Boundary edge: turn clockwise around dest(e) until the edge back to org(e).
  const VertexId back = mesh.org(e);
  EdgeRef f = lnext(e);  // leaves dest(e)
  while (true) {
    if (mesh.dest(f) == back) return f;
    const EdgeRef twin = mesh.link[f];
    if (twin == kNone) return kNone;
    f = lnext(twin);
  }
}

}  // namespace

bool is_power_of_two_length(double length) {
  if (!(length > 0.0)) return false;
  const double nearest = std::exp2(std::round(std::log2(length)));
  return std::fabs(length - nearest) <= kLengthTolerance * nearest;
}

bool split_permitted(const Mesh& mesh, const SegmentApices& apices, EdgeRef s, double d) {
  const Cluster at_org = cluster_at_origin(mesh, apices, s);
  Cluster at_dest;
  const EdgeRef back = reversed(mesh, s);
  if (back != kNone) at_dest = cluster_at_origin(mesh, apices, back);
  const double length = edge_length(mesh, s);
  // l.27-28: in no cluster, in two clusters, or not yet cut to a shell length.
  if (at_org.in_cluster() == at_dest.in_cluster() || !is_power_of_two_length(length)) return true;
  const Cluster& cluster = at_org.in_cluster() ? at_org : at_dest;
  // l.30-31: a shorter member means the cluster is already being cut down; follow suit.
  for (EdgeRef member : cluster.members)
    if (edge_length(mesh, member) < length * (1.0 - kLengthTolerance)) return true;
  // l.32-34: the shortest free edge that splitting the whole cluster to |s|/2 would create.
  const double r_min = length * std::sin(cluster.min_separation / 2.0);
  return r_min >= d;
}

}  // namespace deltri
