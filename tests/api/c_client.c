/* A client of deltri's C library written only against the installed header <deltri/triangle.h>,
 * compiled as C99 (tests/api/c_client_test.sh). It reads the input arrays from a plain text file
 * (sections "NAME ROWS COLUMNS" then the values, written by compare_c_client.py), calls
 * triangulate() with the given switches and writes every output array in the same form.
 *
 *   c_client INPUT OUTPUT SWITCHES [SWITCHES2] [--preallocate]
 *
 * With SWITCHES2 (an r refinement), the output of the first call is the input of a second call,
 * which is the one written. With --preallocate the output arrays are first sized by a call with
 * NULL pointers, then the caller allocates them and a second call writes into them (as Fortran
 * callers do); both calls must give the same arrays. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <deltri/triangle.h>

static void *read_section(FILE *f, const char *want, int *rows, int *cols, int integer) {
  char name[64];
  long pos = ftell(f);
  rewind(f);
  while (fscanf(f, "%63s %d %d", name, rows, cols) == 3) {
    size_t n = (size_t)*rows * (size_t)*cols, k;
    void *data = NULL;
    if (strcmp(name, want) == 0) data = malloc(n ? n * 8 : 1);
    for (k = 0; k < n; ++k) {
      double v;
      if (fscanf(f, "%lf", &v) != 1) { fprintf(stderr, "bad section %s\n", name); exit(2); }
      if (data && integer) ((int *)data)[k] = (int)v;
      else if (data) ((double *)data)[k] = v;
    }
    if (data) return data;
  }
  (void)pos;
  *rows = 0;
  *cols = 0;
  return NULL;
}

static void read_input(const char *path, struct triangulateio *in) {
  FILE *f = fopen(path, "r");
  int rows, cols;
  if (!f) { perror(path); exit(2); }
  memset(in, 0, sizeof *in);
  in->pointlist = read_section(f, "points", &rows, &cols, 0);
  in->numberofpoints = rows;
  in->pointattributelist = read_section(f, "point_attributes", &rows, &cols, 0);
  in->numberofpointattributes = cols;
  in->pointmarkerlist = read_section(f, "point_markers", &rows, &cols, 1);
  in->segmentlist = read_section(f, "segments", &rows, &cols, 1);
  in->numberofsegments = rows;
  in->segmentmarkerlist = read_section(f, "segment_markers", &rows, &cols, 1);
  in->holelist = read_section(f, "holes", &rows, &cols, 0);
  in->numberofholes = rows;
  in->regionlist = read_section(f, "regions", &rows, &cols, 0);
  in->numberofregions = rows;
  in->trianglelist = read_section(f, "triangles", &rows, &cols, 1);
  in->numberoftriangles = rows;
  in->numberofcorners = cols ? cols : 3;
  in->triangleattributelist = read_section(f, "triangle_attributes", &rows, &cols, 0);
  in->numberoftriangleattributes = cols;
  in->trianglearealist = read_section(f, "triangle_areas", &rows, &cols, 0);
  fclose(f);
}

static void put_reals(FILE *f, const char *name, const double *a, int rows, int cols) {
  int i;
  if (!a || rows <= 0 || cols <= 0) return;
  fprintf(f, "%s %d %d\n", name, rows, cols);
  for (i = 0; i < rows * cols; ++i) fprintf(f, "%.17g%c", a[i], (i + 1) % cols ? ' ' : '\n');
}

static void put_ints(FILE *f, const char *name, const int *a, int rows, int cols) {
  int i;
  if (!a || rows <= 0 || cols <= 0) return;
  fprintf(f, "%s %d %d\n", name, rows, cols);
  for (i = 0; i < rows * cols; ++i) fprintf(f, "%d%c", a[i], (i + 1) % cols ? ' ' : '\n');
}

static void write_output(const char *path, const struct triangulateio *o, const struct triangulateio *v) {
  FILE *f = fopen(path, "w");
  if (!f) { perror(path); exit(2); }
  fprintf(f, "counts %d %d %d %d %d %d %d %d\n", o->numberofpoints, o->numberofpointattributes, o->numberoftriangles,
          o->numberofcorners, o->numberoftriangleattributes, o->numberofsegments, o->numberofedges, o->numberofholes);
  put_reals(f, "points", o->pointlist, o->numberofpoints, 2);
  put_reals(f, "point_attributes", o->pointattributelist, o->numberofpoints, o->numberofpointattributes);
  put_ints(f, "point_markers", o->pointmarkerlist, o->numberofpoints, 1);
  put_ints(f, "triangles", o->trianglelist, o->numberoftriangles, o->numberofcorners);
  put_reals(f, "triangle_attributes", o->triangleattributelist, o->numberoftriangles, o->numberoftriangleattributes);
  put_ints(f, "neighbors", o->neighborlist, o->numberoftriangles, 3);
  put_ints(f, "segments", o->segmentlist, o->numberofsegments, 2);
  put_ints(f, "segment_markers", o->segmentmarkerlist, o->numberofsegments, 1);
  put_ints(f, "edges", o->edgelist, o->numberofedges, 2);
  put_ints(f, "edge_markers", o->edgemarkerlist, o->numberofedges, 1);
  put_reals(f, "holes", o->holelist, o->numberofholes, 2);
  put_reals(f, "regions", o->regionlist, o->numberofregions, 4);
  if (v) {
    put_reals(f, "voronoi_points", v->pointlist, v->numberofpoints, 2);
    put_reals(f, "voronoi_point_attributes", v->pointattributelist, v->numberofpoints, v->numberofpointattributes);
    put_ints(f, "voronoi_edges", v->edgelist, v->numberofedges, 2);
    put_reals(f, "voronoi_normals", v->normlist, v->numberofedges, 2);
  }
  fclose(f);
}

static void release(struct triangulateio *o) {
  /* holelist and regionlist are the input's (Triangle's rule): not freed here. */
  trifree(o->pointlist);
  trifree(o->pointattributelist);
  trifree(o->pointmarkerlist);
  trifree(o->trianglelist);
  trifree(o->triangleattributelist);
  trifree(o->neighborlist);
  trifree(o->segmentlist);
  trifree(o->segmentmarkerlist);
  trifree(o->edgelist);
  trifree(o->edgemarkerlist);
  trifree(o->normlist);
  memset(o, 0, sizeof *o);
}

