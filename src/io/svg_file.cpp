#include "io/svg_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <string_view>

#include "geometry/box.h"

namespace deltri {
namespace {

constexpr double kCanvas = 10000.0;
constexpr long long kMargin = 200;  // around the mesh, in canvas units
constexpr int kShades = 6;
// Worst (below 10 degrees) to best (50 to 60): red through yellow to blue.
constexpr std::array<const char*, kShades> kFill = {"#d7301f", "#fc8d59", "#fdcc8a", "#d9f0a3", "#91cf60", "#4393c3"};
// Boundary and segment edges by marker: dark, saturated colours that stand apart from the shades
// (and from each other); marker 0 (an interior segment without one) is black. More markers than
// colours reuse them in turn, each still named in the legend.
constexpr std::array<const char*, 10> kMarkerColour = {"#1b3a8c", "#c51b7d", "#00a0a0", "#6a3d9a", "#e6a800",
                                                       "#8c2d04", "#2e7d32", "#ff00ff", "#5a5a5a", "#00bfff"};
constexpr std::size_t kMarkersListed = 30;  // beyond: one legend entry, "other markers"

// The legend's type: its font size and line height in canvas units, and the width given to a
// digit or an ordinary letter (DejaVu Sans, the usual fallback for sans-serif: digits 0.64 em).
constexpr long long kFont = 150;
constexpr long long kRow = 300;
constexpr long long kSwatch = 250;
constexpr double kCharWidth = 0.65;

double angle_at(const Point& p, const Point& q, const Point& r) {
  const double ux = q.x - p.x, uy = q.y - p.y, vx = r.x - p.x, vy = r.y - p.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

// The frame is the triangles' bounding box: vertices no triangle uses (input vertices outside
// the domain, in holes, duplicates) are left out of the picture, and the legend says how many.
class Canvas {
 public:
  Canvas(const Mesh& mesh, const VertexNumbering& number) {
    for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
      if (mesh.is_live(t))
        for (EdgeRef e : edges_of(t)) box_.add(mesh.points[mesh.org(e)]);
    if (box_.empty())  // no triangles: the vertices are all there is
      for (VertexId v{0}; v < mesh.vertex_count(); ++v)
        if (number.written(v) && mesh.kind[v] != VertexKind::Dead) box_.add(mesh.points[v]);
    if (box_.empty()) box_ = Box{0, 0, 1, 1};
    const double span = std::max({box_.width(), box_.height(), std::numeric_limits<double>::min()});
    scale_ = kCanvas / span;
    width_ = std::max(1LL, static_cast<long long>(std::ceil(box_.width() * scale_)));
    height_ = std::max(1LL, static_cast<long long>(std::ceil(box_.height() * scale_)));
  }
  long long x(const Point& p) const { return std::llround((p.x - box_.lo_x) * scale_); }
  long long y(const Point& p) const { return std::llround((box_.hi_y - p.y) * scale_); }
  bool inside(const Point& p) const {
    return p.x >= box_.lo_x && p.x <= box_.hi_x && p.y >= box_.lo_y && p.y <= box_.hi_y;
  }
  long long width() const { return width_; }
  long long height() const { return height_; }

 private:
  Box box_;
  double scale_ = 1;
  long long width_ = 1, height_ = 1;
};

// One line of the legend: a swatch (none for a heading) and its text.
struct LegendEntry {
  const char* colour = nullptr;  // null: a heading, text only
  bool line = false;             // a marker's swatch is a bar, a shade's a square
  std::string text;
  long long x = 0, y = 0;        // the swatch's top left corner (the heading's text box's)
};

// An upper bound on a legend text's width: each character at its class's widest advance in DejaVu
// Sans (digits 0.64 em, most letters under that, m and w wider, narrow letters and punctuation far narrower).
long long text_width(const std::string& text) {
  double em = 0;
  for (unsigned char c : text) {
    if ((c & 0xc0) == 0x80) continue;  // a UTF-8 continuation byte: the character is counted once
    em += c == 'm' ? 0.98 : c == 'w' ? 0.82 : std::string_view(" :;,.-()").find(static_cast<char>(c)) != std::string_view::npos ? 0.4
        : std::string_view("fijlrt").find(static_cast<char>(c)) != std::string_view::npos ? 0.42 : kCharWidth;
  }
  return static_cast<long long>(std::ceil(em * kFont));
}

long long entry_width(const LegendEntry& e) { return (e.colour ? kSwatch + 60 : 0) + text_width(e.text); }

// Lays the entries out in columns of equal width, below a wide mesh or to the right of a tall
// one, so that no text runs into the next entry at any aspect ratio; returns the legend's far corner.
std::array<long long, 2> lay_out(std::vector<LegendEntry>& entries, long long width, long long height) {
  long long column = 0;
  for (const LegendEntry& e : entries) column = std::max(column, entry_width(e) + 200);
  const bool below = width >= height;
  const long long x0 = below ? 0 : width + 2 * kMargin, y0 = below ? height + 2 * kMargin : 0;
  const long long room = below ? std::max(width, column) : std::max(height, kRow);
  const long long n = static_cast<long long>(entries.size());
  // Filled a column at a time, so that the entries read in order down each column.
  const long long columns = below ? std::max(1LL, (room + 200) / column) : 0;
  const long long per_column = below ? (n + columns - 1) / columns : std::max(1LL, room / kRow);
  // Below the mesh, each group (a heading and its entries) gets a column of its own where there are enough.
  std::vector<long long> group_of(entries.size(), 0), row_in_group(entries.size(), 0);
  long long groups = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i > 0 && !entries[i].colour) ++groups;
    group_of[i] = groups;
    row_in_group[i] = i > 0 && group_of[i - 1] == groups ? row_in_group[i - 1] + 1 : 0;
  }
  const bool by_group = below && groups + 1 <= columns;
  long long far_x = x0, far_y = y0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const long long k = static_cast<long long>(i);
    const long long col = by_group ? group_of[i] : k / per_column, row = by_group ? row_in_group[i] : k % per_column;
    entries[i].x = x0 + col * column;
    entries[i].y = y0 + row * kRow;
    far_x = std::max(far_x, entries[i].x + entry_width(entries[i]));
    far_y = std::max(far_y, entries[i].y + kRow);
  }
  return {far_x, far_y};
}

