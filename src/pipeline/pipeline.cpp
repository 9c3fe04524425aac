#include "pipeline/pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cdt/convex_hull.h"
#include "cdt/corner_lopping.h"
#include "cdt/holes_and_regions.h"
#include "cdt/insert_segments.h"
#include "cdt/markers.h"
#include "cdt/rebuild_mesh.h"
#include "delaunay/triangulate.h"
#include "io/midpoints.h"
#include "util/errors.h"
#include "quality/bound_misses.h"
#include "quality/conformity.h"
#include "quality/check_mesh.h"
#include "refine/area_field.h"
#include "improve/smooth.h"
#include "refine/refine.h"

namespace deltri {
namespace {

// The predicates are exact for every finite double (geometry/exact_integer.h), and segment
// crossings are constructed at a scale where nothing overflows, so triangulating (-p, -c, holes,
// regions) takes any finite coordinates. Refinement's constructions (circumcentres, off-centres,
// split points, lengths and areas) are plain floating point and need their squares and
// products to stay finite and normal: they are safe for vertices within +-2^200 and not all
// below 2^-150 (distinct vertices of magnitude M differ by at least M 2^-52, so M >= 2^-150 keeps
// their differences above 2^-202). An input outside that range is refined scaled by a power of
// two into [1, 2) and the mesh scaled back: exact whenever every input coordinate survives the
// round trip, which is checked; an input that does not (its coordinates span more than the
// doubles' exponent range) is refused.
constexpr double kLargestCoordinate = 0x1p200;   // about 1.6e60
constexpr double kSmallestMagnitude = 0x1p-150;  // about 7.0e-46
// Below it the mesh scaled back would round its new vertices to subnormal numbers with fewer than
// 53 bits across the domain: split points off their segments (-s or refinement at 5e-320).
constexpr double kSmallestScalable = 0x1p-970;   // about 1.0e-292

template <class See>
void each_coordinate(const Pslg& pslg, See see) {
  for (const Point& p : pslg.points) see(p.x), see(p.y);
  for (const Point& p : pslg.holes) see(p.x), see(p.y);
  for (const Pslg::Region& r : pslg.regions) see(r.at.x), see(r.at.y);
}

// The power of two refinement runs the input at (0: as given); throws when it cannot be exact.
int refinement_scale(const Pslg& pslg, const std::string& path) {
  double largest = 0.0, largest_vertex = 0.0;
  for (const Point& p : pslg.points) largest_vertex = std::max({largest_vertex, std::fabs(p.x), std::fabs(p.y)});
  each_coordinate(pslg, [&largest](double c) { largest = std::max(largest, std::fabs(c)); });
  // Only the vertices are ever differenced with each other: a tiny input is tiny in them.
  const bool tiny = largest_vertex > 0.0 && largest_vertex < kSmallestMagnitude;
  if (largest <= kLargestCoordinate && !tiny) return 0;
  if (largest_vertex > 0.0 && largest_vertex < kSmallestScalable) {
    char magnitude[32];
    std::snprintf(magnitude, sizeof magnitude, "%g", largest_vertex);
    throw InputError(path, 0, std::string("every vertex coordinate is below ") + magnitude +
                                  " in magnitude: new vertices there would be subnormal numbers, coarser than the input's "
                                  "features (below 2^-970, about 1e-292); scale the input up");
  }
  const int e = -std::ilogb(tiny ? largest_vertex : largest);
  bool exact = true;
  each_coordinate(pslg, [&exact, e](double c) { exact = exact && std::ldexp(std::ldexp(c, e), -e) == c; });
  if (exact) return e;
  char magnitude[32];
  std::snprintf(magnitude, sizeof magnitude, "%g", tiny ? largest_vertex : largest);
  throw InputError(path, 0, std::string("coordinates of magnitude ") + magnitude +
                                " are outside +-2^200 and 2^-150 (the range refinement computes in), and the input "
                                "cannot be scaled into it exactly: its coordinates span more than the doubles' exponent range");
}

// Segments that cross where every vertex coordinate is below kSmallestScalable: each crossing
// point is rounded to a grid of subnormal numbers, ulps of the input's size, off both segments, and
// the segments are no chains of mesh edges. Refused as refinement there is (refinement_scale).
void refuse_subnormal_crossings(const Mesh& mesh, std::size_t input_vertices, std::size_t crossings,
                                const std::string& path) {
  if (crossings == 0) return;
  double largest = 0.0;
  for (std::size_t v = 0; v < input_vertices && v < mesh.points.size(); ++v)
    largest = std::max({largest, std::fabs(mesh.points[v].x), std::fabs(mesh.points[v].y)});
  if (!(largest > 0.0 && largest < kSmallestScalable)) return;
  char magnitude[32];
  std::snprintf(magnitude, sizeof magnitude, "%g", largest);
  throw InputError(path, 0, std::to_string(crossings) + (crossings == 1 ? " crossing" : " crossings") +
                                " of segments where every vertex coordinate is below " + magnitude +
                                " in magnitude: the crossing points would be subnormal numbers rounded off their "
                                "segments (below 2^-970, about 1e-292); scale the input up");
}

// An area or length bound at the scale refinement runs at: a positive bound stays positive and finite.
double scaled_bound(double bound, int e) {
  if (!(bound > 0.0)) return bound;
  return std::clamp(std::ldexp(bound, e), std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max());
}

void scale_input(Pslg& pslg, int e) {
  for (Point& p : pslg.points) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
  for (Point& p : pslg.holes) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
  for (Pslg::Region& r : pslg.regions) {
    r.at = {std::ldexp(r.at.x, e), std::ldexp(r.at.y, e)};
    r.max_area = scaled_bound(r.max_area, 2 * e);
  }
}

// About the triangles a size field asks for (refine/size_field.h: the equilateral triangle of
// edge h, h at each triangle's centroid), in the mesh at scale 2^e.
double size_field_triangles(const Mesh& mesh, const std::function<double(const Point&)>& length, int e) {
  double wanted = 0.0;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const auto [a, b, c] = mesh.corner_points(t);
    const Point centroid{std::ldexp((a.x + b.x + c.x) / 3.0, -e), std::ldexp((a.y + b.y + c.y) / 3.0, -e)};
    const double h = length(centroid);
    const double area = std::ldexp(0.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)), -2 * e);
    if (h > 0.0) wanted += area / (std::sqrt(3.0) / 4.0 * h * h);
  }
  return wanted;
}

