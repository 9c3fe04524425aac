// Readers for the Triangle file formats, written independently of deltri's src/io.
// Lines are split at '#' (comment) and whitespace; blank lines are skipped. Numbers must be whole
// tokens for strtod/strtol and finite.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "verify.h"

namespace mv {
namespace {

class Lines {
 public:
  Lines(const std::string& path, Failures& f) : path_(path), f_(f) {
    std::ifstream file(path, std::ios::binary);
    ok_ = static_cast<bool>(file);
    if (!ok_) return;
    std::stringstream ss;
    ss << file.rdbuf();
    text_ = ss.str();
    if (text_.starts_with("\xEF\xBB\xBF")) text_.erase(0, 3);  // a UTF-8 byte order mark
  }
  bool opened() const { return ok_; }

  // Next non-blank line's tokens; false at the end of the file.
  bool next(std::vector<std::string>& tokens) {
    tokens.clear();
    while (pos_ < text_.size() && tokens.empty()) {
      std::size_t end = text_.find('\n', pos_);
      if (end == std::string::npos) end = text_.size();
      std::string line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      line = line.substr(0, line.find('#'));
      std::istringstream words(line);
      for (std::string w; words >> w;) tokens.push_back(w);
    }
    return !tokens.empty();
  }
  // Like next() but a missing line is a failure.
  bool need(std::vector<std::string>& tokens, std::size_t min_tokens, const char* what) {
    if (!next(tokens)) return fail(std::string("missing ") + what);
    if (tokens.size() < min_tokens) return fail(std::string("too few fields in ") + what);
    return true;
  }
  bool fail(const std::string& message) {
    f_.add("parse", path_ + ":" + std::to_string(line_) + ": " + message);
    return false;
  }
  bool number(const std::string& token, double& value) {
    errno = 0;
    char* end = nullptr;
    value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0' || !std::isfinite(value)) return fail("not a finite number: '" + token + "'");
    return true;
  }
  bool integer(const std::string& token, long& value) {
    errno = 0;
    char* end = nullptr;
    value = std::strtol(token.c_str(), &end, 10);
    if (end == token.c_str() || *end != '\0' || errno != 0) return fail("not an integer: '" + token + "'");
    return true;
  }
  // A count in a header, 0 <= value <= limit.
  bool count(const std::string& token, long& value, long limit = 100000000) {
    if (!integer(token, value)) return false;
    if (value < 0 || value > limit) return fail("count out of range: " + token);
    return true;
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  Failures& f_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 0;
  bool ok_ = false;
};

// A node section: header then lines "index x y [attributes] [marker]". The first line's index
// sets the numbering; later ones must follow consecutively. strict: exact field counts.
bool read_nodes(Lines& in, std::vector<Point>& points, int& first, bool strict, bool allow_empty_header) {
  std::vector<std::string> t;
  long n = 0, dim = 2, attrs = 0, markers = 0;
  if (!in.need(t, 1, "node header")) return false;
  if (!in.count(t[0], n)) return false;
  if (t.size() > 1 && !in.integer(t[1], dim)) return false;
  if (t.size() > 2 && !in.count(t[2], attrs, 1000)) return false;
  // Any non-zero marker count means "one marker column", as Triangle reads it.
  if (t.size() > 3 && !in.count(t[3], markers, 2147483647)) return false;
  markers = markers != 0;
  if (dim != 2) return in.fail("dimension is not 2");
  if (n == 0 && allow_empty_header) return true;
  const std::size_t fields = 3 + attrs + markers;
  for (long k = 0; k < n; ++k) {
    if (!in.need(t, fields, "vertex line")) return false;
    if (strict && t.size() != fields) return in.fail("wrong number of fields in a vertex line");
    long index = 0;
    Point p;
    if (!in.integer(t[0], index) || !in.number(t[1], p.x) || !in.number(t[2], p.y)) return false;
    for (std::size_t a = 3; a < fields; ++a) {
      double ignored = 0;
      if (!in.number(t[a], ignored)) return false;
    }
    if (k == 0) {
      if (index != 0 && index != 1 && strict) return in.fail("first vertex number is not 0 or 1");
      first = static_cast<int>(index);
    } else if (index != first + k) {
      return in.fail("vertex numbers are not consecutive: " + t[0]);
    }
    points.push_back(p);
  }
  return true;
}

// Segment lines "index a b [marker]" with endpoints in [first, first + n). Out-of-range endpoints
// fail when strict (output files) and drop the segment otherwise (deltri ignores them too).
bool read_segments(Lines& in, long count, long markers, int first, std::size_t n, bool strict,
                   std::vector<EdgeLine>& out) {
  std::vector<std::string> t;
  const std::size_t fields = 3 + markers;
  for (long k = 0; k < count; ++k) {
    if (!in.need(t, 3, "segment/edge line")) return false;
    if (strict && t.size() != fields) return in.fail("wrong number of fields in a segment/edge line");
    long index = 0, a = 0, b = 0, marker = 0;
    if (!in.integer(t[0], index) || !in.integer(t[1], a) || !in.integer(t[2], b)) return false;
    if (strict && index != first + k) return in.fail("numbers are not consecutive: " + t[0]);
    if (markers && t.size() > 3 && !in.integer(t[3], marker)) return false;
    const bool in_range = a >= first && b >= first && a < first + static_cast<long>(n) && b < first + static_cast<long>(n);
    if (!in_range) {
      if (strict) return in.fail("endpoint out of range");
      continue;
    }
    EdgeLine e{static_cast<int>(a - first), static_cast<int>(b - first), std::nullopt};
    if (markers) e.marker = static_cast<int>(marker);
    out.push_back(e);
  }
  return true;
}

bool read_holes(Lines& in, std::vector<Point>& holes) {
  std::vector<std::string> t;
  long count = 0;
  if (!in.next(t)) return true;  // Triangle tolerates a missing hole section
  if (!in.count(t[0], count)) return false;
  for (long k = 0; k < count; ++k) {
    Point p;
    if (!in.need(t, 3, "hole line") || !in.number(t[1], p.x) || !in.number(t[2], p.y)) return false;
    holes.push_back(p);
  }
  return true;
}

std::string sibling(const std::string& path, const std::string& extension) {
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? path.substr(0, dot) : path) + extension;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

bool read_input(const std::string& path, InputPslg& in, Failures& f) {
  Lines lines(path, f);
  if (!lines.opened()) return lines.fail("cannot open the input");
  in.is_poly = ends_with(path, ".poly");
  int first = 1;
  if (!read_nodes(lines, in.points, first, false, in.is_poly)) return false;
  if (!in.is_poly) return true;
  if (in.points.empty()) {  // vertices in the .node next to the .poly
    Lines nodes(sibling(path, ".node"), f);
    if (nodes.opened() && !read_nodes(nodes, in.points, first, false, false)) return false;
  }
  std::vector<std::string> t;
  long count = 0, markers = 0;
  if (!lines.need(t, 1, "segment header") || !lines.count(t[0], count)) return false;
  if (t.size() > 1 && !lines.count(t[1], markers, 2147483647)) return false;
  markers = markers != 0;
  std::vector<EdgeLine> segments;
  if (!read_segments(lines, count, markers, first, in.points.size(), false, segments)) return false;
  for (const EdgeLine& e : segments) in.segments.push_back({e.a, e.b, e.marker.value_or(0)});
  return read_holes(lines, in.holes);
}

bool read_output(const std::string& base, OutputMesh& out, Failures& f) {
  Lines node(base + ".node", f);
  if (!node.opened()) return node.fail("cannot open");
  if (!read_nodes(node, out.points, out.first, true, false)) return false;
  std::vector<std::string> t;
  if (node.next(t)) return node.fail("text after the last vertex");

  Lines ele(base + ".ele", f);
  if (!ele.opened()) return ele.fail("cannot open");
  long count = 0, corners = 0, attrs = 0;
  if (!ele.need(t, 2, "header") || !ele.count(t[0], count) || !ele.integer(t[1], corners)) return false;
  if (t.size() > 2 && !ele.count(t[2], attrs, 1000)) return false;
  if (corners != 3 && corners != 6) return ele.fail("not 3 or 6 nodes per triangle");
  const long n = static_cast<long>(out.points.size());
  for (long k = 0; k < count; ++k) {
    if (!ele.need(t, 1 + corners + attrs, "triangle line")) return false;
    if (t.size() != static_cast<std::size_t>(1 + corners + attrs)) return ele.fail("wrong number of fields in a triangle line");
    long index = 0;
    std::array<int, 6> nodes{};
    if (!ele.integer(t[0], index)) return false;
    if (index != out.first + k) return ele.fail("triangle numbers are not consecutive from the .node's first index");
    for (int i = 0; i < corners; ++i) {
      long v = 0;
      if (!ele.integer(t[1 + i], v)) return false;
      if (v < out.first || v >= out.first + n) return ele.fail("vertex number out of range: " + t[1 + i]);
      nodes[i] = static_cast<int>(v - out.first);
    }
    for (long a = 0; a < attrs; ++a) {
      double ignored = 0;
      if (!ele.number(t[1 + corners + a], ignored)) return false;
    }
    out.triangles.push_back({nodes[0], nodes[1], nodes[2]});
    if (corners == 6) out.midpoints.push_back({nodes[3], nodes[4], nodes[5]});
  }
  if (ele.next(t)) return ele.fail("text after the last triangle");

  Lines edge(base + ".edge", f);
  if (edge.opened()) {
    long markers = 0;
    if (!edge.need(t, 1, "header") || !edge.count(t[0], count)) return false;
    if (t.size() > 1 && !edge.count(t[1], markers, 1)) return false;
    out.edges.emplace();
    if (!read_segments(edge, count, markers, out.first, out.points.size(), true, *out.edges)) return false;
  }

  Lines neigh(base + ".neigh", f);
  if (neigh.opened()) {
    if (!neigh.need(t, 2, "header") || !neigh.count(t[0], count)) return false;
    if (count != static_cast<long>(out.triangles.size()) || t[1] != "3") return neigh.fail("header does not match the .ele");
    out.neighbors.emplace();
    for (long k = 0; k < count; ++k) {
      if (!neigh.need(t, 4, "neighbour line")) return false;
      long index = 0;
      std::array<int, 3> nb{};
      if (!neigh.integer(t[0], index)) return false;
      if (index != out.first + k) return neigh.fail("numbers are not consecutive");
      for (int i = 0; i < 3; ++i) {
        long v = 0;
        if (!neigh.integer(t[1 + i], v)) return false;
        if (v != -1 && (v < out.first || v >= out.first + count)) return neigh.fail("neighbour out of range: " + t[1 + i]);
        nb[i] = v == -1 ? -1 : static_cast<int>(v - out.first);
      }
      out.neighbors->push_back(nb);
    }
  }

  Lines vnode(base + ".v.node", f);
  if (vnode.opened()) {
    int vfirst = out.first;
    out.voronoi_points.emplace();
    if (!read_nodes(vnode, *out.voronoi_points, vfirst, false, false)) return false;
    if (vfirst != out.first) return vnode.fail("numbered from " + std::to_string(vfirst) + ", the .node from " + std::to_string(out.first));
    Lines vedge(base + ".v.edge", f);
    if (!vedge.opened()) return vedge.fail("cannot open (the .v.node exists)");
    if (!vedge.need(t, 1, "header") || !vedge.count(t[0], count)) return false;
    const long nv = static_cast<long>(out.voronoi_points->size());
    for (long k = 0; k < count; ++k) {
      if (!vedge.need(t, 3, "Voronoi edge line")) return false;
      long index = 0, a = 0, b = 0;
      if (!vedge.integer(t[0], index) || !vedge.integer(t[1], a) || !vedge.integer(t[2], b)) return false;
      if (index != out.first + k) return vedge.fail("numbers are not consecutive");
      OutputMesh::VoronoiEdge e;
      if (a < out.first || a >= out.first + nv) return vedge.fail("Voronoi vertex out of range: " + t[1]);
      e.a = static_cast<int>(a - out.first);
      if (b == -1) {
        if (t.size() != 5 || !vedge.number(t[3], e.dx) || !vedge.number(t[4], e.dy)) return vedge.fail("a ray needs a direction dx dy");
      } else {
        if (t.size() != 3) return vedge.fail("wrong number of fields in a Voronoi edge line");
        if (b < out.first || b >= out.first + nv) return vedge.fail("Voronoi vertex out of range: " + t[2]);
        e.b = static_cast<int>(b - out.first);
      }
      out.voronoi_edges.push_back(e);
    }
    if (vedge.next(t)) return vedge.fail("text after the last edge");
  }

  Lines off(base + ".off", f);
  if (off.opened()) {
    long nv = 0, nf = 0, ne = 0;
    if (!off.need(t, 1, "OFF keyword")) return false;
    if (t[0] != "OFF" || t.size() != 1) return off.fail("the first line is not OFF");
    if (!off.need(t, 3, "counts") || !off.count(t[0], nv) || !off.count(t[1], nf) || !off.count(t[2], ne)) return false;
    out.off_points.emplace();
    for (long k = 0; k < nv; ++k) {
      Point p;
      double z = 0;
      if (!off.need(t, 3, "vertex line") || !off.number(t[0], p.x) || !off.number(t[1], p.y) || !off.number(t[2], z)) return false;
      if (t.size() != 3 || z != 0) return off.fail("a vertex line is not 'x y 0'");
      out.off_points->push_back(p);
    }
    for (long k = 0; k < nf; ++k) {
      if (!off.need(t, 4, "face line")) return false;
      if (t.size() != 4 || t[0] != "3") return off.fail("a face line is not '3 a b c'");
      std::array<int, 3> face{};
      for (int i = 0; i < 3; ++i) {
        long v = 0;
        if (!off.integer(t[1 + i], v)) return false;
        if (v < 0 || v >= nv) return off.fail("face vertex out of range (OFF numbers from 0): " + t[1 + i]);
        face[i] = static_cast<int>(v);
      }
      out.off_faces.push_back(face);
    }
    if (off.next(t)) return off.fail("text after the last face");
  }

  Lines poly(base + ".poly", f);
  if (poly.opened()) {
    std::vector<Point> embedded;
    int first = out.first;
    if (!read_nodes(poly, embedded, first, true, true)) return false;
    if (!embedded.empty() && embedded.size() != out.points.size()) return poly.fail("vertex count differs from the .node");
    long markers = 0;
    if (!poly.need(t, 1, "segment header") || !poly.count(t[0], count)) return false;
    if (t.size() > 1 && !poly.count(t[1], markers, 1)) return false;
    out.poly_segments.emplace();
    if (!read_segments(poly, count, markers, out.first, out.points.size(), true, *out.poly_segments)) return false;
    std::vector<Point> holes;
    if (!read_holes(poly, holes)) return false;
  }
  return true;
}

}  // namespace mv
