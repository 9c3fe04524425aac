/* A client written the way Triangle's C users write theirs: REAL and VOID defined by the caller,
 * Triangle's header included by its own name ("triangle.h", found through pkg-config's -I), a
 * triangulation with the convex hull and then a refinement of its output. It prints facts that
 * tests/setup/c_users_test.sh checks against the input (counts and areas of a unit square).
 *   triangle_h_client          prints: first T AREA, refined T AREA LARGEST */
#define REAL double
#define VOID int
#include <stdio.h>
#include <stdlib.h>
#include "triangle.h"

static void clear(struct triangulateio *io)
{
  io->pointlist = NULL; io->pointattributelist = NULL; io->pointmarkerlist = NULL;
  io->numberofpoints = 0; io->numberofpointattributes = 0;
  io->trianglelist = NULL; io->triangleattributelist = NULL; io->trianglearealist = NULL;
  io->neighborlist = NULL; io->numberoftriangles = 0; io->numberofcorners = 0;
  io->numberoftriangleattributes = 0;
  io->segmentlist = NULL; io->segmentmarkerlist = NULL; io->numberofsegments = 0;
  io->holelist = NULL; io->numberofholes = 0; io->regionlist = NULL; io->numberofregions = 0;
  io->edgelist = NULL; io->edgemarkerlist = NULL; io->normlist = NULL; io->numberofedges = 0;
}

/* The triangles' areas from their corners: their sum and the largest. */
static REAL area_of(const struct triangulateio *io, REAL *largest)
{
  REAL sum = 0.0;
  *largest = 0.0;
  for (int t = 0; t < io->numberoftriangles; ++t) {
    const int *c = io->trianglelist + t * io->numberofcorners;
    const REAL *a = io->pointlist + 2 * c[0], *b = io->pointlist + 2 * c[1], *d = io->pointlist + 2 * c[2];
    REAL area = 0.5 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
    sum += area;
    if (area > *largest) *largest = area;
  }
  return sum;
}

static void release(struct triangulateio *io)
{
  trifree((VOID *) io->pointlist); trifree((VOID *) io->pointmarkerlist);
  trifree((VOID *) io->trianglelist); trifree((VOID *) io->triangleattributelist);
  trifree((VOID *) io->neighborlist); trifree((VOID *) io->segmentlist);
  trifree((VOID *) io->segmentmarkerlist); trifree((VOID *) io->edgelist);
  trifree((VOID *) io->edgemarkerlist);
}

int main(void)
{
  /* The unit square's corners and its centre. */
  REAL points[] = {0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.5, 0.5};
  struct triangulateio in, mid, out, vorout;
  REAL largest;
  clear(&in); clear(&mid); clear(&out); clear(&vorout);
  in.numberofpoints = 5;
  in.pointlist = points;
  triangulate("pczeQ", &in, &mid, &vorout);
  if (mid.numberoftriangles == 0) return 1;
  printf("first %d %.17g\n", mid.numberoftriangles, area_of(&mid, &largest));
  triangulate("prza0.01Q", &mid, &out, (struct triangulateio *) NULL);
  REAL total = area_of(&out, &largest);
  printf("refined %d %.17g %.17g\n", out.numberoftriangles, total, largest);
  release(&mid);
  release(&out);
  return 0;
}
