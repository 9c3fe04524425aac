// The files of a surface mesh in 3-D (surface/surface_mesh.h), TetGen's layouts:
//   .node  <#points> 3 0 <#markers 0|1>      then <index> <x> <y> <z> [<marker>]
//   .ele   <#triangles> 3 1                   then <index> <a> <b> <c> <facet marker>
//   .edge  <#subsegments> <#markers 0|1>      then <index> <a> <b> [<marker>]   (marker: the
//          marker of the first facet holding the subsegment's segment)
// and for other programs: .off (-g, Geomview OFF), ASCII .stl (--stl), Gmsh MSH 2.2 ASCII (--msh;
// each triangle's physical tag is its facet's marker by io/physical_groups.h's rule, named in
// $PhysicalNames, its elementary tag the facet's number) and
// VTK .vtu ASCII (--vtu; cell data facet_marker).
#pragma once

#include "io/text_writer.h"
#include "surface/surface_mesh.h"

namespace deltri {

struct SurfaceWriteOptions {
  int first_index = 1;
  bool markers = true;  // false: -B
};

void write_surface_node(ByteSink& out, const SurfaceMesh& mesh, const SurfaceWriteOptions& options);
void write_surface_ele(ByteSink& out, const SurfaceMesh& mesh, const SurfaceWriteOptions& options);
void write_surface_edge(ByteSink& out, const SurfaceMesh& mesh, const SurfaceWriteOptions& options);
void write_surface_off(ByteSink& out, const SurfaceMesh& mesh);
void write_surface_stl(ByteSink& out, const SurfaceMesh& mesh);
void write_surface_msh(ByteSink& out, const SurfaceMesh& mesh);
void write_surface_vtu(ByteSink& out, const SurfaceMesh& mesh);

}  // namespace deltri
