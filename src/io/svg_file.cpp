#include "io/svg_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "geometry/box.h"

namespace deltri {
namespace {

constexpr double kCanvas = 10000.0;
constexpr int kShades = 6;
// Worst (below 10 degrees) to best (50 to 60): red through yellow to blue.
constexpr std::array<const char*, kShades> kFill = {"#d7301f", "#fc8d59", "#fdcc8a", "#d9f0a3", "#91cf60", "#4393c3"};

double angle_at(const Point& p, const Point& q, const Point& r) {
  const double ux = q.x - p.x, uy = q.y - p.y, vx = r.x - p.x, vy = r.y - p.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

class Canvas {
 public:
  Canvas(const Mesh& mesh, const VertexNumbering& number, const std::vector<Point>& holes) {
    Box box;
    for (VertexId v{0}; v < mesh.vertex_count(); ++v)
      if (number.written(v)) box.add(mesh.points[v]);
    for (const Point& h : holes) box.add(h);
    if (box.empty()) box = Box{0, 0, 1, 1};
    const double span = std::max({box.width(), box.height(), std::numeric_limits<double>::min()});
    scale_ = kCanvas / span;
    lo_x_ = box.lo_x, hi_y_ = box.hi_y;
    width_ = std::max(1.0, std::ceil(box.width() * scale_));
    height_ = std::max(1.0, std::ceil(box.height() * scale_));
  }
  long long x(const Point& p) const { return std::llround((p.x - lo_x_) * scale_); }
  long long y(const Point& p) const { return std::llround((hi_y_ - p.y) * scale_); }
  double width() const { return width_; }
  double height() const { return height_; }

 private:
  double scale_ = 1, lo_x_ = 0, hi_y_ = 0, width_ = 1, height_ = 1;
};

}  // namespace

double smallest_angle_degrees(const Point& a, const Point& b, const Point& c) {
  const double m = std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
  return m * (180.0 / 3.14159265358979323846);
}

void write_svg_file(ByteSink& sink, const Mesh& mesh, const SvgOptions& options) {
  const VertexNumbering number{options.mesh.numbering, options.first_index};
  const Canvas canvas(mesh, number, options.holes);
  std::array<std::vector<TriangleId>, kShades> shade;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const auto [a, b, c] = mesh.corner_points(t);
    const double angle = smallest_angle_degrees(a, b, c);
    shade[std::clamp(static_cast<int>(angle / 10.0), 0, kShades - 1)].push_back(t);
  }
  sink.expect(static_cast<std::size_t>(mesh.live_triangles()) * 32 + 4096);
  TextWriter out(sink);
  const long long w = static_cast<long long>(canvas.width()), h = static_cast<long long>(canvas.height());
  const double pixels = 1000.0 / kCanvas;  // the picture is 1000 pixels across its longer side
  out.text("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"");
  out.integer(-200);
  out.next_integer(-200);
  out.next_integer(w + 400);
  out.next_integer(h + 1200);
  out.text("\" width=\"");
  out.integer(std::llround((w + 400) * pixels));
  out.text("\" height=\"");
  out.integer(std::llround((h + 1200) * pixels));
  out.text("\">\n<rect x=\"-200\" y=\"-200\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
  // Widths are in canvas units (10 to a pixel at the picture's own size): edges at 0.3 pixels
  // stay readable in dense meshes, segments at 1.5 pixels stand out.
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
  if (mesh.has_subsegments()) {
    out.text("<path fill=\"none\" stroke=\"black\" stroke-width=\"15\" stroke-linecap=\"round\" d=\"");
    for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
      if (!mesh.is_live(t)) continue;
      for (EdgeRef e : edges_of(t)) {
        if (!mesh.subseg.has(e) || !(mesh.link[e] == kNone || mesh.link[e] > e)) continue;
        out.text("M");
        out.integer(canvas.x(mesh.points[mesh.org(e)]));
        out.next_integer(canvas.y(mesh.points[mesh.org(e)]));
        out.next_integer(canvas.x(mesh.points[mesh.dest(e)]));
        out.next_integer(canvas.y(mesh.points[mesh.dest(e)]));
        out.end_line();
      }
    }
    out.text("\"/>\n");
  }
  for (const Point& p : options.holes) {
    out.text("<circle fill=\"none\" stroke=\"#c00\" stroke-width=\"20\" r=\"60\" cx=\"");
    out.integer(canvas.x(p));
    out.text("\" cy=\"");
    out.integer(canvas.y(p));
    out.text("\"/>\n");
  }
  if (options.vertex_numbers) {
    out.text("<g font-family=\"sans-serif\" font-size=\"90\" fill=\"#003\">\n");
    for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
      if (!number.written(v) || mesh.kind[v] == VertexKind::Duplicate || mesh.kind[v] == VertexKind::Dead) continue;
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
  // The legend: what each shade means and how many triangles have it.
  out.text("<g font-family=\"sans-serif\" font-size=\"150\">\n");
  for (int s = 0; s < kShades; ++s) {
    const long long x = s * (w + 200) / kShades;
    out.text("<rect y=\"");
    out.integer(h + 300);
    out.text("\" x=\"");
    out.integer(x);
    out.text(std::string("\" width=\"250\" height=\"250\" stroke=\"#555\" fill=\"") + kFill[s] + "\"/><text y=\"");
    out.integer(h + 520);
    out.text("\" x=\"");
    out.integer(x + 300);
    out.text("\">");
    out.integer(10 * s);
    out.text(s + 1 < kShades ? "-" : "-60");
    if (s + 1 < kShades) out.integer(10 * s + 10);
    out.text("\xc2\xb0: ");
    out.integer(static_cast<long long>(shade[s].size()));
    out.text("</text>\n");
  }
  out.text("<text y=\"");
  out.integer(h + 900);
  out.text("\" x=\"0\">smallest angle per triangle; ");
  out.integer(mesh.live_triangles());
  out.text(" triangles</text>\n</g>\n</svg>\n");
  out.finish();
}

}  // namespace deltri