/* The caller's own arrays, sized from a first run's counts (Triangle's alternative to NULL). */
static void preallocate(struct triangulateio *o, const struct triangulateio *sized) {
  memset(o, 0, sizeof *o);
#define ALLOCATE(field, count) o->field = (sized->field ? malloc((size_t)(count) * sizeof *o->field + 1) : NULL)
  ALLOCATE(pointlist, sized->numberofpoints * 2);
  ALLOCATE(pointattributelist, sized->numberofpoints * sized->numberofpointattributes);
  ALLOCATE(pointmarkerlist, sized->numberofpoints);
  ALLOCATE(trianglelist, sized->numberoftriangles * sized->numberofcorners);
  ALLOCATE(triangleattributelist, sized->numberoftriangles * sized->numberoftriangleattributes);
  ALLOCATE(neighborlist, sized->numberoftriangles * 3);
  ALLOCATE(segmentlist, sized->numberofsegments * 2);
  ALLOCATE(segmentmarkerlist, sized->numberofsegments);
  ALLOCATE(edgelist, sized->numberofedges * 2);
  ALLOCATE(edgemarkerlist, sized->numberofedges);
  ALLOCATE(normlist, sized->numberofedges * 2);
#undef ALLOCATE
}

static int same_arrays(const char *a, const char *b) {
  FILE *fa = fopen(a, "r"), *fb = fopen(b, "r");
  int ca, cb, same = 1;
  if (!fa || !fb) return 0;
  do {
    ca = fgetc(fa);
    cb = fgetc(fb);
    if (ca != cb) same = 0;
  } while (same && ca != EOF);
  fclose(fa);
  fclose(fb);
  return same;
}

int main(int argc, char **argv) {
  struct triangulateio in, mid, out, vor;
  char *switches, *second = NULL, scratch[4096];
  int prealloc = 0, i;
  if (argc < 4) { fprintf(stderr, "usage: c_client INPUT OUTPUT SWITCHES [SWITCHES2] [--preallocate]\n"); return 2; }
  switches = argv[3];
  for (i = 4; i < argc; ++i) {
    if (strcmp(argv[i], "--preallocate") == 0) prealloc = 1;
    else second = argv[i];
  }
  read_input(argv[1], &in);
  memset(&mid, 0, sizeof mid);
  memset(&out, 0, sizeof out);
  memset(&vor, 0, sizeof vor);
  triangulate(switches, &in, &out, &vor);
  if (out.numberoftriangles == 0 && out.trianglelist == NULL && strchr(switches, 'E') == NULL) {
    fprintf(stderr, "c_client: triangulate gave no triangles\n");
    return 1;
  }
  if (second) {
    /* r: the first output is the second call's input (its own arrays, as a caller would keep them). */
    mid = out;
    memset(&out, 0, sizeof out);
    release(&vor);
    triangulate(second, &mid, &out, &vor);
  }
  write_output(argv[2], &out, strchr(second ? second : switches, 'v') ? &vor : NULL);
  if (prealloc) {
    /* The same call again, into arrays the caller allocated. */
    struct triangulateio own, ownvor;
    struct triangulateio *source = second ? &mid : &in;
    preallocate(&own, &out);
    preallocate(&ownvor, &vor);
    triangulate(second ? second : switches, source, &own, &ownvor);
    snprintf(scratch, sizeof scratch, "%s.preallocated", argv[2]);
    write_output(scratch, &own, strchr(second ? second : switches, 'v') ? &ownvor : NULL);
    if (!same_arrays(argv[2], scratch)) {
      fprintf(stderr, "c_client: the caller-allocated arrays differ from the library-allocated ones\n");
      return 1;
    }
    release(&own);
    release(&ownvor);
  }
  release(&out);
  release(&vor);
  if (second) release(&mid);
  free(in.pointlist);
  free(in.pointattributelist);
  free(in.pointmarkerlist);
  free(in.segmentlist);
  free(in.segmentmarkerlist);
  free(in.holelist);
  free(in.regionlist);
  free(in.trianglelist);
  free(in.triangleattributelist);
  free(in.trianglearealist);
  return 0;
}
