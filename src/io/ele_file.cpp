#include "io/ele_file.h"

#include <algorithm>
#include <climits>

#include "io/line_reader.h"
#include "io/output_numbering.h"

namespace deltri {
namespace {

constexpr long long kMaxTriangles = 0xFFFFFFF0LL;
constexpr long long kMaxAttributes = 1 << 20;

void read_ele_header(LineReader& in, EleData& ele, std::uint32_t& count) {
  if (!in.next_line()) in.fail("unexpected end of file: the triangle header is missing");
  count = static_cast<std::uint32_t>(in.read_int({"triangle header", -1, "number of triangles"}, 0, kMaxTriangles));
  if (in.has_field()) {
    const long long nodes = in.read_int({"triangle header", -1, "nodes per triangle"}, LLONG_MIN, LLONG_MAX);
    if (nodes != 3 && nodes != 6) in.fail("triangle header: nodes per triangle must be 3 or 6, not " + std::to_string(nodes));
    ele.nodes_per_triangle = static_cast<std::uint32_t>(nodes);
  }
  if (in.has_field())
    ele.num_attributes = static_cast<int>(in.read_int({"triangle header", -1, "number of attributes"}, 0, kMaxAttributes));
}

void read_triangle(LineReader& in, EleData& ele, long long number, int first_index, std::uint32_t vertex_count) {
  in.read_int({"triangle", number, "index"}, LLONG_MIN, LLONG_MAX);
  const long long last = first_index + static_cast<long long>(vertex_count) - 1;
  for (std::uint32_t k = 0; k < ele.nodes_per_triangle; ++k) {
    const long long v = in.read_int({"triangle", number, "node", static_cast<int>(k) + 1}, LLONG_MIN, LLONG_MAX);
    if (v < first_index || v > last)
      in.fail("triangle " + std::to_string(number) + ": node " + std::to_string(k + 1) + " is " + std::to_string(v) +
              ", not a vertex (vertices are numbered " + std::to_string(first_index) + " to " + std::to_string(last) + ")");
    ele.corners.push_back(static_cast<std::uint32_t>(v - first_index));
  }
  for (int a = 0; a < ele.num_attributes; ++a) ele.attributes.push_back(in.read_double({"triangle", number, "attribute", a + 1}));
}

// `Out` is a TextWriter::Line (room for the whole line checked once) or, for lines with more
// fields than a Line may hold, the TextWriter itself.
template <class Out>
void write_triangle_line(Out& out, const Mesh& mesh, const VertexNumbering& number, const std::vector<VertexId>* mid,
                         TriangleId t, long long index) {
  const int na = mesh.num_triangle_attributes;
  out.integer(index);
  for (EdgeRef e : edges_of(t)) out.next_integer(number(mesh.corner[e]));
  if (mid)
    for (EdgeRef e : edges_of(t)) out.next_integer(number((*mid)[e]));
  for (int a = 0; a < na; ++a) out.next_real(mesh.triangle_attributes[static_cast<std::size_t>(t) * na + a]);
  out.end_line();
}

}  // namespace

EleData read_ele_file(const std::string& path, int first_index, std::uint32_t vertex_count, int threads) {
  LineReader in = LineReader::open(path, threads);
  EleData ele;
  std::uint32_t count = 0;
  read_ele_header(in, ele, count);
  ele.corners.reserve(std::min<std::size_t>(count, in.bytes_left() / 8 + 1) * ele.nodes_per_triangle);
  for (std::uint32_t k = 0; k < count; ++k) {
    const long long number = first_index + static_cast<long long>(k);
    if (!in.next_line()) in.fail("unexpected end of file: " + std::to_string(count) + " triangles announced, " + std::to_string(k) + " found");
    read_triangle(in, ele, number, first_index, vertex_count);
  }
  return ele;
}

namespace {

// The output index of the first live triangle of each range of TextWriter::kItemsPerRange slots,
// so that every range can be formatted on its own.
std::vector<long long> first_index_of_ranges(const Mesh& mesh, long long first_index) {
  const std::size_t per = TextWriter::kItemsPerRange;
  std::vector<long long> first((mesh.triangle_slots() + per - 1) / per);
  long long index = first_index;
  for (std::size_t r = 0; r < first.size(); ++r) {
    first[r] = index;
    const std::size_t end = std::min<std::size_t>(mesh.triangle_slots(), (r + 1) * per);
    for (TriangleId t{static_cast<std::uint32_t>(r * per)}; t < end; ++t) index += mesh.is_live(t);
  }
  return first;
}

}  // namespace

void write_ele_file(ByteSink& sink, const Mesh& mesh, const EleWriteOptions& options) {
  const VertexNumbering number{options.numbering, options.first_index};
  const int na = mesh.num_triangle_attributes;
  const std::vector<VertexId>* mid = options.midpoints;
  sink.expect(static_cast<std::size_t>(mesh.live_triangles()) * (mid ? 60 : 36) + 24 * static_cast<std::size_t>(na));
  TextWriter out(sink);
  out.integer(mesh.live_triangles());
  out.next_integer(mid ? 6 : 3);
  out.next_integer(na);
  out.end_line();
  const std::vector<long long> first = first_index_of_ranges(mesh, options.first_index);
  const std::size_t fields = (mid ? 7 : 4) + static_cast<std::size_t>(na);
  out.write_lines(mesh.triangle_slots(), [&](TextWriter& part, std::size_t begin, std::size_t end) {
    long long index = first[begin / TextWriter::kItemsPerRange];
    for (TriangleId t{static_cast<std::uint32_t>(begin)}; t < end; ++t) {
      if (!mesh.is_live(t)) continue;
      if (fields <= TextWriter::kMaxLineFields) {
        TextWriter::Line line = part.line(fields);
        write_triangle_line(line, mesh, number, mid, t, index++);
      } else {
        write_triangle_line(part, mesh, number, mid, t, index++);
      }
    }
  });
  out.finish();
}

void write_ele_file(std::string& out, const Mesh& mesh, const EleWriteOptions& options) {
  StringSink sink(out);
  write_ele_file(sink, mesh, options);
}

}  // namespace deltri
