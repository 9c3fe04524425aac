// --smooth (src/improve/smooth.h) on many small random domains, each meshed twice through the
// pipeline, without and with the pass. Everything is judged from the two meshes alone, with the
// test's own measures: long double angles by the law of cosines, exact orient2d and incircle from
// the predicates, areas from coordinates. Nothing here calls the pass's own checks.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "pipeline/pipeline.h"
#include "options/switches.h"
#include "geometry/predicates.h"
#include "harness/check.h"
#include "quality/check_mesh.h"

namespace {

using namespace deltri;

// A fixed generator, so that every run tests the same domains.
struct Lcg {
  std::uint64_t s;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) * 0x1p-53;
  }
};

// A star-shaped polygon of 5 to 12 corners around the origin at radii 0.4 to 1, a point or two
// inside (some runs), and with vertex markers and one attribute, so that both can be compared.
Pslg random_domain(std::uint64_t seed) {
  Lcg r{seed * 2654435761u + 1};
  Pslg p;
  const int corners = 5 + static_cast<int>(r.next() * 8);
  std::vector<double> turns;
  for (int i = 0; i < corners; ++i) turns.push_back(r.next());
  std::sort(turns.begin(), turns.end());
  p.num_attributes = 1;
  p.has_markers = true;
  for (int i = 0; i < corners; ++i) {
    const double a = 2 * std::numbers::pi * (turns[i] + i) / corners, radius = 0.4 + 0.6 * r.next();
    p.points.push_back({radius * std::cos(a), radius * std::sin(a)});
    p.attributes.push_back(r.next());
    p.markers.push_back(i + 1);
    p.segments.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>((i + 1) % corners), 1});
  }
  if (seed % 3 == 0) {
    p.points.push_back({0.05 * r.next(), 0.05 * r.next()});
    p.attributes.push_back(0.5);
    p.markers.push_back(0);
  }
  p.has_segment_section = true;
  return p;
}

Mesh meshed(std::uint64_t seed, const std::vector<std::string>& words) {
  std::vector<const char*> argv = {"deltri"};
  for (const std::string& w : words) argv.push_back(w.c_str());
  argv.push_back("input.poly");
  const Switches sw = parse_switches(static_cast<int>(argv.size()), argv.data());
  Pslg pslg = random_domain(seed);
  PipelineSource source;
  source.name = "input.poly";
  source.is_poly = true;
  RunReport report;
  PipelineResult result = run_pipeline(pslg, source, sw, report);
  REQUIRE(!result.check_failed);
  return std::move(result.mesh);
}

long double angle_at(const Point& a, const Point& b, const Point& c) {
  const long double ab = std::hypot(static_cast<long double>(b.x) - a.x, static_cast<long double>(b.y) - a.y);
  const long double ac = std::hypot(static_cast<long double>(c.x) - a.x, static_cast<long double>(c.y) - a.y);
  const long double bc = std::hypot(static_cast<long double>(c.x) - b.x, static_cast<long double>(c.y) - b.y);
  const long double cosine = std::clamp((ab * ab + ac * ac - bc * bc) / (2 * ab * ac), -1.0L, 1.0L);
  return std::acos(cosine) * 180.0L / std::numbers::pi_v<long double>;
}

long double smallest_angle(const Mesh& m, TriangleId t) {
  const auto [a, b, c] = m.corner_points(t);
  return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
}

