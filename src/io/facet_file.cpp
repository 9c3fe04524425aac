#include "io/facet_file.h"

#include <climits>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "io/line_reader.h"
#include "util/errors.h"

namespace deltri {
namespace {

constexpr long long kMaxItems = 0xFFFFFFF0LL;
constexpr long long kMaxAttributes = 1 << 20;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string base_of(const std::string& path) {
  for (const char* ext : {".poly", ".smesh"})
    if (ends_with(path, ext)) return path.substr(0, path.size() - std::string(ext).size());
  return path;
}

struct NodeHeader3 {
  std::uint32_t count = 0;
  int attributes = 0;
  bool markers = false;
};

NodeHeader3 read_header(LineReader& in) {
  if (!in.next_line()) in.fail("unexpected end of file: the node header is missing");
  NodeHeader3 h;
  h.count = static_cast<std::uint32_t>(in.read_int({"node header", -1, "number of points"}, 0, kMaxItems));
  if (in.has_field() && in.read_int({"node header", -1, "dimension"}, LLONG_MIN, LLONG_MAX) != 3)
    in.fail("node header: dimension must be 3 for facets in space");
  if (in.has_field())
    h.attributes = static_cast<int>(in.read_int({"node header", -1, "number of attributes"}, 0, kMaxAttributes));
  if (in.has_field()) h.markers = in.read_int({"node header", -1, "number of boundary markers"}, 0, INT_MAX) != 0;
  return h;
}

// A 2-D .poly whose header says dimension 3 by a typo: its first point has exactly the fields of a
// planar point (two coordinates), one fewer than the header asks for. Said so, rather than
// failing on whichever later field is then missing.
void refuse_planar_point(LineReader& in, const NodeHeader3& h, long long index) {
  const LineReader::Mark start = in.mark();
  int fields = 0;
  try {
    for (; in.has_field(); ++fields) in.read_double({"point", index, "field"});
  } catch (const InputError&) {
    fields = -1;  // not all numbers: the reading proper will say what is wrong
  }
  in.reset(start);
  if (fields == 2 + h.attributes + (h.markers ? 1 : 0))
    in.fail("the node header says dimension 3, but point " + std::to_string(index) +
            " has 2 coordinates (x y), as a 2-D file has: for a planar .poly the dimension must be 2");
}

void read_points(LineReader& in, const NodeHeader3& h, FacetInput& out) {
  for (std::uint32_t k = 0; k < h.count; ++k) {
    if (!in.next_line())
      in.fail("unexpected end of file: " + std::to_string(h.count) + " points announced, " + std::to_string(k) + " found");
    const long long expected = out.first_index + static_cast<long long>(k);
    const long long index = in.read_int({"point", expected, "index"}, LLONG_MIN, LLONG_MAX);
    if (k == 0) {
      if (index != 0 && index != 1) in.fail("first point: index must be 0 or 1, not " + std::to_string(index));
      refuse_planar_point(in, h, index);
      out.first_index = static_cast<int>(index);
    } else if (index != expected) {
      in.fail("point index " + std::to_string(index) + " is out of sequence: expected " + std::to_string(expected));
    }
    Point3 p;
    p.x = in.read_double({"point", index, "x coordinate"});
    p.y = in.read_double({"point", index, "y coordinate"});
    p.z = in.read_double({"point", index, "z coordinate"});
    for (int a = 0; a < h.attributes; ++a) in.read_double({"point", index, "attribute", a + 1});
    if (h.markers) out.markers.push_back(static_cast<int>(in.read_int({"point", index, "boundary marker"}, INT_MIN, INT_MAX)));
    out.points.push_back(p);
  }
  out.has_markers = h.markers;
}

// The node section of the file itself, or of <base>.node when its count is 0.
void read_node_section(LineReader& in, FacetInput& out) {
  const NodeHeader3 h = read_header(in);
  if (h.count > 0) {
    read_points(in, h, out);
  } else {
    if (in.name() == kStandardInputName) in.fail("the points are in a separate .node file, which standard input cannot name");
    LineReader node = LineReader::open(base_of(in.name()) + ".node", in.threads());
    const NodeHeader3 nh = read_header(node);
    read_points(node, nh, out);
  }
  if (out.points.size() < 3) in.fail("facets need at least 3 points, the node section has " + std::to_string(out.points.size()));
}

std::uint32_t read_corner(LineReader& in, const FacetInput& out, long long facet) {
  const long long first = out.first_index;
  const long long last = first + static_cast<long long>(out.points.size()) - 1;
  const long long v = in.read_int({"facet", facet, "corner"}, LLONG_MIN, LLONG_MAX);
  if (v < first || v > last) in.fail(corner_not_a_point(facet, v, first, last));
  return static_cast<std::uint32_t>(v - first);
}

std::vector<std::uint32_t> read_polygon(LineReader& in, const FacetInput& out, long long facet) {
  const long long corners = in.read_int({"facet", facet, "number of corners"}, 1, kMaxItems);
  std::vector<std::uint32_t> polygon;
  for (long long c = 0; c < corners; ++c) {
    if (!in.has_field())
      in.fail("facet " + std::to_string(facet) + ": the polygon announces " + std::to_string(corners) + " corners, " +
              std::to_string(c) + " found");
    polygon.push_back(read_corner(in, out, facet));
  }
  return polygon;
}

void next_facet_line(LineReader& in, std::uint32_t count, std::uint32_t k) {
  if (!in.next_line())
    in.fail("unexpected end of file: " + std::to_string(count) + " facets announced, " + std::to_string(k) + " complete");
}

void read_poly_facet(LineReader& in, FacetInput& out, bool markers, long long number, std::uint32_t count, std::uint32_t k) {
  FacetInput::Facet f;
  f.line = in.line();
  const long long polygons = in.read_int({"facet", number, "number of polygons"}, 1, kMaxItems);
  const long long holes = in.has_field() ? in.read_int({"facet", number, "number of holes"}, 0, kMaxItems) : 0;
  if (markers && in.has_field()) f.marker = static_cast<int>(in.read_int({"facet", number, "boundary marker"}, INT_MIN, INT_MAX));
  for (long long p = 0; p < polygons; ++p) {
    next_facet_line(in, count, k);
    f.polygons.push_back(read_polygon(in, out, number));
  }
  for (long long h = 0; h < holes; ++h) {
    next_facet_line(in, count, k);
    f.hole_lines.push_back(in.line());
    in.read_int({"facet hole", h + 1, "index"}, LLONG_MIN, LLONG_MAX);
    Point3 p;
    p.x = in.read_double({"facet hole", h + 1, "x coordinate"});
    p.y = in.read_double({"facet hole", h + 1, "y coordinate"});
    p.z = in.read_double({"facet hole", h + 1, "z coordinate"});
    f.holes.push_back(p);
  }
  out.facets.push_back(std::move(f));
}

void read_smesh_facet(LineReader& in, FacetInput& out, bool markers, long long number) {
  FacetInput::Facet f;
  f.line = in.line();
  f.polygons.push_back(read_polygon(in, out, number));
  if (markers && in.has_field()) f.marker = static_cast<int>(in.read_int({"facet", number, "boundary marker"}, INT_MIN, INT_MAX));
  out.facets.push_back(std::move(f));
}

void read_facets(LineReader& in, FacetInput& out, bool smesh) {
  if (!in.next_line()) in.fail("unexpected end of file: the facet header is missing");
  const auto count = static_cast<std::uint32_t>(in.read_int({"facet header", -1, "number of facets"}, 1, kMaxItems));
  const bool markers = in.has_field() && in.read_int({"facet header", -1, "number of boundary markers"}, 0, INT_MAX) != 0;
  for (std::uint32_t k = 0; k < count; ++k) {
    const long long number = out.first_index + static_cast<long long>(k);
    next_facet_line(in, count, k);
    if (smesh)
      read_smesh_facet(in, out, markers, number);
    else
      read_poly_facet(in, out, markers, number, count, k);
  }
}

}  // namespace

namespace {

// Whether a .poly line with something on it gives dimension 3 (its second word), or nullopt for a
// line of nothing but separators and comments.
std::optional<bool> says_three_dimensions(std::string line) {
  line = line.substr(0, line.find('#'));
  for (char& c : line)
    if (c == ',' || c == '\t' || c == '\r') c = ' ';
  const std::size_t a = line.find_first_not_of(' ');
  if (a == std::string::npos) return std::nullopt;
  const std::size_t b = line.find_first_of(' ', a);
  const std::size_t c = b == std::string::npos ? std::string::npos : line.find_first_not_of(' ', b);
  if (c == std::string::npos) return false;
  const std::size_t d = line.find_first_of(' ', c);
  return line.substr(c, d == std::string::npos ? std::string::npos : d - c) == "3";
}

}  // namespace

bool is_facet_file(const std::string& path) {
  if (ends_with(path, ".smesh")) return true;
  if (path == "-") return false;
  // C stdio rather than a stream: a small run then never starts iostreams and their locale. The
  // buffer is given (and outlives the file), so stdio does not ask the file system for a block size.
  char buffer[4096];
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) return false;
  std::setvbuf(file.get(), buffer, _IOFBF, sizeof buffer);
  std::string line;
  for (int c; (c = std::getc(file.get())) != EOF || !line.empty();) {
    if (c != '\n' && c != EOF) {
      line += static_cast<char>(c);
      continue;
    }
    if (const std::optional<bool> three = says_three_dimensions(line)) return *three;
    line.clear();
  }
  return false;
}

FacetInput read_facet_file(const std::string& path, int threads) {
  LineReader in = LineReader::open(path, threads);
  FacetInput out;
  out.source_name = path;
  read_node_section(in, out);
  read_facets(in, out, ends_with(path, ".smesh"));
  return out;
}

}  // namespace deltri