void write_legend(TextWriter& out, const std::vector<LegendEntry>& entries) {
  out.text("<g font-family=\"sans-serif\" font-size=\"150\" class=\"legend\">\n");
  for (const LegendEntry& e : entries) {
    long long text_x = e.x;
    if (e.colour) {
      const long long bar = e.line ? 80 : kSwatch;
      out.text("<rect x=\"");
      out.integer(e.x);
      out.text("\" y=\"");
      out.integer(e.y + (kSwatch - bar) / 2);
      out.text("\" width=\"250\" height=\"");
      out.integer(bar);
      out.text(std::string("\" stroke=\"#555\" fill=\"") + e.colour + "\"/>");
      text_x += kSwatch + 60;
    }
    out.text("<text x=\"");
    out.integer(text_x);
    out.text("\" y=\"");
    out.integer(e.y + 190);  // the baseline: the text's cap height centred on the swatch
    out.text("\">");
    out.text(e.text);
    out.text("</text>\n");
  }
  out.text("</g>\n");
}

// The boundary and segment edges, one <path> per marker (all black with -B).
struct MarkedEdges {
  std::map<int, std::vector<EdgeRef>> by_marker;
  static const char* colour(std::size_t rank) { return rank < kMarkersListed ? kMarkerColour[rank % kMarkerColour.size()] : "#000"; }
};

MarkedEdges marked_edges(const Mesh& mesh, bool markers) {
  MarkedEdges m;
  for (EdgeRef e : boundary_and_segment_edges(mesh)) m.by_marker[markers ? edge_marker(mesh, e) : 0].push_back(e);
  return m;
}

// 3 pixels wide where few, thinner where thousands would cover the triangles between them.
long long edge_width(std::size_t edges) {
  const double width = 30.0 * std::sqrt(2000.0 / static_cast<double>(std::max<std::size_t>(edges, 1)));
  return std::llround(std::clamp(width, 6.0, 30.0));
}

