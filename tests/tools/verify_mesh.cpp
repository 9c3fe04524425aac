// Shared helpers: failure collection, exact point keys, a uniform grid, the mesh topology.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "verify.h"

namespace mv {

void Failures::add(const std::string& kind, const std::string& message) {
  if (++counts_[kind] <= kShownPerKind) lines_.push_back(kind + ": " + message);
}

void Failures::print() const {
  for (const std::string& line : lines_) std::printf("%s\n", line.c_str());
  for (const auto& [kind, n] : counts_)
    if (n > kShownPerKind) std::printf("%s: ... %d failures in all\n", kind.c_str(), n);
}

std::size_t PointHash::operator()(const Point& p) const {
  const double x = p.x + 0.0, y = p.y + 0.0;  // -0 -> +0
  std::uint64_t a = 0, b = 0;
  std::memcpy(&a, &x, sizeof a);
  std::memcpy(&b, &y, sizeof b);
  return std::hash<std::uint64_t>()(a * 0x9E3779B97F4A7C15ULL ^ (b + 0x632BE59BD9B4E019ULL + (a << 6)));
}

bool on_closed_segment(deltri::Predicates& pred, const Point& a, const Point& b, const Point& p) {
  return pred.orient2d(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

bool properly_cross(deltri::Predicates& pred, const Point& a, const Point& b, const Point& d, const Point& e) {
  const auto opposite = [](double u, double v) { return (u > 0 && v < 0) || (u < 0 && v > 0); };
  return opposite(pred.orient2d(a, b, d), pred.orient2d(a, b, e)) &&
         opposite(pred.orient2d(d, e, a), pred.orient2d(d, e, b));
}

std::string fmt(const Point& p) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

Grid::Grid(const std::vector<Point>& pts, std::size_t items) {
  if (pts.empty()) {
    cells_.resize(1);
    return;
  }
  double max_x = pts[0].x, max_y = pts[0].y;
  min_x_ = pts[0].x;
  min_y_ = pts[0].y;
  for (const Point& p : pts) {
    min_x_ = std::min(min_x_, p.x);
    min_y_ = std::min(min_y_, p.y);
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
  }
  const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(items) / 2.0)));
  nx_ = ny_ = std::min(side, 1024);
  cell_w_ = (max_x - min_x_) / nx_;
  cell_h_ = (max_y - min_y_) / ny_;
  if (!(cell_w_ > 0)) cell_w_ = 1;
  if (!(cell_h_ > 0)) cell_h_ = 1;
  cells_.resize(static_cast<std::size_t>(nx_) * ny_);
}

int Grid::cell_x(double x) const {
  const double c = std::floor((x - min_x_) / cell_w_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

int Grid::cell_y(double y) const {
  const double c = std::floor((y - min_y_) / cell_h_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(ny_ - 1)));
}

// Cells are widened by one on each side, so rounding in cell_x/cell_y can never lose an item.
void Grid::insert(int id, const Point& lo, const Point& hi) {
  const int x1 = std::min(cell_x(hi.x) + 1, nx_ - 1), y1 = std::min(cell_y(hi.y) + 1, ny_ - 1);
  for (int y = std::max(cell_y(lo.y) - 1, 0); y <= y1; ++y)
    for (int x = std::max(cell_x(lo.x) - 1, 0); x <= x1; ++x) cells_[static_cast<std::size_t>(y) * nx_ + x].push_back(id);
}

std::vector<int> Grid::query(const Point& lo, const Point& hi) const {
  std::vector<int> ids;
  for (int y = cell_y(lo.y); y <= cell_y(hi.y); ++y)
    for (int x = cell_x(lo.x); x <= cell_x(hi.x); ++x) {
      const auto& cell = cells_[static_cast<std::size_t>(y) * nx_ + x];
      ids.insert(ids.end(), cell.begin(), cell.end());
    }
  return ids;
}

namespace {

Point lower(const Point& a, const Point& b) { return {std::min(a.x, b.x), std::min(a.y, b.y)}; }
Point upper(const Point& a, const Point& b) { return {std::max(a.x, b.x), std::max(a.y, b.y)}; }

Topology build_topology(const OutputMesh& out) {
  Topology topo;
  topo.used.assign(out.points.size(), 0);
  topo.adjacent.resize(out.points.size());
  for (std::size_t t = 0; t < out.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = out.triangles[t][i], b = out.triangles[t][(i + 1) % 3];
      topo.used[a] = 1;
      topo.directed.emplace(edge_key(a, b), static_cast<int>(3 * t + i));  // duplicates are reported later
      topo.adjacent[a].push_back(b);
      topo.adjacent[b].push_back(a);
    }
  for (auto& list : topo.adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  for (std::size_t v = 0; v < out.points.size(); ++v)
    if (topo.used[v]) topo.used_at.emplace(out.points[v], static_cast<int>(v));
  return topo;
}

std::vector<Point> used_points(const OutputMesh& out) {
  std::vector<Point> pts;
  for (const auto& t : out.triangles)
    for (int v : t) pts.push_back(out.points[v]);
  return pts;
}

}  // namespace

Context::Context(const InputPslg& input, const OutputMesh& output)
    : in(input),
      out(output),
      topo(build_topology(output)),
      triangle_grid(used_points(output), output.triangles.size()),
      vertex_grid(used_points(output), output.triangles.size()) {
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    const Point a = tri_point(t, 0), b = tri_point(t, 1), c = tri_point(t, 2);
    triangle_grid.insert(static_cast<int>(t), lower(lower(a, b), c), upper(upper(a, b), c));
  }
  for (std::size_t v = 0; v < out.points.size(); ++v)
    if (topo.used[v]) vertex_grid.insert(static_cast<int>(v), out.points[v], out.points[v]);
}

std::vector<int> Context::triangles_near(const Point& p, const Point& q) const {
  std::vector<int> ids = triangle_grid.query(lower(p, q), upper(p, q));
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

// Separating-axis test with exact signs: the open segment and the open triangle are disjoint iff
// one of the triangle's edge lines or the segment's line weakly separates them.
bool Context::open_segment_meets_mesh(const Point& p, const Point& q) {
  for (int t : triangles_near(p, q)) {
    const Point c[3] = {tri_point(t, 0), tri_point(t, 1), tri_point(t, 2)};
    bool separated = false;
    for (int i = 0; i < 3 && !separated; ++i)
      separated = pred.orient2d(c[i], c[(i + 1) % 3], p) <= 0 && pred.orient2d(c[i], c[(i + 1) % 3], q) <= 0;
    if (separated) continue;
    int pos = 0, neg = 0;
    for (const Point& v : c) {
      const double o = pred.orient2d(p, q, v);
      pos += o > 0;
      neg += o < 0;
    }
    if (pos == 0 || neg == 0) continue;
    return true;
  }
  return false;
}

}  // namespace mv
