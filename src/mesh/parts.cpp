#include "mesh/parts.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "mesh/internal.h"
#include "mesh/lawson.h"
#include "mesh/operations.h"
#include "util/run_both.h"
#include "mesh/topology_writer.h"

namespace deltri {
namespace {

// Values per slot of each per-triangle data array (mesh.h, kTriangleData): 0 when it is empty.
std::size_t data_width(const Mesh& mesh, std::vector<double> Mesh::*array) {
  const std::size_t slots = mesh.triangle_slots();
  return slots == 0 ? 0 : (mesh.*array).size() / slots;
}

std::uint64_t edge_key(VertexId a, VertexId b) { return static_cast<std::uint64_t>(a) << 32 | b; }

// The part's id of each of the mesh's vertices or records listed in `ids`, kNone for the others.
template <class Id>
std::vector<Id> local_ids(const std::vector<Id>& ids, std::size_t count) {
  std::vector<Id> local(count, kNone);
  for (std::size_t i = 0; i < ids.size(); ++i) local[ids[i]] = static_cast<Id>(i);
  return local;
}

// The ids i whose mark is set (want) or clear (!want), increasing.
template <class Id>
std::vector<Id> marked_ids(const std::vector<char>& marked, bool want = true) {
  std::vector<Id> ids;
  ids.reserve(static_cast<std::size_t>(std::count_if(marked.begin(), marked.end(), [&](char m) { return (m != 0) == want; })));
  for (std::size_t i = 0; i < marked.size(); ++i)
    if ((marked[i] != 0) == want) ids.push_back(static_cast<Id>(i));
  return ids;
}

// Lists what the part holds: the vertices its triangles use and those marked in keep, and the
// records on their edges.
// Returns how many of their slots carry a subsegment.
std::size_t list_part_ids(const Mesh& mesh, CutOff& cut, const std::vector<std::uint8_t>& moves, std::vector<char> keep) {
  keep.resize(mesh.vertex_count(), 0);
  std::vector<char> records(mesh.subsegments.size(), 0);
  std::size_t carried = 0;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!moves[t] || !mesh.is_live(t)) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      keep[mesh.corner[e]] = 1;
      mesh.subseg.fetch_ahead(e);
      if (!mesh.subseg.has(e)) continue;
      ++carried;
      if (mesh.subseg[e] < records.size()) records[mesh.subseg[e]] = 1;
    }
  }
  cut.vertices = marked_ids<VertexId>(keep);
  cut.records = marked_ids<SubsegmentId>(records);
  return carried;
}

// Copies the part's slots: corners and subsegments in the part's ids, links inside the part,
// subsegments (cut edges marked on both sides), and the triangle data; records which records the
// part owns and which lie on the cut. Returns the moved slots that carry a subsegment in the mesh.
std::vector<EdgeRef> copy_part(Mesh& mesh, CutOff& cut, const std::vector<std::uint8_t>& moves,
                               const std::vector<TriangleId>& slot, SubsegmentId mark, std::size_t carried) {
  const std::vector<VertexId> vertex = cut.vertex_map(mesh.vertex_count());
  const std::vector<SubsegmentId> record_of = local_ids(cut.records, mesh.subsegments.size());
  Mesh& r = cut.part;
  const std::uint32_t n = r.triangle_slots();
  std::size_t width[std::size(kTriangleData)];
  for (std::size_t k = 0; k < std::size(kTriangleData); ++k) {
    width[k] = data_width(mesh, kTriangleData[k]);
    (r.*kTriangleData[k]).resize(static_cast<std::size_t>(n) * width[k]);
  }
  const auto record = [&](SubsegmentId s) { return s < mesh.subsegments.size(); };
  std::vector<EdgeRef> leaving;  // the mesh's slots whose subsegments the part takes
  std::vector<std::pair<EdgeRef, SubsegmentId>> values;  // the part's slots that carry one
  leaving.reserve(carried);
  values.reserve(carried);
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!moves[t] || !mesh.is_live(t)) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i), f = edge_of(slot[t], i);
      const EdgeRef twin = mesh.link[e];
      mesh.subseg.fetch_ahead(e);
      const bool on_cut = twin != kNone && !moves[triangle_of(twin)];
      detail::corner_slots(r)[f] = vertex[mesh.corner[e]];
      detail::link_slots(r)[f] = twin == kNone || on_cut ? kNone : edge_of(slot[triangle_of(twin)], side_of(twin));
      SubsegmentId s = mesh.subseg[e];
      if (s != kNone) leaving.push_back(e);
      if (on_cut) cut.cut_keys.push_back(edge_key(mesh.corner[twin], mesh.corner[lnext(twin)]));
      if (record(s)) (on_cut ? cut.cut_records : cut.part_records)[s] = 1;
      if (on_cut && s == kNone) {
        s = mark;
        detail::subseg_slots(mesh).set(twin, mark);
      }
      if (s != kNone) values.emplace_back(f, record(s) ? record_of[s] : s);
    }
    for (std::size_t k = 0; k < std::size(kTriangleData); ++k) {
      const auto& from = mesh.*kTriangleData[k];
      std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(t * width[k]), width[k],
                  (r.*kTriangleData[k]).begin() + static_cast<std::ptrdiff_t>(slot[t] * width[k]));
    }
  }
  detail::subseg_slots(r).set_all(values);
  return leaving;
}

}  // namespace

