#include "quality/check_mesh.h"

#include <string>
#include <vector>

#include "geometry/predicates.h"
#include "mesh/overlap.h"

namespace deltri {
namespace {

struct KindInfo {
  const char* name;
  const char* subject;
  CheckLayer layer;
};

constexpr std::array<KindInfo, kFaultKinds> kKinds = {{
    {"array lengths disagree", "", CheckLayer::Storage},
    {"triangle corner is not a vertex", "triangle", CheckLayer::Storage},
    {"triangle repeats a vertex", "triangle", CheckLayer::Storage},
    {"bad free-list entry", "triangle", CheckLayer::Storage},
    {"dead triangle slot not on the free list", "triangle", CheckLayer::Storage},
    {"link is not an edge slot", "edge", CheckLayer::Storage},
    {"subsegment id out of range", "edge", CheckLayer::Storage},
    {"edge linked to a dead triangle", "edge", CheckLayer::Topology},
    {"link is not an involution", "edge", CheckLayer::Topology},
    {"twin edges without swapped endpoints", "edge", CheckLayer::Topology},
    {"directed edge in two triangles", "edge", CheckLayer::Topology},
    {"twin edges carry different subsegments", "edge", CheckLayer::Topology},
    {"subsegment endpoints differ from its edge", "edge", CheckLayer::Topology},
    {"duplicate or dead vertex used by a triangle", "vertex", CheckLayer::Topology},
    {"clockwise triangle", "triangle", CheckLayer::Orientation},
    {"flat triangle (collinear corners)", "triangle", CheckLayer::Orientation},
    {"boundary does not close up at vertex", "vertex", CheckLayer::Boundary},
    {"edge not locally Delaunay", "edge", CheckLayer::Delaunay},
    {"reflex turn of a convex-hull boundary", "edge", CheckLayer::ConvexHull},
    {"more than one boundary loop", "edge", CheckLayer::ConvexHull},
    {"input vertex in no triangle", "vertex", CheckLayer::ConvexHull},
    {"triangles overlap or meet other than at shared corners", "triangle", CheckLayer::Orientation},
}};

constexpr std::array<const char*, kCheckLayers> kLayerNames = {
    "storage", "topology", "orientation", "boundary", "Delaunay", "convex hull"};

std::size_t index(FaultKind kind) { return static_cast<std::size_t>(kind); }

// Runs the layers in order; each layer method assumes the layers it relies on found nothing.
class Checker {
 public:
  Checker(const Mesh& mesh, const CheckOptions& opt, CheckReport& report)
      : mesh_(mesh), opt_(opt), report_(report) {}

  void run() {
    check_storage();
    if (!clean(CheckLayer::Storage)) return skip_after(CheckLayer::Storage);
    // These three need only sound storage, so each still reports on a broken topology.
    check_topology();
    check_orientation();
    check_boundary();
    if (clean(CheckLayer::Topology) && clean(CheckLayer::Orientation)) check_overlap();
    const bool sound = clean(CheckLayer::Topology) && clean(CheckLayer::Orientation);
    if (sound)
      check_delaunay();
    else
      skip(CheckLayer::Delaunay);
    if (!opt_.convex_hull_expected) return;
    if (sound && clean(CheckLayer::Boundary))
      check_convex_hull();
    else
      skip(CheckLayer::ConvexHull);
  }

 private:
  bool clean(CheckLayer layer) const {
    for (std::size_t k = 0; k < kFaultKinds; ++k)
      if (kKinds[k].layer == layer && report_.counts[k] != 0) return false;
    return true;
  }
  void skip(CheckLayer layer) { report_.skipped[static_cast<std::size_t>(layer)] = true; }
  void skip_after(CheckLayer last_run) {
    for (std::size_t l = static_cast<std::size_t>(last_run) + 1; l < kCheckLayers; ++l) {
      if (static_cast<CheckLayer>(l) == CheckLayer::ConvexHull && !opt_.convex_hull_expected) break;
      report_.skipped[l] = true;
    }
  }
  void fault(FaultKind kind, std::uint32_t where) { report_.record(kind, where); }

  std::uint32_t slots() const { return mesh_.triangle_slots(); }
  std::uint32_t vertices() const { return mesh_.vertex_count(); }
  bool live(TriangleId t) const { return mesh_.is_live(t); }
  bool has_subsegment(EdgeRef e) const { return mesh_.has_subsegments() && mesh_.subseg.has(e); }
  const Point& at(VertexId v) const { return mesh_.points[v]; }

  // --- storage ---
  void check_storage() {
    if (!check_sizes()) return;
    check_triangle_slots();
    check_free_list();
    check_edge_ids();
  }

