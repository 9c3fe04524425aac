#include "io/msh_file.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string_view>

#include "io/binary_writer.h"
#include "io/physical_groups.h"

namespace deltri {
namespace {

// One file in either encoding. ASCII fields are separated by spaces and lines end in newlines;
// binary fields are the raw values and line ends vanish. Section keywords and counts that the
// format keeps in ASCII go through text() in both.
class MshOut {
 public:
  MshOut(ByteSink& sink, bool binary) : binary(binary), ascii(sink), raw(sink) {}
  void text(std::string_view s) { binary ? raw.text(s) : ascii.text(s); }
  void count_line(long long n) { text(std::to_string(n) + "\n"); }
  void i32(long long v) { binary ? raw.put(static_cast<std::int32_t>(v)) : field(v); }
  void u64(long long v) { binary ? raw.put(static_cast<std::uint64_t>(v)) : field(v); }
  void f64(double v) {
    if (binary) return raw.put(v);
    first_ ? ascii.real(v) : ascii.next_real(v);
    first_ = false;
  }
  void end_line() {
    if (!binary) ascii.end_line();
    first_ = true;
  }
  // Closes a section: binary data is followed by a newline before the $End line.
  void end_section(std::string_view end) {
    if (binary) raw.text("\n");
    text(end);
  }
  void finish() { binary ? raw.finish() : ascii.finish(); }

  const bool binary;
  TextWriter ascii;
  BinaryWriter raw;

 private:
  void field(long long v) {
    first_ ? ascii.integer(v) : ascii.next_integer(v);
    first_ = false;
  }
  bool first_ = true;
};

struct Box {
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x;
  double hi_x = -lo_x, hi_y = -lo_x;
  void add(const Point& p) {
    lo_x = std::min(lo_x, p.x), lo_y = std::min(lo_y, p.y);
    hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
  }
  void write(MshOut& out) const {
    const bool empty = lo_x > hi_x;
    for (double v : {lo_x, lo_y, 0.0, hi_x, hi_y, 0.0}) out.f64(empty ? 0.0 : v);
  }
};

// Elements of one dimension, grouped.
struct ElementSet {
  int dim = 1;
  std::vector<EdgeRef> items;  // edges, or triangles' first edge 3t
  const PhysicalGroups* groups = nullptr;
  std::vector<Box> boxes;      // per group
  std::vector<std::uint32_t> order;  // items by group; within a group in .edge / .ele order
};

// Everything both versions write, worked out once.
struct MshContent {
  const Mesh& mesh;
  VertexNumbering number;
  const std::vector<VertexId>* mid;
  std::uint32_t node_count;
  MeshPhysicalGroups groups;
  ElementSet lines, triangles;
  bool attributes;  // surfaces are triangle attributes rather than the one "domain"