std::vector<VertexId> CutOff::vertex_map(std::size_t count) const { return local_ids(vertices, count); }

CutOff cut_off(Mesh& mesh, const std::vector<std::uint8_t>& moves, SubsegmentId mark, std::vector<char> keep) {
  CutOff cut;
  const std::size_t carried = list_part_ids(mesh, cut, moves, std::move(keep));
  cut.part = mesh.part_with(cut.vertices, cut.records);
  cut.part_records.assign(mesh.subsegments.size(), 0);
  cut.cut_records.assign(mesh.subsegments.size(), 0);
  std::vector<TriangleId> slot(mesh.triangle_slots(), kNone);
  TriangleId n{0};
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (moves[t] && mesh.is_live(t)) slot[t] = n++;
  Mesh& r = cut.part;
  detail::corner_slots(r).resize(3 * static_cast<std::size_t>(n));
  detail::link_slots(r).resize(r.corner.size());
  detail::subseg_slots(r).resize(r.corner.size());
  const std::vector<EdgeRef> leaving = copy_part(mesh, cut, moves, slot, mark, carried);
  std::sort(cut.cut_keys.begin(), cut.cut_keys.end());
  // The moved triangles' slots die here: their subsegments, which the part holds now, leave the
  // mesh's table, and kill_triangle unlinks the other side's cut edges.
  detail::subseg_slots(mesh).erase_all(leaving);
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t)
    if (moves[t] && mesh.is_live(t)) mesh.kill_triangle(t);
  detail::subseg_slots(mesh).fit();
  return cut;
}

// The part's triangles and vertices after the mesh's. The appends fault in fresh pages, most of
// their cost: the links and vertices on a second thread, the rest on this one.
PartIds append_part(Mesh& mesh, CutOff& cut, SubsegmentId mark, int threads) {
  Mesh& r = cut.part;
  const PartIds ids{&cut.vertices,
                    &cut.records,
                    static_cast<VertexId>(cut.vertices.size()),
                    VertexId{mesh.vertex_count()},
                    static_cast<SubsegmentId>(cut.records.size()),
                    static_cast<SubsegmentId>(mesh.subsegments.size()),
                    TriangleId{mesh.triangle_slots()}};
  const auto moved = [&](Subsegment s) {
    s.a = ids.vertex(s.a);
    s.b = ids.vertex(s.b);
    return s;
  };
  for (SubsegmentId s{0}; s < ids.s0; ++s)
    if (cut.part_records[cut.records[s]]) mesh.subsegments[cut.records[s]] = moved(r.subsegments[s]);
  for (SubsegmentId s = ids.s0; s < r.subsegments.size(); ++s) mesh.subsegments.push_back(moved(r.subsegments[s]));
  const auto links_and_vertices = [&] {
    move_appending(detail::link_slots(r), detail::link_slots(mesh), [&](EdgeRef e) { return e == kNone ? e : EdgeRef{edge_of(ids.triangle_base, 0) + e}; });
    mesh.take_vertices(r, ids.v0);
  };
  const auto corners_and_subsegments = [&] {
    move_appending(detail::corner_slots(r), detail::corner_slots(mesh), [&](VertexId v) { return ids.vertex(v); });
    const std::size_t base = edge_of(ids.triangle_base, 0);
    detail::subseg_slots(mesh).resize(base + r.subseg.size());
    std::vector<std::pair<EdgeRef, SubsegmentId>> values;
    values.reserve(r.subseg.count());
    r.subseg.for_each([&](EdgeRef f, SubsegmentId s) { values.emplace_back(EdgeRef{static_cast<std::uint32_t>(base + f)}, ids.record(s, mark)); });
    detail::subseg_slots(mesh).set_all(values);
    detail::subseg_slots(r).clear();
  };
  run_both(threads >= 2, links_and_vertices, corners_and_subsegments);
  for (std::vector<double> Mesh::*array : kTriangleData) {
    std::vector<double>& to = mesh.*array;
    const std::vector<double>& from = r.*array;
    to.insert(to.end(), from.begin(), from.end());
  }
  for (TriangleId t : r.free_triangles) mesh.free_triangles.push_back(ids.triangle(t));
  r = Mesh{};
  return ids;
}

