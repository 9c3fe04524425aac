#include "io/msh_file.h"

#include <algorithm>
#include <limits>

#include "io/physical_groups.h"

namespace deltri {
namespace {

struct Box {
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x;
  double hi_x = -lo_x, hi_y = -lo_x;
  void add(const Point& p) {
    lo_x = std::min(lo_x, p.x), lo_y = std::min(lo_y, p.y);
    hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
  }
  void write(TextWriter& out) const {
    const bool empty = lo_x > hi_x;
    out.next_real(empty ? 0.0 : lo_x);
    out.next_real(empty ? 0.0 : lo_y);
    out.next_integer(0);
    out.next_real(empty ? 0.0 : hi_x);
    out.next_real(empty ? 0.0 : hi_y);
    out.next_integer(0);
  }
};

// Elements of one dimension, grouped.
struct ElementSet {
  std::vector<EdgeRef> items;  // edges, or triangles' first edge 3t
  PhysicalGroups groups;
  std::vector<Box> boxes;      // per group
};

void write_entity_lines(TextWriter& out, const ElementSet& set) {
  for (std::size_t g = 0; g < set.groups.values.size(); ++g) {
    out.integer(static_cast<long long>(g) + 1);
    set.boxes[g].write(out);
    out.next_integer(1);
    out.next_integer(set.groups.tags[g]);
    out.next_integer(0);
    out.end_line();
  }
}

void write_data_view(TextWriter& out, const std::string& name, const Mesh& mesh, const VertexNumbering& number,
                     std::uint32_t count, double (*value)(const Mesh&, VertexId, int), int k) {
  out.text("$NodeData\n1\n\"" + name + "\"\n1\n0\n3\n0\n1\n");
  out.integer(count);
  out.end_line();
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    if (!number.written(v)) continue;
    out.integer(number(v));
    out.next_real(value(mesh, v, k));
    out.end_line();
  }
  out.text("$EndNodeData\n");
}

}  // namespace

