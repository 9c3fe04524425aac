// Randomised incremental construction. The outside of the hull is covered by ghost triangles
// (mesh/ghosts.h) so that insert_vertex treats a point beyond the hull like any other. A big
// enclosing triangle would instead leave its own edges in the hull.
#include "delaunay/incremental.h"

#include <algorithm>
#include <cstdint>
#include <random>

#include "delaunay/lawson_pass.h"
#include "geometry/box.h"
#include "geometry/hilbert.h"
#include "mesh/assemble.h"
#include "mesh/ghosts.h"
#include "mesh/operations.h"

namespace deltri {
namespace {

// Fisher-Yates with a fixed-seed generator and no library distribution, whose algorithms differ
// between standard libraries: the same input gives the same mesh everywhere.
void shuffle(std::vector<VertexId>& order) {
  std::mt19937 rng(20240601u);
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng() % i]);
}

std::vector<std::uint32_t> hilbert_keys(const Mesh& mesh, const std::vector<VertexId>& ids) {
  Box box;
  for (VertexId v : ids) box.add(mesh.point(v));
  const HilbertCurve curve(box);
  std::vector<std::uint32_t> keys(mesh.vertex_count(), 0);
  for (VertexId v : ids) keys[v] = curve.key(mesh.point(v));
  return keys;
}

// A biased randomised insertion order (Amenta, Choi and Rote): a random order cut into rounds of
// doubling size, each round sorted along a Hilbert curve. The randomness keeps the expected amount
// of flipping linear; the sorting makes each walk from the previous vertex short.
std::vector<VertexId> insertion_order(const Mesh& mesh, std::vector<VertexId> ids) {
  const std::vector<std::uint32_t> keys = hilbert_keys(mesh, ids);
  shuffle(ids);
  for (std::size_t end = ids.size(); end > 64; end /= 2)
    std::sort(ids.begin() + end / 2, ids.begin() + end, [&keys](VertexId a, VertexId b) {
      return keys[a] != keys[b] ? keys[a] < keys[b] : a < b;
    });
  return ids;
}

// Moves three non-collinear vertices to the front of `order`; false if there are none. The first
// two are distinct because duplicates are gone, so any third point off their line will do.
bool front_triangle(const Mesh& mesh, Predicates& pred, std::vector<VertexId>& order) {
  if (order.size() < 3) return false;
  const Point& a = mesh.point(order[0]);
  const Point& b = mesh.point(order[1]);
  for (std::size_t k = 2; k < order.size(); ++k)
    if (pred.orient2d(a, b, mesh.point(order[k])) != 0) {
      std::rotate(order.begin() + 2, order.begin() + k, order.begin() + k + 1);
      return true;
    }
  return false;
}

}  // namespace

std::vector<VertexId> distinct_inputs(Mesh& mesh,
                                      std::vector<std::pair<VertexId, VertexId>>& duplicates) {
  clear_triangles(mesh);
  std::vector<VertexId> ids;
  for (VertexId v{0}; v < mesh.vertex_count(); ++v)
    if (mesh.kind[v] == VertexKind::Input) ids.push_back(v);
  const auto& p = mesh.points;
  std::sort(ids.begin(), ids.end(), [&p](VertexId a, VertexId b) {
    if (p[a].x != p[b].x) return p[a].x < p[b].x;
    if (p[a].y != p[b].y) return p[a].y < p[b].y;
    return a < b;
  });
  std::vector<std::pair<VertexId, VertexId>> found;
  std::vector<VertexId> kept;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (!kept.empty() && p[ids[i]] == p[kept.back()]) {
      found.emplace_back(ids[i], kept.back());
      mesh.kind[ids[i]] = VertexKind::Duplicate;
    } else {
      kept.push_back(ids[i]);
    }
  }
  std::sort(found.begin(), found.end());
  duplicates.insert(duplicates.end(), found.begin(), found.end());
  std::sort(kept.begin(), kept.end());
  return kept;
}

void incremental_delaunay(Mesh& mesh, Predicates& pred,
                          std::vector<std::pair<VertexId, VertexId>>& duplicates) {
  std::vector<VertexId> order = insertion_order(mesh, distinct_inputs(mesh, duplicates));
  if (!front_triangle(mesh, pred, order)) return;
  if (pred.orient2d(mesh.point(order[0]), mesh.point(order[1]), mesh.point(order[2])) < 0)
    std::swap(order[0], order[1]);
  seed_with_ghosts(mesh, order[0], order[1], order[2]);
  EdgeRef hint{0};
  for (std::size_t k = 3; k < order.size(); ++k) {
    const InsertResult r = insert_vertex(mesh, pred, order[k], hint);
    if (r.status == InsertStatus::Inserted) hint = r.edge;
  }
  remove_ghosts(mesh);
  // insert_vertex leaves cocircular ties as its insertion order made them; the tie rule picks
  // divide and conquer's diagonals (one incircle test per edge on general-position input).
  lawson_pass(mesh, pred);
}

}  // namespace deltri
