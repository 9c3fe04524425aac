#include "io/node_file.h"

#include <algorithm>
#include <climits>
#include <exception>

#include "io/output_numbering.h"
#include "util/errors.h"
#include "util/run_both.h"

namespace deltri {
namespace {

constexpr long long kMaxVertices = 0xFFFFFFF0LL;  // leaves room for the mesh's reserved ids
constexpr long long kMaxAttributes = 1 << 20;
// Below these a second parsing thread costs more than it saves.
constexpr std::uint32_t kParallelVertices = 100000;
constexpr std::size_t kParallelBytes = std::size_t{2} << 20;
// Index conventions for parse_vertices: the first line must say 0 or 1 / may say anything.
constexpr long long kFirstFromFile = -1;
constexpr long long kFirstAny = -2;

struct NodeHeader {
  std::uint32_t count = 0;
  int attributes = 0;
  bool markers = false;
};

NodeHeader read_node_header(LineReader& in, bool allow_empty) {
  if (!in.next_line()) in.fail("unexpected end of file: the node header is missing");
  NodeHeader h;
  h.count = static_cast<std::uint32_t>(in.read_int({"node header", -1, "number of vertices"}, 0, kMaxVertices));
  if (h.count < 3 && !(allow_empty && h.count == 0))
    in.fail("a triangulation needs at least 3 vertices, the header says " + std::to_string(h.count));
  if (in.has_field() && in.read_int({"node header", -1, "dimension"}, LLONG_MIN, LLONG_MAX) != 2)
    in.fail("node header: dimension must be 2");
  if (in.has_field())
    h.attributes = static_cast<int>(in.read_int({"node header", -1, "number of attributes"}, 0, kMaxAttributes));
  if (in.has_field()) h.markers = in.read_int({"node header", -1, "number of boundary markers"}, 0, INT_MAX) != 0;  // non-zero: markers present
  return h;
}

// What a lenient (serial) reading of the vertex lines met and assumed, turned into warnings once
// the list is read. The parallel halves read strictly and leave anything odd to the serial reader.
struct Leniency {
  long irregular_line = 0;  // first vertex line whose index is out of sequence
  std::string irregular_text;
  std::size_t irregular = 0;
  long odd_first_line = 0;  // a first index other than 0 or 1
  long long odd_first = 0;
  long missing_marker_line = 0;
  std::size_t missing_markers = 0;
};

// The first vertex line decides the numbering (or, for the second half of a split list, just
// tells where it starts); every later one must follow it. Read leniently, as Triangle reads them,
// any indices are accepted and noted; the vertices are numbered by their place in the file.
void read_vertex_index(LineReader& in, long long& first, std::uint32_t k, Leniency* lenient) {
  if (k == 0 && first < 0) {
    const long long index = in.read_int({"first vertex", -1, "index"}, LLONG_MIN, LLONG_MAX);
    if (first == kFirstFromFile && index != 0 && index != 1) {
      if (!lenient) in.fail("first vertex: index must be 0 or 1, not " + std::to_string(index));
      lenient->odd_first_line = in.line();
      lenient->odd_first = index;
    }
    first = index;
    return;
  }
  const long long expected = first + static_cast<long long>(k);
  const long long index = in.read_int({"vertex", expected, "index"}, LLONG_MIN, LLONG_MAX);
  if (index == expected) return;
  const std::string problem = "vertex index " + std::to_string(index) + " is out of sequence: expected " + std::to_string(expected);
  if (!lenient) in.fail(problem);
  if (lenient->irregular++ == 0) {
    lenient->irregular_line = in.line();
    lenient->irregular_text = problem;
  }
}

// The point is stored last, so that after an error out.points counts the complete vertices (the
// parallel reader relies on that; attributes and markers may then hold a few extra entries).
// A missing trailing marker is 0 when read leniently (Triangle's default): with every attribute
// present, nothing else can be meant.
void read_vertex_fields(LineReader& in, Pslg& out, const NodeHeader& h, long long number, Leniency* lenient) {
  Point p;
  p.x = in.read_double({"vertex", number, "x coordinate"});
  p.y = in.read_double({"vertex", number, "y coordinate"});
  for (int a = 0; a < h.attributes; ++a) out.attributes.push_back(in.read_double({"vertex", number, "attribute", a + 1}));
  if (h.markers) {
    if (lenient && !in.has_field()) {
      if (lenient->missing_markers++ == 0) lenient->missing_marker_line = in.line();
      out.markers.push_back(0);
    } else {
      out.markers.push_back(static_cast<int>(in.read_int({"vertex", number, "boundary marker"}, INT_MIN, INT_MAX)));
    }
  }
  out.points.push_back(p);
}

// Reads vertex lines into `out` until `limit` are stored or the text ends; returns how many.
// `after` is left just behind the last vertex read.
std::uint32_t parse_vertices(LineReader& in, Pslg& out, const NodeHeader& h, std::uint32_t limit, long long& first,
                             LineReader::Mark& after, Leniency* lenient = nullptr) {
  std::uint32_t k = 0;
  for (; k < limit && in.next_line(); ++k) {
    read_vertex_index(in, first, k, lenient);
    read_vertex_fields(in, out, h, first + static_cast<long long>(k), lenient);
    after = in.mark();
  }
  return k;
}

// A header may promise billions of vertices; reserve no more than the remaining text can hold
// ("i x y\n" is at least six bytes).
void reserve_vertices(std::size_t bytes, Pslg& out, const NodeHeader& h) {
  const std::size_t n = std::min<std::size_t>(h.count, bytes / 6 + 1);
  out.points.reserve(n);
  out.attributes.reserve(n * static_cast<std::size_t>(std::min(h.attributes, 64)));
  if (h.markers) out.markers.reserve(n);
}

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void note_leniency(const LineReader& in, Pslg& out, const Leniency& l) {
  const auto at = [&in](long line) { return in.name() + ":" + std::to_string(line) + ": "; };
  if (l.odd_first_line)
    out.read_warnings.push_back(at(l.odd_first_line) + "the first vertex is numbered " + std::to_string(l.odd_first) +
                                ", not 0 or 1: the output is numbered from 1 (0 with -z), as in Triangle");
  if (l.irregular) {
    out.irregular_index_line = l.irregular_line;
    out.irregular_index_text = l.irregular_text;
    out.read_warnings.push_back(at(l.irregular_line) + l.irregular_text + " (" +
                                plural(l.irregular, "vertex line", "vertex lines") +
                                " out of sequence): vertices are numbered by their order in the file, as in Triangle");
  }
  if (l.missing_markers)
    out.read_warnings.push_back(at(l.missing_marker_line) + plural(l.missing_markers, "vertex has", "vertices have") +
                                " no boundary marker: 0 assumed, as in Triangle");
}

void read_vertices_serially(LineReader& in, Pslg& out, const NodeHeader& h) {
  long long first = kFirstFromFile;
  LineReader::Mark after = in.mark();
  Leniency lenient;
  const std::uint32_t found = parse_vertices(in, out, h, h.count, first, after, &lenient);
  if (found < h.count)
    in.fail("unexpected end of file: " + std::to_string(h.count) + " vertices announced, " + std::to_string(found) +
            " found");
  out.numbered_by_file = first == 0 || first == 1;
  out.first_index = out.numbered_by_file ? static_cast<int>(first) : 1;
  if (!out.numbered_by_file) {
    out.irregular_index_line = lenient.odd_first_line;
    out.irregular_index_text = "first vertex: index must be 0 or 1, not " + std::to_string(first);
  }
  note_leniency(in, out, lenient);
}

// One half of a split vertex list. Errors end the half quietly: whether they matter depends on
// where the other half ends, and a serial re-read reports them exactly as usual.
struct VertexRun {
  Pslg* part = nullptr;  // where the half's vertices go
  long long first = kFirstAny;
  std::uint32_t count = 0;
  LineReader::Mark after{};
  long lines = 0;  // lines seen, when the half ran to its end
  std::exception_ptr fatal;
};

// The half works on copies on its own thread's stack and writes them back once at the end. The
// two runs (and the second half's vertices) sit side by side on the first thread's stack: written
// there at every line, they shared cache lines between the threads, and depending on the stack's
// random alignment the parse took twice as long in about half the runs.
void run_half(LineReader in, const NodeHeader& h, VertexRun& result) {
  VertexRun run = result;
  Pslg part = std::move(*result.part);
  run.after = in.mark();
  const std::size_t before = part.points.size();
  try {
    run.count = parse_vertices(in, part, h, h.count, run.first, run.after);
    run.lines = in.line();
  } catch (const InputError&) {
    run.count = static_cast<std::uint32_t>(part.points.size() - before);
  } catch (...) {
    run.fatal = std::current_exception();
  }
  *result.part = std::move(part);
  result = run;
}

void append(Pslg& out, const Pslg& part, std::uint32_t count, const NodeHeader& h) {
  out.points.insert(out.points.end(), part.points.begin(), part.points.begin() + count);
  out.attributes.insert(out.attributes.end(), part.attributes.begin(),
                        part.attributes.begin() + static_cast<std::ptrdiff_t>(count) * h.attributes);
  if (h.markers) out.markers.insert(out.markers.end(), part.markers.begin(), part.markers.begin() + count);
}

// Cuts `out` back to its first `count` vertices.
void truncate(Pslg& out, std::uint32_t count, const NodeHeader& h) {
  out.points.resize(count);
  out.attributes.resize(static_cast<std::size_t>(count) * h.attributes);
  if (h.markers) out.markers.resize(count);
}

// Puts `in` behind the last vertex, which lies `needed` vertex lines into the second half.
void resume_after(LineReader& in, const LineReader& tail, const VertexRun& first, const VertexRun& second,
                  std::uint32_t needed) {
  if (second.count == needed) {
    in.reset({second.after.pos, first.lines + second.after.line, true});
    return;
  }
  in = tail;
  in.reset({tail.mark().pos, first.lines, false});
  for (std::uint32_t k = 0; k < needed; ++k) in.next_line();
}

// Parses the two halves of the text at once; false when the serial reader must decide (an error,
// or an odd split), in which case `out` is left empty. The first half goes straight into `out`
// and only the second is copied, so at most one and a half copies of the vertices exist.
bool read_vertices_in_parallel(LineReader& in, Pslg& out, const NodeHeader& h) {
  const LineReader tail = in.tail_after(in.bytes_left() / 2);
  LineReader head = in;
  head.end_at(tail);
  // Reserving costs address space only; pages are committed as vertices arrive. The second half's
  // vectors are deliberately left to grow: freeing one large reserved block made glibc serve the
  // triangulation's later allocations from its heap, which raised the peak memory by a fifth.
  reserve_vertices(in.bytes_left(), out, h);
  Pslg second_part;
  VertexRun first, second;
  first.part = &out;
  first.first = kFirstFromFile;
  second.part = &second_part;
  run_both([&] { run_half(tail, h, second); }, [&] { run_half(head, h, first); });
  if (first.fatal) std::rethrow_exception(first.fatal);
  if (second.fatal) std::rethrow_exception(second.fatal);
  const bool first_ran_out = first.count < h.count && first.lines > 0;
  const std::uint32_t needed = h.count - first.count;
  if (first.count == 0 || (needed > 0 && (!first_ran_out || second.count < needed ||
                                          second.first != first.first + static_cast<long long>(first.count)))) {
    truncate(out, 0, h);
    return false;
  }
  out.first_index = static_cast<int>(first.first);
  if (needed == 0) {
    truncate(out, h.count, h);  // the first half may hold lines beyond the announced vertices
    in.reset(first.after);
    return true;
  }
  append(out, second_part, needed, h);
  resume_after(in, tail, first, second, needed);
  return true;
}

}  // namespace

std::uint32_t read_node_section(LineReader& in, Pslg& out, bool allow_empty) {
  const NodeHeader h = read_node_header(in, allow_empty);
  if (h.count == 0) return 0;
  out.points.clear();
  out.attributes.clear();
  out.markers.clear();
  out.num_attributes = h.attributes;
  out.has_markers = h.markers;
  out.source_name = in.name();
  if (in.threads() >= 2 && h.count >= kParallelVertices && in.bytes_left() >= kParallelBytes &&
      read_vertices_in_parallel(in, out, h))
    return h.count;
  reserve_vertices(in.bytes_left(), out, h);
  read_vertices_serially(in, out, h);
  return h.count;
}

namespace {

// Whether the next data line is a segment header: one or two non-negative integers and nothing
// else. A .node has nothing after its vertices (Triangle ignores whatever is there), so such a line
// means a .poly.
bool segment_header_follows(LineReader& in) {
  if (!in.next_line()) return false;
  try {
    in.read_int({"segment header", -1, "number of segments"}, 0, LLONG_MAX);
    if (in.has_field()) in.read_int({"segment header", -1, "number of boundary markers"}, 0, LLONG_MAX);
    return !in.has_field();
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

void require_regular_numbering(const Pslg& pslg, const std::string& referrer) {
  if (pslg.irregular_index_line == 0) return;
  throw InputError(pslg.source_name, pslg.irregular_index_line,
                   pslg.irregular_index_text + " (" + referrer +
                       " name vertices by number, so which vertex each number means is ambiguous)");
}

Pslg read_node_file(const std::string& path, int threads) {
  LineReader in = LineReader::open(path, threads);
  Pslg pslg;
  read_node_section(in, pslg);
  // Standard input has no extension to say what it is: a .poly piped in without -p would be meshed
  // as its vertices' convex hull, its segments dropped without a word.
  if (path == "-" && segment_header_follows(in)) in.fail("this looks like a .poly (segment section); use -p");
  return pslg;
}

namespace {

// `Out` is a TextWriter::Line (room for the whole line checked once) or, for lines with more
// fields than a Line may hold, the TextWriter itself.
template <class Out>
void write_vertex_line(Out& out, const Mesh& mesh, const NodeWriteOptions& options, VertexId v, long long number) {
  const int na = mesh.num_attributes;
  out.integer(number);
  out.next_real(mesh.points[v].x);
  out.next_real(mesh.points[v].y);
  for (int a = 0; a < na; ++a) out.next_real(mesh.attributes[static_cast<std::size_t>(v) * na + a]);
  if (options.markers) out.next_integer(mesh.marker.empty() ? 0 : mesh.marker[v]);
  out.end_line();
}

// Vertices [begin, end): each line's number comes from the vertex alone, so any range can be
// formatted on its own.
void write_vertex_range(TextWriter& out, const Mesh& mesh, const NodeWriteOptions& options, std::size_t begin,
                        std::size_t end) {
  const VertexNumbering number{options.numbering, options.first_index};
  const std::size_t fields = 4 + static_cast<std::size_t>(mesh.num_attributes);
  for (VertexId v{static_cast<std::uint32_t>(begin)}; v < end; ++v) {
    if (!number.written(v)) continue;
    if (fields <= TextWriter::kMaxLineFields) {
      TextWriter::Line line = out.line(fields);
      write_vertex_line(line, mesh, options, v, number(v));
    } else {
      write_vertex_line(out, mesh, options, v, number(v));
    }
  }
}

void write_vertex_lines(TextWriter& out, const Mesh& mesh, const NodeWriteOptions& options) {
  out.write_lines(mesh.vertex_count(), [&mesh, &options](TextWriter& part, std::size_t begin, std::size_t end) {
    write_vertex_range(part, mesh, options, begin, end);
  });
}

std::uint32_t written_vertex_count(const Mesh& mesh, const NodeWriteOptions& options) {
  if (!options.numbering) return mesh.vertex_count();
  std::uint32_t count = 0;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) count += (*options.numbering)[v] != kNone;
  return count;
}

}  // namespace

void write_node_section(TextWriter& out, const Mesh& mesh, const NodeWriteOptions& options) {
  out.integer(written_vertex_count(mesh, options));
  out.next_integer(2);
  out.next_integer(mesh.num_attributes);
  out.next_integer(options.markers ? 1 : 0);
  out.end_line();
  write_vertex_lines(out, mesh, options);
}

void write_node_file(ByteSink& sink, const Mesh& mesh, const NodeWriteOptions& options) {
  sink.expect(static_cast<std::size_t>(mesh.vertex_count()) * (48 + 24 * static_cast<std::size_t>(mesh.num_attributes)));
  TextWriter out(sink);
  write_node_section(out, mesh, options);
  out.finish();
}

void write_node_file(std::string& out, const Mesh& mesh, const NodeWriteOptions& options) {
  StringSink sink(out);
  write_node_file(sink, mesh, options);
}

}  // namespace deltri