void write_edges(TextWriter& out, const Mesh& mesh, const Canvas& canvas, const MarkedEdges& edges, bool markers) {
  std::size_t rank = 0, total = 0;
  for (const auto& entry : edges.by_marker) total += entry.second.size();
  const std::string width = std::to_string(edge_width(total));
  for (const auto& [marker, list] : edges.by_marker) {
    const char* colour = markers && marker != 0 ? MarkedEdges::colour(rank++) : "black";
    out.text(std::string("<path fill=\"none\" stroke=\"") + colour + "\" stroke-width=\"" + width +
             "\" stroke-linecap=\"round\" class=\"marker\" data-marker=\"");
    out.integer(markers ? marker : -1);
    out.text("\" d=\"");
    for (EdgeRef e : list) {
      out.text("M");
      out.integer(canvas.x(mesh.points[mesh.org(e)]));
      out.next_integer(canvas.y(mesh.points[mesh.org(e)]));
      out.next_integer(canvas.x(mesh.points[mesh.dest(e)]));
      out.next_integer(canvas.y(mesh.points[mesh.dest(e)]));
      out.end_line();
    }
    out.text("\"/>\n");
  }
}

std::string count_text(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::vector<LegendEntry> legend_entries(const Mesh& mesh, const std::array<std::vector<TriangleId>, kShades>& shade,
                                        const MarkedEdges& edges, bool markers, std::uint32_t left_out) {
  std::vector<LegendEntry> entries;
  entries.push_back({nullptr, false, "smallest angle per triangle; " + count_text(mesh.live_triangles(), "triangle", "triangles")});
  for (int s = 0; s < kShades; ++s)
    entries.push_back({kFill[s], false, std::to_string(10 * s) + "-" + std::to_string(10 * s + 10) + "\xc2\xb0: " +
                                            std::to_string(shade[s].size())});
  if (markers && !edges.by_marker.empty()) {
    entries.push_back({nullptr, false, "boundary and segment edges by marker"});
    std::size_t rank = 0, others = 0;
    for (const auto& [marker, list] : edges.by_marker) {
      if (marker != 0 && rank >= kMarkersListed) {
        others += list.size();
        continue;
      }
      const char* colour = marker == 0 ? "black" : MarkedEdges::colour(rank++);
      entries.push_back({colour, true, "marker " + std::to_string(marker) + ": " + count_text(list.size(), "edge", "edges")});
    }
    if (others > 0) entries.push_back({"#000", true, "other markers: " + count_text(others, "edge", "edges")});
  }
  if (left_out > 0)
    entries.push_back({nullptr, false, count_text(left_out, "vertex", "vertices") + " outside the mesh not drawn"});
  return entries;
}

// Vertices written to the .node that no triangle uses (when there are triangles).
std::uint32_t vertices_left_out(const Mesh& mesh, const VertexNumbering& number) {
  if (mesh.live_triangles() == 0) return 0;
  std::vector<char> used(mesh.vertex_count(), 0);
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t))
      for (EdgeRef e : edges_of(t)) used[mesh.org(e)] = 1;
  std::uint32_t n = 0;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v)
    n += !used[v] && number.written(v) && mesh.kind[v] != VertexKind::Dead && mesh.kind[v] != VertexKind::Duplicate;
  return n;
}