  int type(const ElementSet& set) const { return set.dim == 1 ? (mid ? 8 : 1) : (mid ? 9 : 2); }
  // The element's nodes in Gmsh order.
  template <class F>
  void element_nodes(const ElementSet& set, EdgeRef e, F&& f) const {
    if (set.dim == 1) {
      f(number(mesh.org(e)));
      f(number(mesh.dest(e)));
      if (mid) f(number((*mid)[lprev(e)]));
      return;
    }
    const TriangleId t = triangle_of(e);  // e is its first edge
    for (unsigned c = 0; c < 3; ++c) f(number(mesh.corner[edge_of(t, c)]));
    // Gmsh orders the midpoints by edge: (0,1), (1,2), (2,0), i.e. opposite corners 2, 0, 1.
    if (mid)
      for (unsigned c : {2u, 0u, 1u}) f(number((*mid)[edge_of(t, c)]));
  }
  // Calls f(set, group, first, end) for each non-empty block of set.order.
  template <class F>
  static void blocks(const ElementSet& set, F&& f) {
    for (std::size_t start = 0; start < set.order.size();) {
      const std::uint32_t g = set.groups->group[set.order[start]];
      std::size_t end = start;
      while (end < set.order.size() && set.groups->group[set.order[end]] == g) ++end;
      f(g, start, end);
      start = end;
    }
  }
  std::size_t block_count() const {
    std::size_t n = 0;
    for (const ElementSet* set : {&lines, &triangles}) blocks(*set, [&](std::uint32_t, std::size_t, std::size_t) { ++n; });
    return n;
  }
};

void sort_by_group(ElementSet& set) {
  set.order.resize(set.items.size());
  for (std::uint32_t k = 0; k < set.order.size(); ++k) set.order[k] = k;
  std::stable_sort(set.order.begin(), set.order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return set.groups->group[a] < set.groups->group[b]; });
}

void write_header(MshOut& out, int version) {
  out.text(version == 22 ? "$MeshFormat\n2.2 " : "$MeshFormat\n4.1 ");
  out.text(out.binary ? "1 8\n" : "0 8\n");
  if (out.binary) {
    out.i32(1);  // tells the reader the byte order
    out.text("\n");
  }
  out.text("$EndMeshFormat\n");
}

void write_physical_names(MshOut& out, const MshContent& c) {
  out.text("$PhysicalNames\n");
  out.count_line(static_cast<long long>(c.groups.lines.values.size() + c.groups.surfaces.values.size()));
  for (std::size_t g = 0; g < c.groups.lines.values.size(); ++g)
    out.text("1 " + std::to_string(c.groups.lines.tags[g]) + " \"marker " + value_text(c.groups.lines.values[g]) + "\"\n");
  for (std::size_t g = 0; g < c.groups.surfaces.values.size(); ++g)
    out.text("2 " + std::to_string(c.groups.surfaces.tags[g]) +
             (c.attributes ? " \"attribute " + value_text(c.groups.surfaces.values[g]) + "\"\n" : std::string(" \"domain\"\n")));
  out.text("$EndPhysicalNames\n");
}

// 4.1: one curve entity per line group, one surface entity per surface group, entity g + 1.
void write_entities(MshOut& out, const MshContent& c) {
  out.text("$Entities\n");
  const long long curves = static_cast<long long>(c.lines.boxes.size());
  const long long surfaces = static_cast<long long>(c.triangles.boxes.size());
  for (long long n : {0LL, curves, surfaces, 0LL}) out.u64(n);
  out.end_line();
  for (const ElementSet* set : {&c.lines, &c.triangles})
    for (std::size_t g = 0; g < set->boxes.size(); ++g) {
      out.i32(static_cast<long long>(g) + 1);
      set->boxes[g].write(out);
      out.u64(1);
      out.i32(set->groups->tags[g]);
      out.u64(0);
      out.end_line();
    }
  out.end_section("$EndEntities\n");
}

void write_nodes(MshOut& out, const MshContent& c, int version) {
  const Mesh& mesh = c.mesh;
  out.text("$Nodes\n");
  if (version == 22) {
    out.count_line(c.node_count);
  } else {
    long long min_tag = 0, max_tag = 0;
    for (VertexId v{0}; v < mesh.vertex_count(); ++v)
      if (c.number.written(v)) {
        if (min_tag == 0) min_tag = c.number(v);
        max_tag = c.number(v);
      }
    for (long long n : {c.node_count > 0 ? 1LL : 0LL, static_cast<long long>(c.node_count), min_tag, max_tag}) out.u64(n);
    out.end_line();
    if (c.node_count > 0) {
      out.i32(2), out.i32(1), out.i32(0), out.u64(c.node_count);
      out.end_line();
      for (VertexId v{0}; v < mesh.vertex_count(); ++v)
        if (c.number.written(v)) {
          out.u64(c.number(v));
          out.end_line();
        }
    }
  }
  if (!out.binary && version == 41) {
    write_points_xyz(out.ascii, mesh, c.number);
  } else {
    for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
      if (!c.number.written(v)) continue;
      if (out.binary) {
        if (version == 22) out.raw.put(static_cast<std::int32_t>(c.number(v)));
        out.raw.put(mesh.points[v].x), out.raw.put(mesh.points[v].y), out.raw.put(0.0);
      } else {
        TextWriter::Line line = out.ascii.line(4);
        line.integer(c.number(v));
        line.next_real(mesh.points[v].x);
        line.next_real(mesh.points[v].y);
        line.next_integer(0);
        line.end_line();
      }
    }
  }
  out.end_section("$EndNodes\n");
}

void write_elements(MshOut& out, const MshContent& c, int version) {
  out.text("$Elements\n");
  const std::size_t element_count = c.lines.items.size() + c.triangles.items.size();
  if (version == 22) {
    out.count_line(static_cast<long long>(element_count));
  } else {
    out.u64(static_cast<long long>(c.block_count()));
    out.u64(static_cast<long long>(element_count));
    out.u64(element_count > 0 ? 1 : 0);
    out.u64(static_cast<long long>(element_count));
    out.end_line();
  }
  long long tag = 1;
  for (const ElementSet* set : {&c.lines, &c.triangles}) {
    const int type = c.type(*set);
    MshContent::blocks(*set, [&](std::uint32_t g, std::size_t start, std::size_t end) {
      const long long entity = static_cast<long long>(g) + 1, physical = set->groups->tags[g];
      if (version == 41) {
        out.i32(set->dim), out.i32(entity), out.i32(type), out.u64(static_cast<long long>(end - start));
        out.end_line();
      } else if (out.binary) {
        out.raw.put(static_cast<std::int32_t>(type));
        out.raw.put(static_cast<std::int32_t>(end - start));
        out.raw.put(static_cast<std::int32_t>(2));  // tags: physical, elementary
      }
      for (std::size_t k = start; k < end; ++k) {
        const EdgeRef e = set->items[set->order[k]];
        if (out.binary && version == 41) {
          out.raw.put(static_cast<std::uint64_t>(tag++));
          c.element_nodes(*set, e, [&](long long n) { out.raw.put(static_cast<std::uint64_t>(n)); });
        } else if (out.binary) {
          out.raw.put(static_cast<std::int32_t>(tag++));
          out.raw.put(static_cast<std::int32_t>(physical));
          out.raw.put(static_cast<std::int32_t>(entity));
          c.element_nodes(*set, e, [&](long long n) { out.raw.put(static_cast<std::int32_t>(n)); });
        } else {
          TextWriter::Line line = out.ascii.line(11);
          line.integer(tag++);
          if (version == 22) {
            line.next_integer(type);
            line.next_integer(2);
            line.next_integer(physical);
            line.next_integer(entity);
          }
          c.element_nodes(*set, e, [&](long long n) { line.next_integer(n); });
          line.end_line();
        }
      }
    });
  }
  out.end_section("$EndElements\n");
}

