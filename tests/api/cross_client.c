/* A C client of deltri_triangulate (deltri/triangle.h), for tests/api/cross_interface.py.
 *   cross_client_c SWITCHES INPUT.flat
 * INPUT.flat, whitespace-separated: sections "<name> <rows> <columns>" and their values, the names
 * points, point_markers, segments, holes, regions. On success it prints the mesh:
 *   points <n> / x y per point (%.17g)
 *   triangles <t> <corners> <attributes> / corners, then attributes (%.17g), per triangle
 *   segments <s> / a b per segment
 *   holes <h> (the output's numberofholes: the input's with p and no r, else 0)
 * and on an error "status <code> <message>", having checked that the output was left as it was.
 * Exit status 0 either way; 1 when the client itself finds something wrong. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "deltri/triangle.h"

static void *read_values(FILE *f, int rows, int columns, int integer) {
  size_t n = (size_t)rows * (size_t)columns, k;
  void *data = malloc(n ? n * 8 : 1);
  if (data == NULL) exit(1);
  for (k = 0; k < n; ++k) {
    double v;
    if (fscanf(f, "%lf", &v) != 1) {
      fprintf(stderr, "cross_client_c: bad input file\n");
      exit(1);
    }
    if (integer) ((int *)data)[k] = (int)v;
    else ((double *)data)[k] = v;
  }
  return data;
}

static void read_input(FILE *f, struct triangulateio *in) {
  char name[64];
  int rows, columns;
  memset(in, 0, sizeof *in);
  while (fscanf(f, "%63s %d %d", name, &rows, &columns) == 3) {
    if (strcmp(name, "points") == 0) {
      in->pointlist = read_values(f, rows, columns, 0);
      in->numberofpoints = rows;
    } else if (strcmp(name, "point_markers") == 0) {
      in->pointmarkerlist = read_values(f, rows, columns, 1);
    } else if (strcmp(name, "segments") == 0) {
      in->segmentlist = read_values(f, rows, columns, 1);
      in->numberofsegments = rows;
    } else if (strcmp(name, "holes") == 0) {
      in->holelist = read_values(f, rows, columns, 0);
      in->numberofholes = rows;
    } else if (strcmp(name, "regions") == 0) {
      in->regionlist = read_values(f, rows, columns, 0);
      in->numberofregions = rows;
    } else {
      fprintf(stderr, "cross_client_c: unknown section %s\n", name);
      exit(1);
    }
  }
}

static void print_mesh(const struct triangulateio *o) {
  int k, c;
  printf("points %d\n", o->numberofpoints);
  for (k = 0; k < o->numberofpoints; ++k) printf("%.17g %.17g\n", o->pointlist[2 * k], o->pointlist[2 * k + 1]);
  printf("triangles %d %d %d\n", o->numberoftriangles, o->numberofcorners, o->numberoftriangleattributes);
  for (k = 0; k < o->numberoftriangles; ++k) {
    for (c = 0; c < o->numberofcorners; ++c) printf("%s%d", c ? " " : "", o->trianglelist[k * o->numberofcorners + c]);
    for (c = 0; c < o->numberoftriangleattributes; ++c)
      printf(" %.17g", o->triangleattributelist[k * o->numberoftriangleattributes + c]);
    printf("\n");
  }
  printf("segments %d\n", o->numberofsegments);
  for (k = 0; k < o->numberofsegments; ++k) printf("%d %d\n", o->segmentlist[2 * k], o->segmentlist[2 * k + 1]);
  printf("holes %d\n", o->numberofholes);
}

int main(int argc, char **argv) {
  struct triangulateio in, out, before;
  struct deltri_status status;
  FILE *f;
  int code;
  if (argc != 3 || (f = fopen(argv[2], "r")) == NULL) {
    fprintf(stderr, "usage: cross_client_c SWITCHES INPUT.flat\n");
    return 1;
  }
  read_input(f, &in);
  fclose(f);
  memset(&out, 0, sizeof out);
  before = out;
  code = deltri_triangulate(argv[1], &in, &out, NULL, &status);
  if (code != DELTRI_OK) {
    printf("status %d %s\n", code, status.message);
    if (status.code != code || memcmp(&out, &before, sizeof out) != 0) {
      fprintf(stderr, "cross_client_c: the failing call changed its output or status\n");
      return 1;
    }
  } else {
    print_mesh(&out);
    /* holelist and regionlist are the input's (Triangle's rule): not freed here. */
    trifree(out.pointlist);
    trifree(out.pointattributelist);
    trifree(out.pointmarkerlist);
    trifree(out.trianglelist);
    trifree(out.triangleattributelist);
    trifree(out.segmentlist);
    trifree(out.segmentmarkerlist);
  }
  free(in.pointlist);
  free(in.pointmarkerlist);
  free(in.segmentlist);
  free(in.holelist);
  free(in.regionlist);
  return 0;
}