void write_header(TextWriter& out, long long right, long long bottom) {
  const double pixels = 1000.0 / kCanvas;  // the mesh is 1000 pixels across its longer side
  const long long w = right + 2 * kMargin, h = bottom + 2 * kMargin;
  out.text("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"");
  out.integer(-kMargin);
  out.next_integer(-kMargin);
  out.next_integer(w);
  out.next_integer(h);
  out.text("\" width=\"");
  out.integer(std::llround(static_cast<double>(w) * pixels));
  out.text("\" height=\"");
  out.integer(std::llround(static_cast<double>(h) * pixels));
  out.text("\">\n<rect x=\"");
  out.integer(-kMargin);
  out.text("\" y=\"");
  out.integer(-kMargin);
  out.text("\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
}

void write_triangles(TextWriter& out, const Mesh& mesh, const Canvas& canvas,
                     const std::array<std::vector<TriangleId>, kShades>& shade) {
  // Widths are in canvas units (10 to a pixel at the picture's own size): edges at 0.3 pixels
  // stay readable in dense meshes.
  out.text("<g stroke=\"#444\" stroke-width=\"3\" stroke-linejoin=\"round\">\n");
  for (int s = 0; s < kShades; ++s) {
    if (shade[s].empty()) continue;
    out.text(std::string("<path fill=\"") + kFill[s] + "\" d=\"");
    for (TriangleId t : shade[s]) {
      const auto [a, b, c] = mesh.corner_points(t);
      out.text("M");
      out.integer(canvas.x(a));
      out.next_integer(canvas.y(a));
      out.next_integer(canvas.x(b));
      out.next_integer(canvas.y(b));
      out.next_integer(canvas.x(c));
      out.next_integer(canvas.y(c));
      out.text("z\n");
    }
    out.text("\"/>\n");
  }
  out.text("</g>\n");
}

// A vertex the picture draws: one the .node lists, not a duplicate or a deleted vertex.
bool shown(const Mesh& mesh, const VertexNumbering& number, VertexId v) {
  return number.written(v) && mesh.kind[v] != VertexKind::Duplicate && mesh.kind[v] != VertexKind::Dead;
}

void write_vertex_numbers(TextWriter& out, const Mesh& mesh, const Canvas& canvas, const VertexNumbering& number) {
  out.text("<g font-family=\"sans-serif\" font-size=\"90\" fill=\"#003\">\n");
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
    if (!shown(mesh, number, v)) continue;
    if (!canvas.inside(mesh.points[v])) continue;
    out.text("<text x=\"");
    out.integer(canvas.x(mesh.points[v]) + 20);
    out.text("\" y=\"");
    out.integer(canvas.y(mesh.points[v]) - 20);
    out.text("\">");
    out.integer(number(v));
    out.text("</text>\n");
  }
  out.text("</g>\n");
}

// A mesh without triangles (every input vertex outside the domain, or collinear): its vertices as
// dots, so that the picture shows what was read rather than a blank frame.
void write_vertex_dots(TextWriter& out, const Mesh& mesh, const Canvas& canvas, const VertexNumbering& number) {
  out.text("<g fill=\"#444\">\n");
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
    if (!shown(mesh, number, v)) continue;
    out.text("<circle r=\"40\" cx=\"");
    out.integer(canvas.x(mesh.points[v]));
    out.text("\" cy=\"");
    out.integer(canvas.y(mesh.points[v]));
    out.text("\"/>\n");
  }
  out.text("</g>\n");
}

}  // namespace

double smallest_angle_degrees(const Point& a, const Point& b, const Point& c) {
  const double m = std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
  return m * (180.0 / 3.14159265358979323846);
}

void write_svg_file(ByteSink& sink, const Mesh& mesh, const SvgOptions& options) {
  const VertexNumbering number{options.mesh.numbering, options.first_index};
  const Canvas canvas(mesh, number);
  std::array<std::vector<TriangleId>, kShades> shade;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const auto [a, b, c] = mesh.corner_points(t);
    const double angle = smallest_angle_degrees(a, b, c);
    shade[std::clamp(static_cast<int>(angle / 10.0), 0, kShades - 1)].push_back(t);
  }
  const bool markers = options.mesh.markers;
  const MarkedEdges edges = marked_edges(mesh, markers);
  std::vector<LegendEntry> legend = legend_entries(mesh, shade, edges, markers, vertices_left_out(mesh, number));
  const auto [far_x, far_y] = lay_out(legend, canvas.width(), canvas.height());
  sink.expect(static_cast<std::size_t>(mesh.live_triangles()) * 32 + 4096);
  TextWriter out(sink);
  write_header(out, std::max(canvas.width(), far_x), std::max(canvas.height(), far_y));
  write_triangles(out, mesh, canvas, shade);
  if (mesh.live_triangles() == 0) write_vertex_dots(out, mesh, canvas, number);
  write_edges(out, mesh, canvas, edges, markers);
  for (const Point& p : options.holes) {
    if (!canvas.inside(p)) continue;
    out.text("<circle fill=\"none\" stroke=\"#c00\" stroke-width=\"20\" r=\"60\" cx=\"");
    out.integer(canvas.x(p));
    out.text("\" cy=\"");
    out.integer(canvas.y(p));
    out.text("\"/>\n");
  }
  if (options.vertex_numbers) write_vertex_numbers(out, mesh, canvas, number);
  write_legend(out, legend);
  out.text("</svg>\n");
  out.finish();
}

}  // namespace deltri