namespace {

// Moves entries ids[i] to i (width values each; ids increasing, so ids[i] >= i and nothing is
// overwritten before it is moved) and drops the rest, giving their pages back; the capacity
// stays for what the side adds.
template <class Values, class Id>
void compact(Values& values, const std::vector<Id>& ids, std::size_t width) {
  if (values.empty()) return;
  if (width == 1) {
    for (std::size_t i = 0; i < ids.size(); ++i) values[i] = values[ids[i]];
  } else {
    for (std::size_t i = 0; i < ids.size(); ++i)
      std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(ids[i] * width), width,
                  values.begin() + static_cast<std::ptrdiff_t>(i * width));
  }
  const std::size_t kept = ids.size() * width;
  release_pages(values.data() + kept, (values.size() - kept) * sizeof(values[0]));
  values.resize(kept);
}

// compact's inverse: entry i to ids[i], and the entries added after them (from ids.size() on) to
// `base` on, from the last one down so that nothing is overwritten before it is moved. The other
// entries below base are the caller's to fill. An empty array stays empty.
template <class Values, class Id>
void expand(Values& values, const std::vector<Id>& ids, std::size_t base, std::size_t width) {
  if (width == 0 || values.empty()) return;  // an array the mesh does not use (markers) stays empty
  const std::size_t n = ids.size(), added = values.size() / width - n;
  values.resize((base + added) * width);
  const auto move = [&](std::size_t from, std::size_t to) {
    if (from != to)
      std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(from * width), width,
                  values.begin() + static_cast<std::ptrdiff_t>(to * width));
  };
  if (width == 1) {
    std::copy_backward(values.begin() + static_cast<std::ptrdiff_t>(n),
                       values.begin() + static_cast<std::ptrdiff_t>(n + added),
                       values.begin() + static_cast<std::ptrdiff_t>(base + added));
    for (std::size_t i = n; i-- > 0;) values[ids[i]] = values[i];
    return;
  }
  for (std::size_t j = added; j-- > 0;) move(n + j, base + j);
  for (std::size_t i = n; i-- > 0;) move(i, ids[i]);
}

// Calls f(j, list[j]) for the entries of `list` not in `held` (both increasing).
template <class Id, class F>
void for_each_not_held(const std::vector<Id>& list, const std::vector<Id>& held, F&& f) {
  std::size_t k = 0;
  for (std::size_t j = 0; j < list.size(); ++j) {
    while (k < held.size() && held[k] < list[j]) ++k;
    if (k == held.size() || held[k] != list[j]) f(j, list[j]);
  }
}

// Vertex j of `from`, with all its per-vertex data, as vertex v of `to` (which has room for it).
void copy_vertex(const Mesh& from, std::size_t j, Mesh& to, VertexId v) {
  const std::size_t na = static_cast<std::size_t>(to.num_attributes);
  to.points[v] = from.points[j];
  to.kind[v] = from.kind[j];
  if (!to.marker.empty()) to.marker[v] = from.marker[j];
  std::copy_n(from.attributes.begin() + static_cast<std::ptrdiff_t>(j * na), na,
              to.attributes.begin() + static_cast<std::ptrdiff_t>(v * na));
}

// Appends vertex v of `from`, with all its per-vertex data, to `to`.
void push_vertex(const Mesh& from, VertexId v, Mesh& to) {
  const std::size_t na = static_cast<std::size_t>(from.num_attributes);
  to.points.push_back(from.points[v]);
  to.kind.push_back(from.kind[v]);
  if (!from.marker.empty()) to.marker.push_back(from.marker[v]);
  to.attributes.insert(to.attributes.end(), from.attributes.begin() + static_cast<std::ptrdiff_t>(v * na),
                       from.attributes.begin() + static_cast<std::ptrdiff_t>((v + 1) * na));
}

