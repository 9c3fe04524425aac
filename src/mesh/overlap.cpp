#include "mesh/overlap.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "geometry/box_pairs.h"
#include "mesh/embedding.h"

namespace deltri {
namespace {

class OverlapFinder {
 public:
  OverlapFinder(const Mesh& mesh, Predicates& pred) : mesh_(mesh), pred_(pred) {}

  std::optional<OverlapFinding> run() {
    std::vector<TriangleId> live;
    for (TriangleId t{0}; t < mesh_.triangle_slots(); ++t)
      if (mesh_.is_live(t)) live.push_back(t);
    std::vector<Box> boxes;
    boxes.reserve(live.size());
    for (const TriangleId t : live) boxes.push_back(box_of(t));
    std::optional<OverlapFinding> found;
    BoxPairs(std::move(boxes)).any([&](std::uint32_t i, std::uint32_t j) {
      found = test(std::min(live[i], live[j]), std::max(live[i], live[j]));
      return found.has_value();
    });
    return found;
  }

 private:
  const Point& corner(TriangleId t, unsigned i) const { return mesh_.point(mesh_.corner[edge_of(t, i)]); }

  Box box_of(TriangleId t) const {
    Box b;
    for (unsigned i = 0; i < 3; ++i) b.add(corner(t, i));
    return b;
  }

  bool is_corner(VertexId v, TriangleId t) const {
    return mesh_.corner[edge_of(t, 0)] == v || mesh_.corner[edge_of(t, 1)] == v || mesh_.corner[edge_of(t, 2)] == v;
  }

  // An edge line of `t` with all of u's corners on its closed outer (right) side.
  bool separates(TriangleId t, TriangleId u) {
    for (unsigned i = 0; i < 3; ++i) {
      const Point &a = corner(t, i), &b = corner(t, (i + 1) % 3);
      if (pred_.orient2d(a, b, corner(u, 0)) <= 0 && pred_.orient2d(a, b, corner(u, 1)) <= 0 &&
          pred_.orient2d(a, b, corner(u, 2)) <= 0)
        return true;
    }
    return false;
  }

  // A corner of u, not a corner of t, in the closed triangle t.
  bool corner_on(TriangleId t, TriangleId u) {
    for (unsigned i = 0; i < 3; ++i) {
      const VertexId v = mesh_.corner[edge_of(u, i)];
      if (is_corner(v, t)) continue;
      const Point& p = mesh_.point(v);
      if (pred_.orient2d(corner(t, 0), corner(t, 1), p) >= 0 && pred_.orient2d(corner(t, 1), corner(t, 2), p) >= 0 &&
          pred_.orient2d(corner(t, 2), corner(t, 0), p) >= 0)
        return true;
    }
    return false;
  }

  std::optional<OverlapFinding> test(TriangleId t, TriangleId u) {
    // Two corners in common: an edge shared in opposite directions (the same direction is a
    // repeated directed edge, rejected before), so the two lie on opposite sides of it.
    int shared = 0;
    for (unsigned i = 0; i < 3; ++i) shared += is_corner(mesh_.corner[edge_of(u, i)], t);
    if (shared >= 2) return std::nullopt;
    if (!separates(t, u) && !separates(u, t)) return OverlapFinding{t, u, true};
    if (corner_on(t, u) || corner_on(u, t)) return OverlapFinding{t, u, false};
    return std::nullopt;
  }

  const Mesh& mesh_;
  Predicates& pred_;
};

}  // namespace

std::optional<OverlapFinding> search_overlap(const Mesh& mesh, Predicates& pred) {
  return OverlapFinder(mesh, pred).run();
}

std::optional<OverlapFinding> find_overlap(const Mesh& mesh, Predicates& pred) {
  if (certify_embedding(mesh, pred)) return std::nullopt;
  return search_overlap(mesh, pred);
}

}  // namespace deltri
