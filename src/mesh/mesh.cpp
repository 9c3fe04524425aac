#include "mesh/mesh.h"

#include <algorithm>

namespace deltri {

TriangleId Mesh::add_triangle(VertexId a, VertexId b, VertexId c) {
  auto& corner = this->corner.slots_;
  auto& link = this->link.slots_;
  if (free_triangles.empty()) return append_triangle(a, b, c);
  const TriangleId t = free_triangles.back();
  free_triangles.pop_back();
  const EdgeRef e = edge_of(t, 0);
  corner[e] = a;
  corner[e + 1] = b;
  corner[e + 2] = c;
  link[e] = link[e + 1] = link[e + 2] = kNone;
  if (!subseg.empty()) subseg.set_triangle(e, kNone);
  return t;
}

// push_back rather than resize: resize's out-of-line value-initialisation showed in profiles of
// refinement, which appends a triangle for every two it creates.
TriangleId Mesh::append_triangle(VertexId a, VertexId b, VertexId c) {
  auto& corner = this->corner.slots_;
  auto& link = this->link.slots_;
  const TriangleId t{triangle_slots()};
  for (VertexId v : {a, b, c}) corner.push_back(v);
  for (int i = 0; i < 3; ++i) link.push_back(kNone);
  if (!subseg.empty()) subseg.grow_triangle();
  if (num_triangle_attributes > 0)
    triangle_attributes.resize(triangle_attributes.size() + num_triangle_attributes);
  if (!area_bound.empty()) area_bound.push_back(0.0);
  return t;
}

void Mesh::kill_triangle(TriangleId t) {
  auto& corner = this->corner.slots_;
  auto& link = this->link.slots_;
  for (unsigned i = 0; i < 3; ++i) {
    const EdgeRef e = edge_of(t, i);
    if (link[e] != kNone) link[link[e]] = kNone;
    link[e] = kNone;
    corner[e] = kNone;
  }
  free_triangles.push_back(t);
}

VertexId Mesh::add_vertex(const Point& p, VertexKind k) {
  const VertexId v{vertex_count()};
  points.push_back(p);
  kind.push_back(k);
  if (!marker.empty()) marker.push_back(0);
  if (num_attributes > 0) attributes.resize(attributes.size() + num_attributes, 0.0);
  return v;
}

void Mesh::interpolate_attributes(VertexId v, VertexId a, VertexId b) {
  const std::size_t na = static_cast<std::size_t>(num_attributes);
  if (na == 0) return;
  const Point& pa = points[a];
  const Point& pb = points[b];
  const Point& p = points[v];
  const double dx = pb.x - pa.x, dy = pb.y - pa.y;
  const double w = ((p.x - pa.x) * dx + (p.y - pa.y) * dy) / (dx * dx + dy * dy);
  for (std::size_t k = 0; k < na; ++k) {
    const double va = attributes[a * na + k];
    const double vb = attributes[b * na + k];
    attributes[v * na + k] = va + w * (vb - va);
  }
}

void Mesh::enable_subsegments() {
  auto& corner = this->corner.slots_;
  if (subseg.size() != corner.size()) subseg.assign(corner.size());
}

void Mesh::compact_triangles() {
  auto& corner = this->corner.slots_;
  auto& link = this->link.slots_;
  if (free_triangles.empty()) return;
  TriangleId last{triangle_slots()};
  const int na = num_triangle_attributes;
  // Fill each dead slot below the end with the last live triangle.
  TriangleId write{0};
  while (true) {
    while (write < last && is_live(write)) ++write;
    while (last > write && !is_live(TriangleId{last - 1})) --last;
    if (write >= last) break;
    const TriangleId from{last - 1};
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef src = edge_of(from, i), dst = edge_of(write, i);
      corner[dst] = corner[src];
      link[dst] = link[src];
      if (link[dst] != kNone) link[link[dst]] = dst;
      if (!subseg.empty()) subseg.set(dst, subseg[src]);
      corner[src] = kNone;
    }
    for (int k = 0; k < na; ++k) triangle_attributes[write * na + k] = triangle_attributes[from * na + k];
    if (!area_bound.empty()) area_bound[write] = area_bound[from];
    --last;
  }
  corner.resize(3 * static_cast<std::size_t>(last));
  link.resize(corner.size());
  if (!subseg.empty()) subseg.resize(corner.size());
  if (na > 0) triangle_attributes.resize(static_cast<std::size_t>(last) * na);
  if (!area_bound.empty()) area_bound.resize(last);
  free_triangles.clear();
}

// The part's vertex arrays have room for the vertices this mesh still has room for (refinement
// reserved its expected count, and a part adds no more than the whole), its records a quarter more,
// so that the part's first appends do not reallocate: a copy of exactly its size doubled at the
// first new vertex or subsegment, and the abandoned copy stayed resident in the refining thread's
// malloc arena (four parts of the 50x50 holes: 12 MB of the peak).
Mesh Mesh::part_with(const std::vector<VertexId>& vertices, const std::vector<SubsegmentId>& records) const {
  const std::size_t room = vertices.size() + (points.capacity() - points.size());
  const std::size_t na = static_cast<std::size_t>(num_attributes);
  Mesh m;
  m.points.reserve(room);
  m.kind.reserve(room);
  if (!marker.empty()) m.marker.reserve(room);
  m.num_attributes = num_attributes;
  m.attributes.reserve(vertices.size() * na);
  for (VertexId v : vertices) {
    m.points.push_back(points[v]);
    m.kind.push_back(kind[v]);
    if (!marker.empty()) m.marker.push_back(marker[v]);
    m.attributes.insert(m.attributes.end(), attributes.begin() + static_cast<std::ptrdiff_t>(v * na),
                        attributes.begin() + static_cast<std::ptrdiff_t>((v + 1) * na));
  }
  m.num_triangle_attributes = num_triangle_attributes;
  std::vector<VertexId> local(points.size(), kNone);
  for (VertexId i{0}; i < vertices.size(); ++i) local[vertices[i]] = i;
  m.subsegments.reserve(records.size() + records.size() / 4);
  for (SubsegmentId s : records) {
    Subsegment r = subsegments[s];
    r.a = r.a == kNone ? kNone : local[r.a];
    r.b = r.b == kNone ? kNone : local[r.b];
    m.subsegments.push_back(r);
  }
  return m;
}

void Mesh::take_vertices(Mesh& from, VertexId first) {
  const std::size_t na = static_cast<std::size_t>(from.num_attributes);
  // Whole ranges: appending one at a time rewrote the sizes, which share cache lines with the
  // arrays that another thread appends to at the same time (mesh/parts.cpp).
  const auto from_first = static_cast<std::ptrdiff_t>(first), from_end = static_cast<std::ptrdiff_t>(from.vertex_count());
  kind.insert(kind.end(), from.kind.begin() + from_first, from.kind.begin() + from_end);
  if (!from.marker.empty()) marker.insert(marker.end(), from.marker.begin() + from_first, from.marker.begin() + from_end);
  move_appending(from.points, points, [](const Point& p) { return p; }, first);
  attributes.insert(attributes.end(), from.attributes.begin() + static_cast<std::ptrdiff_t>(first * na),
                    from.attributes.end());
}

}  // namespace deltri