// The mesh back at the input's scale: the input vertices exactly, new vertices rounded only if
// they fall below the normal range.
void unscale_mesh(Mesh& mesh, RefineReport* report, int e) {
  const auto back = [e](Point& p) { p = {std::ldexp(p.x, -e), std::ldexp(p.y, -e)}; };
  for (Point& p : mesh.points) back(p);
  for (double& a : mesh.area_bound) a = a > 0.0 ? std::ldexp(a, -2 * e) : a;
  if (report == nullptr) return;
  back(report->worst_location);
  back(report->worst_size_location);
}

// The paper's other algorithms and options (--algorithm=ruppert|chew, --interior-bound,
// --range-restricted, --corner-lopping) are younger than the Terminator and less tried on hard
// inputs: their meshes always get the -C check, so that a fault ends in an error, never in exit 0.
bool always_checked(const Options& sw) {
  return sw.refinement != RefinementAlgorithm::Terminator || sw.interior_bound != 0 || sw.range_restricted ||
         sw.corner_lopping;
}

// -D asks for a conforming Delaunay mesh; where subsegments are counted as not Delaunay
// (quality/conformity.h; their warning says so), it is held to the constrained property only.
bool conforming_expected(const Options& sw, const RunReport& report) {
  return sw.conforming_delaunay && !(report.conformity && report.conformity->total > 0);
}