// Every per-vertex and per-record array of the mesh through compact.
void compact_ids(Mesh& mesh, const Held& held) {
  const std::size_t na = static_cast<std::size_t>(mesh.num_attributes);
  compact(mesh.points, held.vertices, 1);
  compact(mesh.kind, held.vertices, 1);
  compact(mesh.marker, held.vertices, 1);
  compact(mesh.attributes, held.vertices, na);
  compact(mesh.subsegments, held.records, 1);
}

}  // namespace

Held hold_only(Mesh& mesh, const CutOff& cut, std::vector<char> keep, int threads) {
  Held held;
  held.whole_vertices = VertexId{mesh.vertex_count()};
  held.whole_records = static_cast<SubsegmentId>(mesh.subsegments.size());
  keep.resize(mesh.vertex_count(), 0);
  std::vector<char> records(mesh.subsegments.size(), 0);
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const EdgeRef e = edge_of(t, i);
      keep[mesh.corner[e]] = 1;
      mesh.subseg.fetch_ahead(e);
      if (mesh.subseg.has(e) && mesh.subseg[e] < records.size()) records[mesh.subseg[e]] = 1;
    }
  }
  held.vertices = marked_ids<VertexId>(keep);
  held.records = marked_ids<SubsegmentId>(records);
  for (VertexId v : cut.vertices) keep[v] = 1;
  for (SubsegmentId s : cut.records) records[s] = 1;
  held.rest_vertices = marked_ids<VertexId>(keep, false);
  held.rest_records = marked_ids<SubsegmentId>(records, false);
  held.rest.num_attributes = mesh.num_attributes;
  for (VertexId v : held.rest_vertices) push_vertex(mesh, v, held.rest);
  for (SubsegmentId s : held.rest_records) held.rest.subsegments.push_back(mesh.subsegments[s]);

  const std::vector<VertexId> local = local_ids(held.vertices, mesh.vertex_count());
  const std::vector<SubsegmentId> local_record = local_ids(held.records, mesh.subsegments.size());
  const auto to_local = [&](VertexId v) { return v == kNone ? v : local[v]; };
  // The corners on a second thread (with `threads` 2 or more); the rest touches no corner.
  run_both(
      threads >= 2,
      [&] {
        for (EdgeRef e{0}; e < mesh.corner.size(); ++e) detail::corner_slots(mesh)[e] = to_local(mesh.corner[e]);
      },
      [&] {
        // A dead slot's left-over subsegment of a record this side does not hold is dropped.
        detail::subseg_slots(mesh).remap([&](SubsegmentId s) { return s < local_record.size() ? local_record[s] : s; });
        compact_ids(mesh, held);
        for (Subsegment& r : mesh.subsegments) r.a = to_local(r.a), r.b = to_local(r.b);
      });
  return held;
}

namespace {

// hold_all's work on everything but the corners.
void hold_all_but_corners(Mesh& mesh, Held& held, const CutOff& cut) {
  const std::size_t records = mesh.subsegments.size();
  const auto to_whole = [&](VertexId v) { return held.whole_vertex(v); };
  detail::subseg_slots(mesh).remap([&](SubsegmentId s) { return s < records ? held.whole_record(s) : s; });
  for (Subsegment& r : mesh.subsegments) r.a = to_whole(r.a), r.b = to_whole(r.b);
  const std::size_t na = static_cast<std::size_t>(mesh.num_attributes);
  expand(mesh.points, held.vertices, held.whole_vertices, 1);
  expand(mesh.kind, held.vertices, held.whole_vertices, 1);
  expand(mesh.marker, held.vertices, held.whole_vertices, 1);
  expand(mesh.attributes, held.vertices, held.whole_vertices, na);
  for_each_not_held(cut.vertices, held.vertices, [&](std::size_t j, VertexId v) { copy_vertex(cut.part, j, mesh, v); });
  for (std::size_t j = 0; j < held.rest_vertices.size(); ++j) copy_vertex(held.rest, j, mesh, held.rest_vertices[j]);

  expand(mesh.subsegments, held.records, held.whole_records, 1);
  for_each_not_held(cut.records, held.records, [&](std::size_t, SubsegmentId s) { mesh.subsegments[s] = Subsegment{}; });
  for (std::size_t j = 0; j < held.rest_records.size(); ++j) mesh.subsegments[held.rest_records[j]] = held.rest.subsegments[j];
  held.rest = Mesh{};
}

}  // namespace

