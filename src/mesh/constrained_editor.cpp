#include "mesh/constrained_editor.h"

#include "mesh/operations.h"
#include "mesh/vertex_edges.h"

namespace deltri {

void ConstrainedEditor::flip(EdgeRef e) {
  const EdgeRef f = mesh.link[e];
  deltri::flip<FlipLayout::KeepOrigins>(mesh, e);
  flipped(e, f);
}

bool ConstrainedEditor::flippable(EdgeRef e) {
  const EdgeRef f = mesh.link[e];
  const Point& p = mesh.point(mesh.org(e));
  const Point& q = mesh.point(mesh.dest(e));
  const Point& r = mesh.point(mesh.apex(e));
  const Point& s = mesh.point(mesh.apex(f));
  return pred.orient2d(p, s, r) > 0.0 && pred.orient2d(q, r, s) > 0.0;
}

bool ConstrainedEditor::violates_delaunay(EdgeRef e) {
  const EdgeRef f = mesh.link[e];
  return pred.incircle(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), mesh.point(mesh.apex(e)),
                       mesh.point(mesh.apex(f))) > 0.0;
}

bool ConstrainedEditor::may_flip(EdgeRef e) {
  return mesh.link[e] != kNone && !mesh.subseg.has(e) && violates_delaunay(e);
}

void ConstrainedEditor::insert_in_triangle(EdgeRef e, VertexId v) {
  const TriangleId t = triangle_of(e);
  split_triangle<SplitLayout::VertexLast>(mesh, e, v);
  // The new slots are the last two taken: (b, c, v) and (c, a, v), their old edges at side 0.
  const TriangleId t1 = triangle_of(mesh.link[edge_of(t, 1)]), t2 = triangle_of(mesh.link[edge_of(t, 2)]);
  touch(t);
  touch(t1);
  touch(t2);
  std::vector<EdgeRef> stack{edge_of(t, 0), edge_of(t1, 0), edge_of(t2, 0)};
  legalize_link(stack, v);
}

void ConstrainedEditor::insert_on_edge(EdgeRef e, VertexId v) {
  const EdgeRef f = mesh.link[e];
  split_edge(mesh, e, v);
  // Left (a, b, c) is now (a, v, c) plus tl = (v, b, c) across v->b; right (b, a, d) likewise
  // (b, v, d) plus tr = (v, a, d). The edges opposite v are lprev of the old slots and side 1 of
  // the new ones.
  const EdgeRef tl_side0 = lnext(mesh.link[lnext(e)]);
  std::vector<EdgeRef> stack{lprev(e), lnext(tl_side0)};
  if (f != kNone) {
    const EdgeRef tr_side0 = lnext(mesh.link[lnext(f)]);
    stack.push_back(lprev(f));
    stack.push_back(lnext(tr_side0));
  }
  touch(triangle_of(e));
  touch(triangle_of(tl_side0));
  if (f != kNone) {
    touch(triangle_of(f));
    touch(triangle_of(stack.back()));
  }
  legalize_link(stack, v);
}

void ConstrainedEditor::legalize_from(EdgeRef e) {
  std::vector<EdgeRef> stack{e};
  legalize(stack, [this](EdgeRef g) { return may_flip(g); });
}

void ConstrainedEditor::legalize_star(VertexId v) {
  const EdgeRef out = leaving(v);
  if (out == kNone) return;
  std::vector<EdgeRef> stack;
  for_each_around(mesh, out, [&](EdgeRef e) { stack.push_back(e); });
  legalize(stack, [this](EdgeRef g) { return may_flip(g); });
}

void ConstrainedEditor::legalize_link(std::vector<EdgeRef>& stack, VertexId v) {
  lawson<FlipLayout::KeepOrigins, LawsonScope::Link>(mesh, stack, v, [this](EdgeRef g) { return may_flip(g); },
                                                    [this](EdgeRef g, EdgeRef f) { flipped(g, f); });
}

}  // namespace deltri