// Debug builds check the mesh after every stage, so that a fault is caught in the stage that made
// it rather than at the end (or never, without -C). A fault there is a bug, not bad input.
void check_stage([[maybe_unused]] const Mesh& mesh, [[maybe_unused]] const char* stage,
                 [[maybe_unused]] bool conforming = false) {
#ifndef NDEBUG
  CheckOptions opt;
  opt.conforming = conforming;
  const CheckReport report = check_mesh(mesh, opt);
  if (!report.ok()) throw std::logic_error(std::string("inconsistent mesh after ") + stage + ": " + report.summary());
#endif
}

// The vertices move into the mesh (the Pslg keeps segments, holes and regions): one copy of the
// coordinates at a time is part of the memory budget.
Mesh mesh_from_pslg(Pslg& pslg) {
  Mesh mesh;
  mesh.kind.assign(pslg.points.size(), VertexKind::Input);
  mesh.points = std::move(pslg.points);
  mesh.num_attributes = pslg.num_attributes;
  mesh.attributes = std::move(pslg.attributes);
  if (pslg.has_markers) mesh.marker = std::move(pslg.markers);
  pslg.points.clear();
  return mesh;
}

// Builds the constrained Delaunay triangulation of a .poly's segments and carves the domain.
void constrain(Mesh& mesh, const Pslg& pslg, const DelaunayReport& dt, const Options& sw,
               RunReport& report) {
  Predicates pred;
  report.segments = insert_segments(mesh, pred, pslg.segments, dt.duplicates, !sw.exact_input, sw.split_segments,
                                    threads_to_use(sw));
  if (sw.convex_hull) enclose_convex_hull(mesh);
  const std::vector<Point> no_holes;
  report.holes = carve_holes(mesh, pred, sw.ignore_holes ? no_holes : pslg.holes, sw.convex_hull, pslg.segments);
  const bool region_areas = sw.variable_area && !pslg.regions.empty();
  if (sw.regional_attributes || region_areas)
    report.regions = spread_regions(mesh, pred, pslg.regions, sw.regional_attributes, region_areas, pslg.segments);
  report.counters.add(pred.counters);
}

// --corner-lopping (Sec. 6.1): X becomes X' and its spokes (cdt/corner_lopping.h); which angles lie
// inside the domain is read off X's own constrained Delaunay triangulation, built on a copy.
CornerLopping lop_corners_of(Pslg& pslg, const Options& sw) {
  Pslg copy = pslg;
  Mesh domain = mesh_from_pslg(copy);
  const DelaunayReport dt = delaunay_triangulate(domain, sw.algorithm, 1);
  RunReport scratch;
  constrain(domain, copy, dt, sw, scratch);
  return lop_corners(pslg, domain);
}

// Output numbers of the vertices: every vertex but deleted ones, or with -j only those a
// triangle uses (its corners and, with -o2, its midpoints). Empty when every vertex is written in
// id order.
std::vector<std::uint32_t> vertex_numbering(const Mesh& mesh, bool jettison, const std::vector<VertexId>& midpoints) {
  std::vector<char> keep(mesh.vertex_count(), 1);
  if (jettison) {
    keep.assign(mesh.vertex_count(), 0);
    for (VertexId v : mesh.corner)
      if (v != kNone) keep[v] = 1;
    for (VertexId v : midpoints)
      if (v != kNone) keep[v] = 1;
  }
  bool all = true;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v) {
    if (mesh.kind[v] == VertexKind::Dead) keep[v] = 0;
    all = all && keep[v];
  }
  std::vector<std::uint32_t> numbering;
  if (all) return numbering;
  numbering.assign(mesh.vertex_count(), kNone);
  std::uint32_t next = 0;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v)
    if (keep[v]) numbering[v] = next++;
  return numbering;
}

