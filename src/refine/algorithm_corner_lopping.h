// --corner-lopping (Sec. 6.1, cdt/corner_lopping.h) as refinement sees it: the fans that fill lopped
// corners are left as they are, and a subsegment from a lopped apex to its shield is never split.
// Chosen once from RefineOptions; inactive (no lopped corners) every question answers no.
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.h"

namespace deltri {

struct RefineOptions;

class CornerLopping {
 public:
  explicit CornerLopping(const RefineOptions& opt);
  bool active() const { return apices_ != nullptr; }
  // Whether the subsegment on e is a spoke: a piece of a segment from a lopped apex to its shield.
  bool is_spoke(const Mesh& mesh, EdgeRef e) const { return active() && spoke(mesh.org(e), mesh.dest(e)); }
  // Whether t is a triangle of a fan that fills a lopped corner.
  bool spares(const Mesh& mesh, TriangleId t) const { return active() && in_lopped_corner(mesh, t); }

 private:
  bool in_lopped_corner(const Mesh& mesh, TriangleId t) const;
  bool at_lopped_apex(VertexId v) const;
  bool spoke(VertexId a, VertexId b) const;

  const std::vector<char>* apices_ = nullptr;
  const std::vector<std::array<VertexId, 3>>* sectors_ = nullptr;
};

}  // namespace deltri
