#include "cdt/rebuild_mesh.h"

#include <cstdint>

#include "mesh/assemble.h"
#include "mesh/constrained_editor.h"
#include "mesh/overlap.h"
#include "mesh/subsegments.h"
#include "util/errors.h"

namespace deltri {
namespace {

std::string triangle_name(TriangleId t) { return "triangle #" + std::to_string(t + 1) + " (in file order)"; }

// The assembly's refusal as the one-line error a user reads.
void throw_problem(const AssemblyProblem& p, const std::string& path) {
  using Kind = AssemblyProblem::Kind;
  switch (p.kind) {
    case Kind::None:
      return;
    case Kind::RepeatedVertex:
      throw InputError(path, 0, triangle_name(p.first) + " repeats a vertex");
    case Kind::Clockwise:
      throw InputError(path, 0, triangle_name(p.first) + " is not counter-clockwise");
    case Kind::SharedEdge:
      throw InputError(path, 0, "an edge is shared by more than two triangles (" + triangle_name(p.first) + ")");
    case Kind::Overlap:
      throw InputError(path, 0, triangle_name(p.first) + " and " + triangle_name(p.second) + " overlap");
  }
}

// A six-node .ele (-o2) lists the edge midpoints as nodes 4 to 6. They are no corners of the
// rebuilt mesh, and refinement makes its own, so, as Triangle does, they leave the mesh: a vertex
// named only as a midpoint is marked Dead and is not written (a -r chain of quadratic meshes would
// otherwise gather unused vertices, pairs of them on the same point).
void drop_midpoint_nodes(Mesh& mesh, const EleData& ele) {
  if (ele.nodes_per_triangle != 6) return;
  std::vector<char> role(mesh.vertex_count(), 0);  // 1: corner, 2: midpoint only
  for (std::size_t i = 0; i < ele.corners.size(); ++i) {
    const std::uint32_t v = ele.corners[i];
    if (i % 6 < 3) role[v] = 1;
    else if (role[v] == 0) role[v] = 2;
  }
  for (VertexId v{0}; v < mesh.vertex_count(); ++v)
    if (role[v] == 2) mesh.kind[v] = VertexKind::Dead;
}

}  // namespace

void rebuild_mesh(Mesh& mesh, Predicates& pred, const EleData& ele, const std::string& ele_path) {
  throw_problem(assemble_triangles(mesh, pred, ele.corners, ele.triangle_count(), ele.nodes_per_triangle), ele_path);
  // Paired edges and counter-clockwise triangles can still cross or lie over one another.
  if (const auto found = find_overlap(mesh, pred))
    throw InputError(ele_path, 0,
                     triangle_name(found->first) + " and " + triangle_name(found->second) +
                         (found->interiors_overlap ? " overlap" : " meet other than at shared corners (a corner of one lies on the other)"));
  mesh.num_triangle_attributes = ele.num_attributes;
  mesh.triangle_attributes = ele.attributes;
  drop_midpoint_nodes(mesh, ele);
}

void protect_boundary(Mesh& mesh) { constrain_boundary(mesh, 1); }

void make_constrained_delaunay(Mesh& mesh, Predicates& pred) {
  ConstrainedEditor editor(mesh, pred);
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e)
    if (mesh.corner[e] != kNone && mesh.link[e] != kNone && mesh.link[e] > e) editor.legalize_from(e);
}

}  // namespace deltri