// -r: the previous mesh's triangles, its .poly segments (with -p) and its .area bounds. Holes
// are not carved again and regions are not read, as in Triangle.
// The .area bounds are kept as a field over the triangles as read (refine/area_field.h), before
// the flips that make the mesh constrained Delaunay re-cut them.
void rebuild(Mesh& mesh, const Pslg& pslg, const PipelineSource& source, const Options& sw, RunReport& report,
             AreaField& area_field, int scale) {
  Predicates pred;
  const PreviousMesh& previous = *source.previous;
  rebuild_mesh(mesh, pred, previous.ele, previous.ele_name);
  report.rebuilt_triangles = previous.ele.triangle_count();
  if (source.is_poly)
    report.segments = insert_segments(mesh, pred, pslg.segments, {}, !sw.exact_input, sw.split_segments, threads_to_use(sw));
  protect_boundary(mesh);
  if (previous.area_bounds) {
    mesh.area_bound = previous.areas;
    for (double& a : mesh.area_bound) a = scaled_bound(a, 2 * scale);
    area_field = AreaField::of(mesh);
  }
  make_constrained_delaunay(mesh, pred);
  report.counters.add(pred.counters);
}

bool area_bounds_read(const PipelineSource& source) { return source.previous && source.previous->area_bounds; }

// The size bounds as refinement sees them on an input scaled by 2^scale (refinement_scale).
SizeBounds scaled_size(SizeBounds size, int scale) {
  size.max_area = scaled_bound(size.max_area, 2 * scale);
  size.max_edge_length = scaled_bound(size.max_edge_length, scale);
  return size;
}

// A caller's size test on a mesh scaled by 2^scale: asked in the input's coordinates and areas.
// Empty when there is no test or no scale.
SizeTest size_test_at_scale(const SizeTest* test, int scale) {
  if (test == nullptr || scale == 0) return {};
  return [test, scale](const Point& a, const Point& b, const Point& c, double area) {
    const auto back = [scale](const Point& p) { return Point{std::ldexp(p.x, -scale), std::ldexp(p.y, -scale)}; };
    return (*test)(back(a), back(b), back(c), std::ldexp(area, -2 * scale));
  };
}

BoundRequest bound_request(const Criteria& criteria, const Options& sw, const RunReport& report, int scale) {
  BoundRequest r;
  r.angle = criteria.angle;
  r.size = scaled_size(criteria.size, scale);
  r.max_angle = criteria.max_angle;
  r.steiner_limited = report.refine && report.refine->stopped_by_max_steiner;
  r.segments_kept_whole = sw.no_boundary_steiner > 0;
  r.threads = threads_to_use(sw);
  return r;
}

// --smooth: after refinement (and its -D account), on one thread in vertex order, so that the
// mesh is the same for every --threads.
void smooth(Mesh& mesh, const Options& sw, const Criteria& criteria, const PipelineSource& source, RunReport& report,
            int scale) {
  SmoothOptions opt;
  opt.rounds = sw.smooth_rounds;
  opt.angle = criteria.angle;
  opt.size = scaled_size(criteria.size, scale);
  opt.max_angle = criteria.max_angle;
  const SizeTest unscaled_test = size_test_at_scale(source.size_test, scale);
  opt.size_test = unscaled_test ? &unscaled_test : source.size_test;
  opt.conforming = conforming_expected(sw, report);
  Predicates pred;
  report.smooth = smooth_mesh(mesh, pred, opt);
  report.counters.add(pred.counters);
}

}  // namespace

Criteria criteria_of(const Options& sw, bool area_file) {
  Criteria c;
  if (sw.quality) c.angle = AngleBound(sw.min_angle);
  c.size = {sw.fixed_area ? sw.max_area : 0.0, sw.variable_area || area_file, sw.user_test ? sw.max_edge_length : 0.0};
  if (sw.max_angle > 0.0) c.max_angle = LargestAngleBound(sw.max_angle);
  return c;
}

