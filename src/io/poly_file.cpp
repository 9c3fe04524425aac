#include "io/poly_file.h"

#include <algorithm>
#include <climits>

#include "io/line_reader.h"
#include "io/node_file.h"
#include "io/output_numbering.h"
#include "util/errors.h"

namespace deltri {
namespace {

constexpr long long kMaxItems = 0xFFFFFFF0LL;

std::string node_path_for(const std::string& poly_path) {
  const std::string ext = ".poly";
  if (poly_path.size() > ext.size() && poly_path.ends_with(ext))
    return poly_path.substr(0, poly_path.size() - ext.size()) + ".node";
  return poly_path + ".node";
}

void load_separate_vertices(const LineReader& in, Pslg& out) {
  if (in.name() == kStandardInputName) in.fail("the vertices are in a separate .node file, which standard input cannot name");
  out = read_node_file(node_path_for(in.name()), in.threads());
}

// Reads a section header's count; the section must be there.
std::uint32_t read_count(LineReader& in, const char* section) {
  if (!in.next_line()) in.fail(std::string("unexpected end of file: the ") + section + " is missing");
  return static_cast<std::uint32_t>(in.read_int({section, -1, "count"}, 0, kMaxItems));
}

// What a lenient reading of the segment lines assumed, for the warnings.
struct SegmentLeniency {
  std::size_t dropped = 0;
  long dropped_line = 0;
  std::string dropped_text;
  std::size_t missing_markers = 0;
  long missing_marker_line = 0;
};

// The 0-based vertex an endpoint names, or kNone (with `problem` set) when it names none.
std::uint32_t read_endpoint(LineReader& in, const Pslg& pslg, long long number, const char* which, std::string& problem) {
  const long long first = pslg.first_index;
  const long long last = first + static_cast<long long>(pslg.points.size()) - 1;
  const long long v = in.read_int({"segment", number, which}, LLONG_MIN, LLONG_MAX);
  if (v < first || v > last) {
    if (problem.empty())
      problem = "segment " + std::to_string(number) + ": " + which + " " + std::to_string(v) +
                " is not a vertex (vertices are numbered " + std::to_string(first) + " to " + std::to_string(last) + ")";
    return kNone;
  }
  return static_cast<std::uint32_t>(v - first);
}

// As in Triangle, a segment naming no vertex is dropped and a missing trailing marker is 0; both
// are plain in meaning and warned about.
void read_segment(LineReader& in, Pslg& pslg, long long number, SegmentLeniency& lenient) {
  in.read_int({"segment", number, "index"}, LLONG_MIN, LLONG_MAX);
  Pslg::Segment s;
  std::string problem;
  s.a = read_endpoint(in, pslg, number, "first endpoint", problem);
  s.b = read_endpoint(in, pslg, number, "second endpoint", problem);
  // A zero-length segment is legal input: the constrained Delaunay stage ignores it and says so.
  if (pslg.has_segment_markers) {
    if (in.has_field()) {
      s.marker = static_cast<int>(in.read_int({"segment", number, "boundary marker"}, INT_MIN, INT_MAX));
    } else if (lenient.missing_markers++ == 0) {
      lenient.missing_marker_line = in.line();
    }
  }
  if (problem.empty()) {
    pslg.segments.push_back(s);
  } else if (lenient.dropped++ == 0) {
    lenient.dropped_line = in.line();
    lenient.dropped_text = problem;
  }
}

void note_leniency(const LineReader& in, Pslg& pslg, const SegmentLeniency& l) {
  const auto at = [&in](long line) { return in.name() + ":" + std::to_string(line) + ": "; };
  if (l.dropped)
    pslg.read_warnings.push_back(at(l.dropped_line) + l.dropped_text + ": " + std::to_string(l.dropped) +
                                 (l.dropped == 1 ? " segment" : " segments") +
                                 " naming no vertex dropped, as in Triangle");
  if (l.missing_markers)
    pslg.read_warnings.push_back(at(l.missing_marker_line) + std::to_string(l.missing_markers) +
                                 (l.missing_markers == 1 ? " segment has" : " segments have") +
                                 " no boundary marker: 0 assumed, as in Triangle");
}

void read_segments(LineReader& in, Pslg& pslg) {
  const std::uint32_t count = read_count(in, "segment header");
  if (in.has_field()) pslg.has_segment_markers = in.read_int({"segment header", -1, "number of boundary markers"}, 0, INT_MAX) != 0;  // any non-zero count means "markers present", as Triangle reads it
  if (count > 0) require_regular_numbering(pslg, "the segments");
  pslg.segments.reserve(std::min<std::size_t>(count, in.bytes_left() / 6 + 1));
  SegmentLeniency lenient;
  for (std::uint32_t k = 0; k < count; ++k) {
    const long long number = pslg.first_index + static_cast<long long>(k);
    if (!in.next_line()) in.fail("unexpected end of file: " + std::to_string(count) + " segments announced, " + std::to_string(k) + " found");
    read_segment(in, pslg, number, lenient);
  }
  note_leniency(in, pslg, lenient);
}

void read_holes(LineReader& in, Pslg& pslg) {
  const std::uint32_t count = read_count(in, "hole header");
  for (std::uint32_t k = 0; k < count; ++k) {
    const long long number = pslg.first_index + static_cast<long long>(k);
    if (!in.next_line()) in.fail("unexpected end of file: " + std::to_string(count) + " holes announced, " + std::to_string(k) + " found");
    in.read_int({"hole", number, "index"}, LLONG_MIN, LLONG_MAX);
    Point p;
    p.x = in.read_double({"hole", number, "x coordinate"});
    p.y = in.read_double({"hole", number, "y coordinate"});
    pslg.holes.push_back(p);
  }
}

void read_regions(LineReader& in, Pslg& pslg) {
  if (!in.next_line()) return;  // the region section is optional
  const std::uint32_t count = static_cast<std::uint32_t>(in.read_int({"region header", -1, "count"}, 0, kMaxItems));
  for (std::uint32_t k = 0; k < count; ++k) {
    const long long number = pslg.first_index + static_cast<long long>(k);
    if (!in.next_line()) in.fail("unexpected end of file: " + std::to_string(count) + " regions announced, " + std::to_string(k) + " found");
    in.read_int({"region", number, "index"}, LLONG_MIN, LLONG_MAX);
    Pslg::Region r;
    r.at.x = in.read_double({"region", number, "x coordinate"});
    r.at.y = in.read_double({"region", number, "y coordinate"});
    r.attribute = in.read_double({"region", number, "attribute"});
    r.max_area = in.has_field() ? in.read_double({"region", number, "maximum area"}) : r.attribute;
    pslg.regions.push_back(r);
  }
}

}  // namespace

LiveSubsegments find_live_subsegments(const Mesh& mesh) {
  LiveSubsegments live;
  if (!mesh.has_subsegments()) return live;
  live.edge.assign(mesh.subsegments.size(), kNone);
  live.boundary.assign(mesh.subsegments.size(), false);
  mesh.subseg.for_each([&](EdgeRef e, SubsegmentId s) {  // slot order
    if (!mesh.is_live(triangle_of(e)) || s >= live.edge.size()) return;
    if (live.edge[s] == kNone) {
      live.edge[s] = e;
      ++live.count;
    }
    if (mesh.link[e] == kNone) live.boundary[s] = true;
  });
  return live;
}

namespace {

void write_segments(TextWriter& out, const Mesh& mesh, const PolyWriteOptions& options) {
  const LiveSubsegments live = find_live_subsegments(mesh);
  const VertexNumbering number{options.numbering, options.first_index};
  out.integer(live.count);
  out.next_integer(options.markers ? 1 : 0);
  out.end_line();
  long long index = options.first_index;
  for (SubsegmentId s{0}; s < live.edge.size(); ++s) {
    const EdgeRef e = live.edge[s];
    if (e == kNone) continue;
    out.integer(index++);
    out.next_integer(number(mesh.org(e)));
    out.next_integer(number(mesh.dest(e)));
    const int marker = mesh.subsegments[s].marker;
    if (options.markers) out.next_integer(marker != 0 ? marker : live.boundary[s] ? 1 : 0);
    out.end_line();
  }
}

void write_holes(TextWriter& out, const std::vector<Point>& holes, int first_index) {
  out.integer(static_cast<long long>(holes.size()));
  out.end_line();
  for (std::size_t k = 0; k < holes.size(); ++k) {
    out.integer(first_index + static_cast<long long>(k));
    out.next_real(holes[k].x);
    out.next_real(holes[k].y);
    out.end_line();
  }
}

void write_regions(TextWriter& out, const std::vector<Pslg::Region>& regions, int first_index) {
  if (regions.empty()) return;
  out.integer(static_cast<long long>(regions.size()));
  out.end_line();
  for (std::size_t k = 0; k < regions.size(); ++k) {
    out.integer(first_index + static_cast<long long>(k));
    out.next_real(regions[k].at.x);
    out.next_real(regions[k].at.y);
    out.next_real(regions[k].attribute);
    out.next_real(regions[k].max_area);
    out.end_line();
  }
}

}  // namespace

Pslg read_poly_file(const std::string& path, int threads) {
  LineReader in = LineReader::open(path, threads);
  Pslg pslg;
  if (read_node_section(in, pslg, true) == 0) load_separate_vertices(in, pslg);
  read_segments(in, pslg);
  read_holes(in, pslg);
  read_regions(in, pslg);
  pslg.has_segment_section = true;
  return pslg;
}

void write_poly_file(ByteSink& sink, const Mesh& mesh, const PolyWriteOptions& options,
                     const std::vector<Point>& holes, const std::vector<Pslg::Region>& regions) {
  TextWriter out(sink);
  if (options.with_vertices) {
    write_node_section(out, mesh, {options.first_index, options.markers, options.numbering});
  } else {
    out.text("0 2 ");
    out.integer(mesh.num_attributes);
    out.next_integer(options.markers ? 1 : 0);
    out.end_line();
  }
  write_segments(out, mesh, options);
  write_holes(out, holes, options.first_index);
  write_regions(out, regions, options.first_index);
  out.finish();
}

void write_poly_file(std::string& out, const Mesh& mesh, const PolyWriteOptions& options,
                     const std::vector<Point>& holes, const std::vector<Pslg::Region>& regions) {
  StringSink sink(out);
  write_poly_file(sink, mesh, options, holes, regions);
}

}  // namespace deltri