  // Returns false when indexing by the sizes would be unsafe, so nothing else may look.
  bool check_sizes() {
    const std::size_t nv = mesh_.points.size();
    const std::size_t ns = mesh_.corner.size() / 3;
    const auto expect = [this](bool good) {
      if (!good) fault(FaultKind::ArraySize, kNone);
    };
    expect(mesh_.kind.size() == nv);
    expect(mesh_.marker.empty() || mesh_.marker.size() == nv);
    expect(mesh_.num_attributes >= 0 &&
           mesh_.attributes.size() == static_cast<std::size_t>(mesh_.num_attributes) * nv);
    expect(mesh_.corner.size() % 3 == 0 && mesh_.corner.size() < kNone);
    expect(mesh_.link.size() == mesh_.corner.size());
    expect(mesh_.subseg.empty() || mesh_.subseg.size() == mesh_.corner.size());
    expect(mesh_.num_triangle_attributes >= 0 &&
           mesh_.triangle_attributes.size() ==
               static_cast<std::size_t>(mesh_.num_triangle_attributes) * ns);
    expect(mesh_.area_bound.empty() || mesh_.area_bound.size() == ns);
    expect(nv < kGhostVertex);
    return report_.count(FaultKind::ArraySize) == 0;
  }

  void check_triangle_slots() {
    for (TriangleId t{0}; t < slots(); ++t) {
      if (!live(t)) continue;
      const auto [a, b, c] = mesh_.corners(t);
      if (a >= vertices() || b >= vertices() || c >= vertices())
        fault(FaultKind::CornerOutOfRange, t);
      else if (a == b || b == c || c == a)
        fault(FaultKind::RepeatedCorner, t);
      ++report_.triangles_checked;
    }
  }

  void check_free_list() {
    std::vector<std::uint8_t> listed(slots(), 0);
    for (const TriangleId t : mesh_.free_triangles) {
      if (t >= slots() || live(t) || listed[t])
        fault(FaultKind::BadFreeListEntry, t);
      else
        listed[t] = 1;
    }
    for (TriangleId t{0}; t < slots(); ++t)
      if (!live(t) && !listed[t]) fault(FaultKind::UnlistedDeadSlot, t);
  }

  void check_edge_ids() {
    const std::size_t nsub = mesh_.subsegments.size();
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e) {
      if (!live(triangle_of(e))) continue;
      if (mesh_.link[e] != kNone && mesh_.link[e] >= mesh_.corner.size())
        fault(FaultKind::LinkOutOfRange, e);
      if (has_subsegment(e) && mesh_.subseg[e] >= nsub) fault(FaultKind::SubsegmentOutOfRange, e);
    }
  }

  // --- topology ---
  void check_topology() {
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e)
      if (live(triangle_of(e))) check_twin(e);
    build_out_edges();
    check_duplicate_edges();
    check_vertex_use();
  }

  void check_twin(EdgeRef e) {
    const EdgeRef f = mesh_.link[e];
    if (f != kNone) {
      if (!live(triangle_of(f))) return fault(FaultKind::LinkToDeadTriangle, e);
      if (mesh_.link[f] != e) return fault(FaultKind::LinkNotInvolution, e);
      if (mesh_.org(f) != mesh_.dest(e) || mesh_.dest(f) != mesh_.org(e))
        return fault(FaultKind::LinkEndpoints, e);
      if (f < e) return;  // the pair is judged once, from its smaller edge
      if (mesh_.has_subsegments() && mesh_.subseg[e] != mesh_.subseg[f])
        fault(FaultKind::SubsegmentMismatch, e);
    }
    ++report_.edges_checked;
    if (has_subsegment(e)) check_subsegment_endpoints(e);
  }

  void check_subsegment_endpoints(EdgeRef e) {
    const Subsegment& s = mesh_.subsegments[mesh_.subseg[e]];
    const VertexId a = mesh_.org(e), b = mesh_.dest(e);
    if (!((s.a == a && s.b == b) || (s.a == b && s.b == a))) fault(FaultKind::SubsegmentEndpoints, e);
  }

