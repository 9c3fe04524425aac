#include "cdt/edit.h"

#include "mesh/operations.h"

namespace deltri {

CdtEditor::CdtEditor(Mesh& m, Predicates& p) : mesh(m), pred(p) {
  vertex_edge.assign(mesh.vertex_count(), kNone);
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t)
    if (mesh.is_live(t)) touch(t);
}

void CdtEditor::touch(TriangleId t) {
  for (unsigned i = 0; i < 3; ++i) vertex_edge[mesh.corner[3 * t + i]] = 3 * t + i;
}

void CdtEditor::grow_to_vertices() { vertex_edge.resize(mesh.vertex_count(), kNone); }

namespace {

// Moves the edge held in slot `from` (its twin and subsegment) into slot `to`.
void move_edge(Mesh& mesh, EdgeRef from, EdgeRef to) {
  const EdgeRef twin = mesh.link[from];
  mesh.link[to] = twin;
  if (twin != kNone) mesh.link[twin] = to;
  mesh.subseg[to] = mesh.subseg[from];
}

}  // namespace

void CdtEditor::flip(EdgeRef e) {
  const EdgeRef f = mesh.link[e];
  deltri::flip<FlipLayout::KeepOrigins>(mesh, e);
  touch(triangle_of(e));
  touch(triangle_of(f));
}

bool CdtEditor::flippable(EdgeRef e) {
  const EdgeRef f = mesh.link[e];
  const Point& p = mesh.point(mesh.org(e));
  const Point& q = mesh.point(mesh.dest(e));
  const Point& r = mesh.point(mesh.apex(e));
  const Point& s = mesh.point(mesh.apex(f));
  return pred.orient2d(p, s, r) > 0.0 && pred.orient2d(q, r, s) > 0.0;
}

bool CdtEditor::violates_delaunay(EdgeRef e) {
  const EdgeRef f = mesh.link[e];
  return pred.incircle(mesh.point(mesh.org(e)), mesh.point(mesh.dest(e)), mesh.point(mesh.apex(e)),
                       mesh.point(mesh.apex(f))) > 0.0;
}

void CdtEditor::insert_in_triangle(EdgeRef e, VertexId v) {
  const TriangleId t = triangle_of(e);
  const EdgeRef e0 = 3 * t, e1 = e0 + 1, e2 = e0 + 2;
  const VertexId a = mesh.corner[e0], b = mesh.corner[e1], c = mesh.corner[e2];
  const TriangleId t1 = mesh.add_triangle(b, c, v);
  const TriangleId t2 = mesh.add_triangle(c, a, v);
  move_edge(mesh, e1, 3 * t1);
  move_edge(mesh, e2, 3 * t2);
  mesh.corner[e2] = v;  // t becomes (a, b, v)
  mesh.bond(e1, 3 * t1 + 2);
  mesh.bond(3 * t1 + 1, 3 * t2 + 2);
  mesh.bond(3 * t2 + 1, e2);
  mesh.subseg[e1] = mesh.subseg[e2] = kNone;
  grow_to_vertices();
  touch(t);
  touch(t1);
  touch(t2);
  std::vector<EdgeRef> stack{e0, 3 * t1, 3 * t2};
  legalize(stack);
}

void CdtEditor::insert_on_edge(EdgeRef e, VertexId v) {
  const EdgeRef f = mesh.link[e];
  const VertexId a = mesh.org(e), b = mesh.dest(e), c = mesh.apex(e);
  // Left triangle (a, b, c) becomes (a, v, c) plus new (v, b, c).
  const TriangleId tl = mesh.add_triangle(v, b, c);
  move_edge(mesh, lnext(e), 3 * tl + 1);
  mesh.corner[lnext(e)] = v;
  mesh.bond(lnext(e), 3 * tl + 2);
  mesh.subseg[lnext(e)] = kNone;
  std::vector<EdgeRef> stack{lprev(e), 3 * tl + 1};
  TriangleId tr = kNone;
  if (f != kNone) {
    // Right triangle (b, a, d) becomes (b, v, d) plus new (v, a, d).
    const VertexId d = mesh.apex(f);
    tr = mesh.add_triangle(v, a, d);
    move_edge(mesh, lnext(f), 3 * tr + 1);
    mesh.corner[lnext(f)] = v;
    mesh.bond(lnext(f), 3 * tr + 2);
    mesh.subseg[lnext(f)] = kNone;
    mesh.bond(e, 3 * tr);
    mesh.bond(f, 3 * tl);
    stack.push_back(lprev(f));
    stack.push_back(3 * tr + 1);
  }
  grow_to_vertices();
  touch(triangle_of(e));
  touch(tl);
  if (f != kNone) {
    touch(triangle_of(f));
    touch(tr);
  }
  legalize(stack);
}

void CdtEditor::legalize_from(EdgeRef e) {
  std::vector<EdgeRef> stack{e};
  while (!stack.empty()) {
    const EdgeRef g = stack.back();
    stack.pop_back();
    const EdgeRef f = mesh.link[g];
    if (f == kNone || mesh.subseg[g] != kNone || !violates_delaunay(g)) continue;
    flip(g);
    for (const EdgeRef outer : {g, lprev(g), f, lprev(f)}) stack.push_back(outer);
  }
}

void CdtEditor::legalize(std::vector<EdgeRef>& stack) {
  while (!stack.empty()) {
    const EdgeRef e = stack.back();
    stack.pop_back();
    const EdgeRef f = mesh.link[e];
    if (f == kNone || mesh.subseg[e] != kNone || !violates_delaunay(e)) continue;
    // e = (a, b) with apex v; after the flip the edges opposite v sit at e and lprev(f).
    flip(e);
    stack.push_back(e);
    stack.push_back(lprev(f));
  }
}

}  // namespace deltri