void write_data_view(MshOut& out, const std::string& name, const MshContent& c,
                     double (*value)(const Mesh&, VertexId, int), int k) {
  out.text("$NodeData\n1\n\"" + name + "\"\n1\n0\n3\n0\n1\n");
  out.count_line(c.node_count);
  for (VertexId v{0}; v < c.mesh.vertex_count(); ++v) {
    if (!c.number.written(v)) continue;
    out.i32(c.number(v));
    out.f64(value(c.mesh, v, k));
    out.end_line();
  }
  out.end_section("$EndNodeData\n");
}

// The edges and triangles the file holds, and their groups.
void collect_groups(MshContent& c, const ExportOptions& options, long long domain_tag) {
  const Mesh& mesh = c.mesh;
  const int na = mesh.num_triangle_attributes;
  std::vector<double> line_values, surface_values;
  if (options.markers) {
    c.lines.items = boundary_and_segment_edges(mesh);
    for (EdgeRef e : c.lines.items) line_values.push_back(edge_marker(mesh, e));
  }
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    c.triangles.items.push_back(edge_of(t, 0));
    surface_values.push_back(na > 0 ? mesh.triangle_attributes[static_cast<std::size_t>(t) * na] : 0.0);
  }
  if (surface_values.empty()) surface_values.push_back(0.0);  // the surface the nodes belong to exists even when empty
  c.groups = physical_groups(line_values, surface_values, na > 0, domain_tag);
}

}  // namespace

std::string msh_tag_clash(const Mesh& mesh, const ExportOptions& options, MshFormat format) {
  MshContent c{mesh, VertexNumbering{options.numbering, 1}, options.midpoints, 0, {}, {}, {}, mesh.num_triangle_attributes > 0};
  collect_groups(c, options, format.domain_tag);
  return c.groups.clash;
}

void write_msh_file(ByteSink& sink, const Mesh& mesh, const ExportOptions& options, MshFormat format) {
  const int na = mesh.num_triangle_attributes;
  MshContent c{mesh, VertexNumbering{options.numbering, 1}, options.midpoints, 0, {}, {}, {}, na > 0};
  c.node_count = c.number.written_count(mesh.vertex_count());
  collect_groups(c, options, format.domain_tag);
  if (c.triangles.items.empty()) c.groups.surfaces.group.clear();
  c.lines.groups = &c.groups.lines;
  c.triangles.groups = &c.groups.surfaces;
  c.triangles.dim = 2;
  for (ElementSet* set : {&c.lines, &c.triangles}) {
    sort_by_group(*set);
    set->boxes.assign(set->groups->values.size(), Box{});
    const int corners = set->dim + 1;
    for (std::size_t k = 0; k < set->items.size(); ++k)
      for (int i = 0; i < corners; ++i) {
        const EdgeRef e = set->items[k];
        set->boxes[set->groups->group[k]].add(mesh.points[i == 0 ? mesh.org(e) : i == 1 ? mesh.dest(e) : mesh.apex(e)]);
      }
  }
  if (c.triangles.items.empty())
    for (VertexId v{0}; v < mesh.vertex_count(); ++v)
      if (c.number.written(v)) c.triangles.boxes[0].add(mesh.points[v]);

  sink.expect(static_cast<std::size_t>(c.node_count) * 56 + c.triangles.items.size() * (c.mid ? 64 : 36));
  MshOut out(sink, format.binary);
  write_header(out, format.version);
  write_physical_names(out, c);
  if (format.version == 41) write_entities(out, c);
  write_nodes(out, c, format.version);
  write_elements(out, c, format.version);
  if (options.markers && !mesh.marker.empty())
    write_data_view(out, "marker", c, [](const Mesh& m, VertexId v, int) { return static_cast<double>(m.marker[v]); }, 0);
  for (int k = 0; k < mesh.num_attributes; ++k)
    write_data_view(out, "attribute " + std::to_string(k + 1), c,
                    [](const Mesh& m, VertexId v, int a) { return m.attributes[static_cast<std::size_t>(v) * m.num_attributes + a]; },
                    k);
  out.finish();
}

}  // namespace deltri