  // Groups the live edges' destinations by origin (a counting sort, linear time) so that repeated
  // directed edges can be found without hashing or sorting millions of keys.
  void build_out_edges() {
    first_out_.assign(static_cast<std::size_t>(vertices()) + 1, 0);
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e)
      if (live(triangle_of(e))) ++first_out_[mesh_.corner[e] + 1];
    for (VertexId v{0}; v < vertices(); ++v) first_out_[v + 1] += first_out_[v];
    out_dest_.resize(first_out_[vertices()]);
    for (TriangleId t{0}; t < slots(); ++t) {
      if (!live(t)) continue;
      const VertexId* c = mesh_.corners_at(t);
      out_dest_[first_out_[c[0]]++] = c[1];
      out_dest_[first_out_[c[1]]++] = c[2];
      out_dest_[first_out_[c[2]]++] = c[0];
    }
    // Each start was advanced to the next vertex's start; shift them back.
    for (VertexId v{vertices()}; v > 0; --v) first_out_[v] = first_out_[v - 1];
    first_out_[0] = 0;
  }

  bool used(VertexId v) const { return first_out_[v + 1] > first_out_[v]; }

  // Destinations rather than edge ids are grouped because reading them sequentially is what
  // makes this fast; the one example edge is looked up afterwards.
  void check_duplicate_edges() {
    std::vector<VertexId> seen_from(vertices(), kNone);  // seen_from[d] == v: v->d already met
    VertexId first_org = kNone, first_dest = kNone;
    for (VertexId v{0}; v < vertices(); ++v) {
      for (std::uint32_t i = first_out_[v]; i < first_out_[v + 1]; ++i) {
        const VertexId d = out_dest_[i];
        if (seen_from[d] != v) {
          seen_from[d] = v;
          continue;
        }
        if (first_org == kNone) first_org = v, first_dest = d;
        fault(FaultKind::DuplicateEdge, kNone);
      }
    }
    if (first_org != kNone)
      report_.examples[index(FaultKind::DuplicateEdge)] = second_edge(first_org, first_dest);
  }

  // The second live edge a->b in slot order (the one reported as the repeat).
  EdgeRef second_edge(VertexId a, VertexId b) const {
    bool met = false;
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e) {
      if (!live(triangle_of(e)) || mesh_.org(e) != a || mesh_.dest(e) != b) continue;
      if (met) return e;
      met = true;
    }
    return kNone;
  }

  void check_vertex_use() {
    for (VertexId v{0}; v < vertices(); ++v) {
      const VertexKind k = mesh_.kind[v];
      if ((k == VertexKind::Duplicate || k == VertexKind::Dead) && used(v))
        fault(FaultKind::DeadVertexUsed, v);
    }
  }

  // --- orientation ---
  void check_orientation() {
    for (TriangleId t{0}; t < slots(); ++t) {
      if (!live(t)) continue;
      const auto [a, b, c] = mesh_.corners(t);
      const double o = pred_.orient2d(at(a), at(b), at(c));
      if (o < 0.0) fault(FaultKind::ClockwiseTriangle, t);
      if (o == 0.0) fault(FaultKind::FlatTriangle, t);
    }
  }

  void check_overlap() {
    if (const auto found = find_overlap(mesh_, pred_)) fault(FaultKind::OverlappingTriangles, found->second);
  }

  // --- boundary ---
  // Boundary edges decompose into closed loops exactly when every vertex has as many boundary
  // edges leaving it as arriving. A sound topology implies this (twins pair arrivals with
  // departures), so its value is in locating the damage when the topology is broken.
  void check_boundary() {
    std::vector<std::int32_t> balance(vertices(), 0);
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e) {
      if (!live(triangle_of(e)) || mesh_.link[e] != kNone) continue;
      ++balance[mesh_.org(e)];
      --balance[mesh_.dest(e)];
    }
    for (VertexId v{0}; v < vertices(); ++v)
      if (balance[v] != 0) fault(FaultKind::OpenBoundary, v);
  }

  // --- delaunay ---
  void check_delaunay() {
    for (EdgeRef e{0}; e < mesh_.corner.size(); ++e) {
      if (!live(triangle_of(e))) continue;
      const EdgeRef f = mesh_.link[e];
      if (f == kNone || f < e) continue;
      if (has_subsegment(e) && !opt_.conforming) continue;
      if (pred_.incircle(at(mesh_.org(e)), at(mesh_.dest(e)), at(mesh_.apex(e)), at(mesh_.apex(f))) > 0.0)
        fault(FaultKind::NotLocallyDelaunay, e);
    }
  }

  // --- convex hull ---
  void check_convex_hull() {
    check_hull_loops();
    if (mesh_.live_triangles() > 0)
      check_inputs_used();
    else
      check_inputs_degenerate();
  }

  // The boundary edge that follows boundary edge e (a->b): the last edge leaving b when turning
  // clockwise from lnext(e) through the triangles around b. The walk cannot cycle when link is an
  // involution (returning to lnext(e) would need a twin of e), but is capped all the same.
  EdgeRef next_boundary_edge(EdgeRef e) const {
    EdgeRef f = lnext(e);
    for (std::size_t steps = 0; mesh_.link[f] != kNone && steps < mesh_.corner.size(); ++steps)
      f = lnext(mesh_.link[f]);
    return f;
  }

  // Follows every boundary loop once; each turn from an edge into its successor must be a left
  // turn or straight (collinear hull vertices are mesh vertices), and there must be one loop.
  // A hole in a point-set mesh is a clockwise loop, so it shows up as reflex turns as well.
  void check_hull_loops() {
    std::vector<std::uint8_t> seen(mesh_.corner.size(), 0);
    for (EdgeRef start{0}; start < mesh_.corner.size(); ++start) {
      if (!live(triangle_of(start)) || mesh_.link[start] != kNone || seen[start]) continue;
      if (++report_.boundary_loops > 1) fault(FaultKind::ExtraBoundaryLoop, start);
      EdgeRef e = start;
      do {
        seen[e] = 1;
        const EdgeRef n = next_boundary_edge(e);
        if (mesh_.link[n] != kNone) break;  // cap reached: cannot happen after the topology layer
        if (pred_.orient2d(at(mesh_.org(e)), at(mesh_.dest(e)), at(mesh_.dest(n))) < 0.0)
          fault(FaultKind::ReflexBoundaryTurn, n);
        e = n;
      } while (!seen[e]);
    }
  }

  void check_inputs_used() {
    for (VertexId v{0}; v < vertices(); ++v)
      if (mesh_.kind[v] == VertexKind::Input && !used(v)) fault(FaultKind::UnusedVertex, v);
  }

  // A point set without triangles is right only when it has fewer than three distinct points or
  // all of them are collinear; otherwise every input vertex went missing.
  void check_inputs_degenerate() {
    std::vector<VertexId> inputs;
    for (VertexId v{0}; v < vertices(); ++v)
      if (mesh_.kind[v] == VertexKind::Input) inputs.push_back(v);
    if (!spans_plane(inputs)) return;
    for (const VertexId v : inputs) fault(FaultKind::UnusedVertex, v);
  }

  bool spans_plane(const std::vector<VertexId>& vs) {
    if (vs.empty()) return false;
    const Point& p = at(vs[0]);
    std::size_t i = 1;
    while (i < vs.size() && at(vs[i]) == p) ++i;
    if (i == vs.size()) return false;
    const Point& q = at(vs[i]);
    for (; i < vs.size(); ++i)
      if (pred_.orient2d(p, q, at(vs[i])) != 0.0) return true;
    return false;
  }

  const Mesh& mesh_;
  const CheckOptions& opt_;
  CheckReport& report_;
  Predicates pred_;
  // out_dest_[first_out_[v] .. first_out_[v+1]) are the ends of the edges leaving v, in slot order.
  std::vector<std::uint32_t> first_out_;
  std::vector<VertexId> out_dest_;
};