// As in hold_only, the corners on a second thread.
void hold_all(Mesh& mesh, Held& held, const CutOff& cut, int threads) {
  run_both(
      threads >= 2,
      [&] {
        for (EdgeRef e{0}; e < mesh.corner.size(); ++e) detail::corner_slots(mesh)[e] = held.whole_vertex(mesh.corner[e]);
      },
      [&] { hold_all_but_corners(mesh, held, cut); });
}

namespace {

// The slots of the cut's edges among slots [from, to) of each side, in cut_keys order (kNone where
// not found; of two for one key, the later).
struct CutEdges {
  std::vector<EdgeRef> stayed, moved;
};
CutEdges find_cut_edges(const Mesh& mesh, const CutOff& cut, const PartIds& ids, SubsegmentId mark, EdgeRef from,
                        EdgeRef to) {
  const std::vector<std::uint64_t>& keys = cut.cut_keys;
  CutEdges found{std::vector<EdgeRef>(keys.size(), kNone), std::vector<EdgeRef>(keys.size(), kNone)};
  for (EdgeRef e = from; e < to; ++e) {
    if (mesh.link[e] != kNone || mesh.corner[e] == kNone) continue;
    const SubsegmentId s = mesh.subseg[e];
    if (s != mark && (s >= cut.cut_records.size() || !cut.cut_records[s])) continue;
    const bool on_stayed = e < edge_of(ids.triangle_base, 0);
    // Keyed by the orientation on the side that stayed.
    const std::uint64_t key = on_stayed ? edge_key(mesh.org(e), mesh.dest(e)) : edge_key(mesh.dest(e), mesh.org(e));
    const auto at = std::lower_bound(keys.begin(), keys.end(), key);
    if (at == keys.end() || *at != key) continue;  // an earlier cut's edge
    (on_stayed ? found.stayed : found.moved)[static_cast<std::size_t>(at - keys.begin())] = e;
  }
  return found;
}

}  // namespace

// The two halves of the slots are searched at once with `threads` 2 or more; the upper half's
// finds come later in slot order, as in one pass.
std::vector<EdgeRef> sew_cut(Mesh& mesh, const CutOff& cut, const PartIds& ids, SubsegmentId mark, int threads) {
  CutEdges half[2];
  run_halves(threads >= 2, EdgeRef{0}, EdgeRef{static_cast<std::uint32_t>(mesh.corner.size())},
             [&](EdgeRef from, EdgeRef to, int h) { half[h] = find_cut_edges(mesh, cut, ids, mark, from, to); });
  const auto later = [](EdgeRef low, EdgeRef high) { return high != kNone ? high : low; };
  std::vector<EdgeRef> stayed(cut.cut_keys.size(), kNone);
  for (std::size_t k = 0; k < stayed.size(); ++k) {
    const EdgeRef e = later(half[0].stayed[k], half[1].stayed[k]), f = later(half[0].moved[k], half[1].moved[k]);
    if (e == kNone || f == kNone) throw std::logic_error("the parts' cut edges do not match");
    mesh.bond(e, f);
    if (mesh.subseg[e] == mark) {
      detail::subseg_slots(mesh).set(e, kNone);
      detail::subseg_slots(mesh).set(f, kNone);
    }
    stayed[k] = e;
  }
  return stayed;
}

// Each side is constrained Delaunay, so only the sewn edges, and the sides of the quadrilaterals
// flipped, can fail the test.
// A quadrilateral with a non-Delaunay diagonal is convex, so the incircle test is may_flip.
void flip_delaunay_from(Mesh& mesh, Predicates& pred, std::vector<EdgeRef> stack, std::vector<TriangleId>& touched) {
  const auto may_flip = [&](EdgeRef e) {
    const EdgeRef twin = mesh.link[e];
    return twin != kNone && !mesh.subseg.has(e) &&
           pred.incircle(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), mesh.point(mesh.apex(e)),
                         mesh.point(mesh.apex(twin))) > 0;
  };
  const auto flipped = [&](EdgeRef e, EdgeRef f) {
    touched.push_back(triangle_of(e));
    touched.push_back(triangle_of(f));
  };
  lawson<FlipLayout::Turn, LawsonScope::Everywhere>(mesh, stack, kNone, may_flip, flipped);
}

}  // namespace deltri