RefineOptions refine_options(const Options& sw, const Criteria& criteria) {
  RefineOptions opt;
  opt.angle = criteria.angle;
  opt.size = criteria.size;
  opt.max_angle = criteria.max_angle;
  opt.lenses = !sw.conforming_delaunay;
  opt.conforming_delaunay = sw.conforming_delaunay;
  opt.no_steiner_on_segments = sw.no_boundary_steiner;
  opt.max_steiner = sw.max_steiner;
  opt.off_centers = !sw.circumcenters_only;
  opt.steiner = sw.steiner;
  opt.queue_order = sw.queue_order;
  opt.decline_cluster_splits = sw.decline_cluster_splits;
  opt.algorithm = sw.refinement;
  opt.interior_bound = sw.interior_bound;
  opt.range_restricted = sw.range_restricted;
  opt.threads = threads_to_use(sw);
  opt.probe_memory = true;
  return opt;
}

bool refinement_wanted(const Options& sw, const PipelineSource& source) {
  return sw.quality || sw.max_angle > 0.0 || sw.fixed_area || sw.variable_area || area_bounds_read(source) || sw.user_test ||
         sw.conforming_delaunay || source.size_test != nullptr;
}

PipelineResult run_pipeline(Pslg& pslg, const PipelineSource& source, const Options& sw, RunReport& report,
                            const StageListener& stage_listener) {
  Progress* const progress = source.progress;
  const auto begin = [progress](const char* name) {
    if (progress) progress->begin(name);
  };
  PipelineResult result;
  Mesh& mesh = result.mesh;
  const auto stage = [&](const char* name) {
    if (progress) progress->set_triangles(mesh.live_triangles());
    if (stage_listener) stage_listener(name);
  };
  const bool rebuilding = source.previous != nullptr;
  // -s splits segments at new vertices too (no refinement): the same range applies.
  const int scale = refinement_wanted(sw, source) || sw.split_segments
                        ? refinement_scale(pslg, pslg.source_name.empty() ? source.name : pslg.source_name)
                        : 0;
  if (scale != 0) scale_input(pslg, scale);
  report.input_name = source.name;
  report.area_file = area_bounds_read(source);
  // The bounds, made once from the switches: refinement and the account of misses both read them.
  const Criteria criteria = criteria_of(sw, report.area_file);
  report.pslg = &pslg;
  report.input_vertices = pslg.points.size();
  report.input_segments = pslg.segments.size();
  stage("read");

  CornerLopping lopping;
  if (sw.corner_lopping && source.is_poly && !rebuilding) lopping = lop_corners_of(pslg, sw);
  mesh = mesh_from_pslg(pslg);
  AreaField area_field;
  if (rebuilding) {
    begin("mesh reconstruction");
    rebuild(mesh, pslg, source, sw, report, area_field, scale);
    stage("mesh reconstruction");
    check_stage(mesh, "mesh reconstruction");
  } else {
    begin("Delaunay");
    const DelaunayReport dt = delaunay_triangulate(mesh, sw.algorithm, threads_to_use(sw));
    report.duplicates = dt.duplicates.size();
    // As for a header of one or two vertices: duplicates merged, nothing could be triangulated.
    if (const std::size_t distinct = report.input_vertices - report.duplicates; distinct < 3)
      throw InputError(report.input_name, 0,
                       "a triangulation needs at least 3 distinct vertices; after merging duplicates the " +
                           std::to_string(report.input_vertices) + " vertices are " + std::to_string(distinct) +
                           " distinct point" + (distinct == 1 ? "" : "s"));
    report.counters.add(dt.counters);
    report.sweepline_fell_back = dt.sweepline_fell_back;
    stage("Delaunay");
    check_stage(mesh, "Delaunay");
    if (source.is_poly) {
      begin("segments and holes");
      constrain(mesh, pslg, dt, sw, report);
      refuse_subnormal_crossings(mesh, report.input_vertices, report.segments ? report.segments->crossings : 0, report.input_name);
      std::vector<Pslg::Segment>().swap(pslg.segments);  // in the mesh now; refinement's peak is later
      stage("segments and holes");
      check_stage(mesh, "segments and holes");
    } else if (sw.convex_hull) {
      enclose_convex_hull(mesh);
      check_stage(mesh, "convex hull");
    }
  }
  if (refinement_wanted(sw, source)) {
    if (!source.is_poly && !sw.convex_hull && !rebuilding) enclose_convex_hull(mesh);  // a point set is bounded by its hull
    Predicates pred;
    if (!rebuilding && (sw.convex_hull || !source.is_poly)) report.hull_absorbed = absorb_near_hull_vertices(mesh, pred);
    RefineOptions opt = refine_options(sw, criteria);
    opt.size_test = source.size_test;
    opt.size = scaled_size(opt.size, scale);
    const SizeTest unscaled_test = size_test_at_scale(source.size_test, scale);
    if (unscaled_test) opt.size_test = &unscaled_test;
    opt.area_field = &area_field;
    if (source.wanted_length) opt.size_test_triangles = size_field_triangles(mesh, source.wanted_length, scale);
    // A first run's .poly may be an earlier output near a tiny crossing (refine/segment_pieces.h).
    opt.straight_chains = rebuilding || source.is_poly;
    opt.straight_chains_at_sharp_junctions_only = !rebuilding;
    opt.progress = progress;
    if (progress) progress->refine_start_triangles.store(mesh.live_triangles(), std::memory_order_relaxed);
    begin("refinement");
    if (lopping.apices > 0) {
      opt.lopped_apices = &lopping.apex;
      opt.lopped_sectors = &lopping.sectors;
    }
    report.refine = refine_mesh(mesh, pred, opt);
    report.counters.add(pred.counters);
    mesh.compact_triangles();
    stage("refinement");
    // -D: the subsegments refinement could not split keep the mesh from being Delaunay; they are
    // counted (and warned of), and the checks then hold the mesh to the constrained property.
    if (sw.conforming_delaunay) report.conformity = count_conformity_misses(mesh);
    check_stage(mesh, "refinement", conforming_expected(sw, report));
  }
  if (sw.smooth_rounds > 0) {
    begin("smoothing");
    smooth(mesh, sw, criteria, source, report, scale);
    stage("smoothing");
    check_stage(mesh, "smoothing", conforming_expected(sw, report));
  }
  begin("boundary markers");
  // Once, at the end: every marker follows from input markers, subsegments and the boundary.
  assign_boundary_markers(mesh, pslg.has_markers, threads_to_use(sw));

  if (sw.check || always_checked(sw)) {
    CheckOptions opt;
    opt.conforming = conforming_expected(sw, report);
    // Split points on hull edges are rounded, so a refined hull is convex only up to rounding.
    opt.convex_hull_expected = !source.is_poly && !report.refine && !rebuilding;
    begin("check");
    report.check = check_mesh(mesh, opt);
    stage("check");
    if (!report.check->ok()) {
      result.check_failed = true;
      return result;
    }
  }

  // After -C, which checks the constrained Delaunay triangulation refinement made, with the lopped
  // corners' chords and spokes still constrained: the fans need not be Delaunay without them.
  forget_lopping_edges(mesh, lopping.internal);
  if (refinement_wanted(sw, source)) report.misses = count_bound_misses(mesh, bound_request(criteria, sw, report, scale));
  // Misses are counted at the scale refinement ran at: at the input's, angles and areas of a mesh
  // near 1e-300 underflow.
  if (scale != 0) unscale_mesh(mesh, report.refine ? &*report.refine : nullptr, scale);

  if (sw.order == 2) result.midpoints = add_edge_midpoints(mesh);
  result.numbering = vertex_numbering(mesh, sw.jettison, result.midpoints);
  if (sw.jettison) {
    const std::vector<std::uint32_t>& n = result.numbering;
    report.jettisoned_vertex_count = n.empty() ? mesh.vertex_count() : n.size() - std::count(n.begin(), n.end(), kNone);
  }
  return result;
}

}  // namespace deltri