void write_msh_file(ByteSink& sink, const Mesh& mesh, const ExportOptions& options) {
  const VertexNumbering number{options.numbering, 1};
  const std::vector<VertexId>* mid = options.midpoints;
  const std::uint32_t node_count = number.written_count(mesh.vertex_count());

  ElementSet lines, triangles;
  std::vector<double> values;
  if (options.markers) {
    lines.items = boundary_and_segment_edges(mesh);
    for (EdgeRef e : lines.items) values.push_back(edge_marker(mesh, e));
  }
  lines.groups = group_by_value(values);
  values.clear();
  const int na = mesh.num_triangle_attributes;
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    triangles.items.push_back(3 * t);
    values.push_back(na > 0 ? mesh.triangle_attributes[static_cast<std::size_t>(t) * na] : 1.0);
  }
  if (values.empty()) values.push_back(1.0);  // the surface the nodes belong to exists even when empty
  triangles.groups = group_by_value(values);
  if (triangles.items.empty()) triangles.groups.group.clear();
  for (ElementSet* set : {&lines, &triangles}) {
    set->boxes.assign(set->groups.values.size(), Box{});
    const int corners = set == &lines ? 2 : 3;
    for (std::size_t k = 0; k < set->items.size(); ++k)
      for (int c = 0; c < corners; ++c) {
        const EdgeRef e = set->items[k];
        set->boxes[set->groups.group[k]].add(mesh.points[c == 0 ? mesh.org(e) : c == 1 ? mesh.dest(e) : mesh.apex(e)]);
      }
  }
  if (triangles.items.empty())
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
      if (number.written(v)) triangles.boxes[0].add(mesh.points[v]);

  sink.expect(static_cast<std::size_t>(node_count) * 56 + triangles.items.size() * (mid ? 64 : 36));
  TextWriter out(sink);
  out.text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n");
  out.integer(static_cast<long long>(lines.groups.values.size() + triangles.groups.values.size()));
  out.end_line();
  for (std::size_t g = 0; g < lines.groups.values.size(); ++g) {
    out.text("1 ");
    out.integer(lines.groups.tags[g]);
    out.text(" \"marker " + value_text(lines.groups.values[g]) + "\"\n");
  }
  for (std::size_t g = 0; g < triangles.groups.values.size(); ++g) {
    out.text("2 ");
    out.integer(triangles.groups.tags[g]);
    out.text(na > 0 ? " \"attribute " + value_text(triangles.groups.values[g]) + "\"\n" : std::string(" \"domain\"\n"));
  }
  out.text("$EndPhysicalNames\n$Entities\n0 ");
  out.integer(static_cast<long long>(lines.groups.values.size()));
  out.next_integer(static_cast<long long>(triangles.groups.values.size()));
  out.text(" 0\n");
  write_entity_lines(out, lines);
  write_entity_lines(out, triangles);
  out.text("$EndEntities\n$Nodes\n");
  long long min_tag = 0, max_tag = 0;
  for (VertexId v = 0; v < mesh.vertex_count(); ++v)
    if (number.written(v)) {
      if (min_tag == 0) min_tag = number(v);
      max_tag = number(v);
    }
  out.integer(node_count > 0 ? 1 : 0);
  out.next_integer(node_count);
  out.next_integer(min_tag);
  out.next_integer(max_tag);
  out.end_line();
  if (node_count > 0) {
    out.text("2 1 0 ");
    out.integer(node_count);
    out.end_line();
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
      if (number.written(v)) {
        out.integer(number(v));
        out.end_line();
      }
    write_points_xyz(out, mesh, number);
  }
  out.text("$EndNodes\n$Elements\n");
  const std::size_t element_count = lines.items.size() + triangles.items.size();
  std::size_t blocks = 0;
  for (ElementSet* set : {&lines, &triangles}) {
    std::vector<char> used(set->groups.values.size(), 0);
    for (std::uint32_t g : set->groups.group) used[g] = 1;
    blocks += static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  }
  out.integer(static_cast<long long>(blocks));
  out.next_integer(static_cast<long long>(element_count));
  out.next_integer(element_count > 0 ? 1 : 0);
  out.next_integer(static_cast<long long>(element_count));
  out.end_line();
  long long tag = 1;
  for (ElementSet* set : {&lines, &triangles}) {
    const bool is_line = set == &lines;
    // Element order within a group stays the .edge / .ele order.
    std::vector<std::uint32_t> order(set->items.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return set->groups.group[a] < set->groups.group[b]; });
    for (std::size_t start = 0; start < order.size();) {
      const std::uint32_t g = set->groups.group[order[start]];
      std::size_t end = start;
      while (end < order.size() && set->groups.group[order[end]] == g) ++end;
      out.integer(is_line ? 1 : 2);
      out.next_integer(static_cast<long long>(g) + 1);
      out.next_integer(is_line ? (mid ? 8 : 1) : (mid ? 9 : 2));
      out.next_integer(static_cast<long long>(end - start));
      out.end_line();
      for (; start < end; ++start) {
        const EdgeRef e = set->items[order[start]];
        TextWriter::Line line = out.line(7);
        line.integer(tag++);
        if (is_line) {
          line.next_integer(number(mesh.org(e)));
          line.next_integer(number(mesh.dest(e)));
          if (mid) line.next_integer(number((*mid)[lprev(e)]));
        } else {
          for (EdgeRef c = 0; c < 3; ++c) line.next_integer(number(mesh.corner[e + c]));
          // Gmsh orders the midpoints by edge: (0,1), (1,2), (2,0), i.e. opposite corners 2, 0, 1.
          if (mid)
            for (EdgeRef c : {2u, 0u, 1u}) line.next_integer(number((*mid)[e + c]));
        }
        line.end_line();
      }
    }
  }
  out.text("$EndElements\n");
  if (options.markers && !mesh.marker.empty())
    write_data_view(out, "marker", mesh, number, node_count,
                    [](const Mesh& m, VertexId v, int) { return static_cast<double>(m.marker[v]); }, 0);
  for (int k = 0; k < mesh.num_attributes; ++k)
    write_data_view(out, "attribute " + std::to_string(k + 1), mesh, number, node_count,
                    [](const Mesh& m, VertexId v, int a) {
                      return m.attributes[static_cast<std::size_t>(v) * m.num_attributes + a];
                    },
                    k);
  out.finish();
}

}  // namespace deltri