double area(const Mesh& m, TriangleId t) {
  const auto [a, b, c] = m.corner_points(t);
  return 0.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

struct Quality {
  long double least = 180.0L, sum = 0.0L, largest_area = 0.0L;
  std::size_t triangles = 0;
};

Quality quality(const Mesh& m) {
  Quality q;
  for (TriangleId t{0}; t < m.triangle_slots(); ++t) {
    if (!m.is_live(t)) continue;
    const long double a = smallest_angle(m, t);
    q.least = std::min(q.least, a);
    q.sum += a;
    q.largest_area = std::max<long double>(q.largest_area, area(m, t));
    ++q.triangles;
  }
  return q;
}

// Every triangle counter-clockwise and every edge without a subsegment locally Delaunay, by the
// exact predicates: with the first, the second makes the mesh constrained Delaunay (Lee and Lin).
bool constrained_delaunay(const Mesh& m) {
  Predicates pred;
  for (EdgeRef e{0}; e < m.corner.size(); ++e) {
    if (m.corner[e] == kNone) continue;
    if (!(pred.orient2d(m.point(m.org(e)), m.point(m.dest(e)), m.point(m.apex(e))) > 0.0)) return false;
    const EdgeRef f = m.link[e];
    if (f == kNone || (m.has_subsegments() && m.subseg.has(e))) continue;
    if (pred.incircle(m.point(m.org(e)), m.point(m.dest(e)), m.point(m.apex(e)), m.point(m.apex(f))) > 0.0) return false;
  }
  return true;
}

// Only free vertices moved; the triangles, kinds, markers and attributes are the same.
bool only_free_vertices_moved(const Mesh& before, const Mesh& after) {
  if (!(before.corner == after.corner) || before.kind != after.kind || before.marker != after.marker ||
      before.attributes != after.attributes || before.vertex_count() != after.vertex_count())
    return false;
  for (VertexId v{0}; v < before.vertex_count(); ++v)
    if (before.kind[v] != VertexKind::Free && !(before.points[v] == after.points[v])) return false;
  return true;
}

void compare(const std::vector<std::string>& plain, double angle, double max_area, long double& gain, int& moved) {
  for (std::uint64_t seed = 0; seed < 150; ++seed) {
    const Mesh before = meshed(seed, plain);
    std::vector<std::string> with = plain;
    with.push_back(seed % 2 ? "--smooth" : "--smooth=5");
    const Mesh after = meshed(seed, with);
    const Quality q0 = quality(before), q1 = quality(after);
    CHECK(only_free_vertices_moved(before, after));
    CHECK(q1.least >= q0.least);            // the smallest angle never falls
    CHECK(q1.sum >= q0.sum - 1e-9L);        // nor the mean of the smallest angles
    CHECK(constrained_delaunay(after));
    CHECK(check_mesh(after, CheckOptions{}).ok());
    if (q0.least >= angle) CHECK(q1.least >= angle);
    if (max_area > 0.0 && q0.largest_area <= max_area) CHECK(q1.largest_area <= max_area);
    gain += q1.sum / q1.triangles - q0.sum / q0.triangles;
    for (VertexId v{0}; v < before.vertex_count(); ++v) moved += !(before.points[v] == after.points[v]);
  }
}

TEST(smoothing_never_lowers_the_smallest_angle_and_raises_the_mean) {
  long double gain = 0.0L;
  int moved = 0;
  compare({"-pq30"}, 30.0, 0.0, gain, moved);
  compare({"-pq25a0.01"}, 25.0, 0.01, gain, moved);
  CHECK(moved > 1000);
  // Over the 300 meshes the mean smallest angle rises by half a degree on average at least.
  CHECK(gain / 300 > 0.5L);
}

TEST(smooth_switch_parses) {
  const char* bare[] = {"deltri", "--smooth", "x.poly"};
  CHECK_EQ(parse_switches(3, bare).smooth_rounds, 3);
  const char* seven[] = {"deltri", "--smooth=7", "x.poly"};
  CHECK_EQ(parse_switches(3, seven).smooth_rounds, 7);
  for (const char* bad : {"--smooth=0", "--smooth=x", "--smooth="}) {
    const char* argv[] = {"deltri", bad, "x.poly"};
    bool refused = false;
    try {
      parse_switches(3, argv);
    } catch (const std::exception&) {
      refused = true;
    }
    CHECK(refused);
  }
}

}  // namespace
