#include "api/output_arrays.h"

#include "io/edge_file.h"
#include "io/output_numbering.h"
#include "io/poly_file.h"
#include "io/voronoi_file.h"

namespace deltri {
namespace {

int as_int(long long x) { return static_cast<int>(x); }

// As write_node_file.
void fill_points(api::Mesh& out, const Mesh& mesh, const VertexNumbering& number, const Options& sw) {
  const std::size_t na = static_cast<std::size_t>(mesh.num_attributes);
  out.point_attribute_count = mesh.num_attributes;
  out.point_count = as_int(number.written_count(mesh.vertex_count()));
  if (sw.no_node) return;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
    if (!number.written(v)) continue;
    out.points.push_back(mesh.points[v].x);
    out.points.push_back(mesh.points[v].y);
    for (std::size_t a = 0; a < na; ++a) out.point_attributes.push_back(mesh.attributes[v * na + a]);
    if (!sw.no_markers) out.point_markers.push_back(mesh.marker.empty() ? 0 : mesh.marker[v]);
  }
}

// As write_ele_file and write_neigh_file.
void fill_triangles(api::Mesh& out, const PipelineResult& result, const VertexNumbering& number, const Options& sw) {
  const Mesh& mesh = result.mesh;
  const std::vector<VertexId>* mid = sw.order == 2 ? &result.midpoints : nullptr;
  const std::size_t na = static_cast<std::size_t>(mesh.num_triangle_attributes);
  out.triangle_count = as_int(mesh.live_triangles());
  out.corner_count = mid ? 6 : 3;
  out.triangle_attribute_count = mesh.num_triangle_attributes;
  const std::vector<std::uint32_t> numbers = number_live_triangles(mesh);
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    if (!sw.no_ele) {
      for (EdgeRef e : edges_of(t)) out.triangles.push_back(as_int(number(mesh.corner[e])));
      if (mid)
        for (EdgeRef e : edges_of(t)) out.triangles.push_back(as_int(number((*mid)[e])));
      for (std::size_t a = 0; a < na; ++a) out.triangle_attributes.push_back(mesh.triangle_attributes[t * na + a]);
    }
    if (sw.neighbors)
      for (unsigned k = 0; k < 3; ++k) {
        const EdgeRef across = mesh.link[edge_of(t, (k + 1) % 3)];
        out.neighbors.push_back(across == kNone ? -1 : as_int(triangle_number(numbers, triangle_of(across)) + number.first_index));
      }
  }
}

// As write_poly_file's segments; without segments, the count of boundary edges (as Triangle).
void fill_segments(api::Mesh& out, const Mesh& mesh, const VertexNumbering& number, const Options& sw, bool poly_input) {
  if (!(poly_input || sw.convex_hull)) {
    for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
      if (mesh.is_live(t))
        for (EdgeRef e : edges_of(t)) out.segment_count += mesh.link[e] == kNone;
    return;
  }
  const LiveSubsegments live = find_live_subsegments(mesh);
  out.segment_count = as_int(live.count);
  if (sw.no_poly) return;
  for (SubsegmentId s{0}; s < live.edge.size(); ++s) {
    const EdgeRef e = live.edge[s];
    if (e == kNone) continue;
    out.segments.push_back(as_int(number(mesh.org(e))));
    out.segments.push_back(as_int(number(mesh.dest(e))));
    const int marker = mesh.subsegments[s].marker;
    if (!sw.no_markers) out.segment_markers.push_back(marker != 0 ? marker : live.boundary[s] ? 1 : 0);
  }
}

// As write_edge_file and write_voronoi_edge_file (the same edges in the same order).
void fill_edges(api::Mesh& out, const Mesh& mesh, const VertexNumbering& number, const Options& sw) {
  out.edge_count = as_int(count_edges(mesh));
  if (!sw.edges && !sw.voronoi) return;
  const std::vector<std::uint32_t> numbers = number_live_triangles(mesh);
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const int here = as_int(triangle_number(numbers, t) + number.first_index);
    for (EdgeRef e : edges_of(t)) {
      if (!edge_written_here(mesh, e)) continue;
      if (sw.edges) {
        out.edges.push_back(as_int(number(mesh.org(e))));
        out.edges.push_back(as_int(number(mesh.dest(e))));
        if (!sw.no_markers) out.edge_markers.push_back(edge_marker(mesh, e));
      }
      if (!sw.voronoi) continue;
      out.voronoi_edges.push_back(here);
      if (mesh.link[e] != kNone) {
        out.voronoi_edges.push_back(as_int(triangle_number(numbers, triangle_of(mesh.link[e])) + number.first_index));
        out.voronoi_normals.insert(out.voronoi_normals.end(), {0.0, 0.0});
      } else {
        // The triangle lies to the left of org -> dest, so the right-hand normal points out.
        const Point &p = mesh.points[mesh.org(e)], &q = mesh.points[mesh.dest(e)];
        out.voronoi_edges.push_back(-1);
        out.voronoi_normals.insert(out.voronoi_normals.end(), {q.y - p.y, p.x - q.x});
      }
    }
  }
}

// As write_voronoi_node_file.
void fill_voronoi_points(api::Mesh& out, const Mesh& mesh) {
  std::vector<double> attributes;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const Point cc = voronoi_vertex(mesh, t, attributes);
    out.voronoi_points.push_back(cc.x);
    out.voronoi_points.push_back(cc.y);
    out.voronoi_point_attributes.insert(out.voronoi_point_attributes.end(), attributes.begin(), attributes.end());
  }
}

}  // namespace

api::Mesh output_arrays(const PipelineResult& result, const Options& sw, int first_index, bool poly_input) {
  const Mesh& mesh = result.mesh;
  const VertexNumbering number{result.numbering.empty() ? nullptr : &result.numbering, first_index};
  api::Mesh out;
  fill_points(out, mesh, number, sw);
  fill_triangles(out, result, number, sw);
  fill_segments(out, mesh, number, sw, poly_input);
  fill_edges(out, mesh, number, sw);
  if (sw.voronoi) fill_voronoi_points(out, mesh);
  return out;
}

}  // namespace deltri