std::string example_text(FaultKind kind, std::uint32_t where) {
  const char* subject = fault_subject(kind);
  if (*subject == '\0' || where == kNone) return "";
  return std::string(" (first: ") + subject + " " + std::to_string(where) + ")";
}

}  // namespace

const char* fault_name(FaultKind kind) { return kKinds[index(kind)].name; }
const char* fault_subject(FaultKind kind) { return kKinds[index(kind)].subject; }
CheckLayer fault_layer(FaultKind kind) { return kKinds[index(kind)].layer; }
const char* layer_name(CheckLayer layer) { return kLayerNames[static_cast<std::size_t>(layer)]; }

void CheckReport::record(FaultKind kind, std::uint32_t where) {
  const std::size_t k = index(kind);
  if (counts[k]++ == 0) examples[k] = where;
}

std::uint64_t CheckReport::total_faults() const {
  std::uint64_t total = 0;
  for (const std::uint64_t c : counts) total += c;
  return total;
}

std::string CheckReport::summary() const {
  const std::string checked = std::to_string(triangles_checked) + " triangles, " +
                              std::to_string(edges_checked) + " edges checked";
  std::string out;
  if (ok())
    out = "Mesh is consistent (" + checked + ").\n";
  else
    out = "Mesh check found " + std::to_string(total_faults()) + " faults (" + checked + "):\n";
  for (std::size_t k = 0; k < kFaultKinds; ++k) {
    if (counts[k] == 0) continue;
    const auto kind = static_cast<FaultKind>(k);
    out += "  " + std::string(fault_name(kind)) + ": " + std::to_string(counts[k]) +
           example_text(kind, examples[k]) + "\n";
  }
  std::string skipped_names;
  for (std::size_t l = 0; l < kCheckLayers; ++l) {
    if (!skipped[l]) continue;
    if (!skipped_names.empty()) skipped_names += ", ";
    skipped_names += kLayerNames[l];
  }
  if (!skipped_names.empty())
    out += "  not checked because of the faults above: " + skipped_names + "\n";
  return out;
}

CheckReport check_mesh(const Mesh& mesh, const CheckOptions& opt) {
  CheckReport report;
  Checker(mesh, opt, report).run();
  return report;
}

}  // namespace deltri
