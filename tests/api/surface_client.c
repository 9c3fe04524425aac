/* A C client of deltri_mesh_surface (deltri/triangle.h), for tests/api/surface_clients.py.
 *   surface_client SWITCHES INPUT.flat
 * INPUT.flat, whitespace-separated: <#points> <markers 0|1>, then x y z [marker] per point;
 * <#facets>, then per facet <#polygons> <#holes> <marker>, its polygons as <#corners> <corners...>
 * and its hole points as x y z. On success it prints the surface:
 *   points <n> <markers 0|1> / x y z [marker] per point (%.17g)
 *   triangles <t> / a b c attribute facet per triangle
 *   edges <e> <markers 0|1> / a b [marker] per edge
 * and on an error "status <code> <message>", having checked that the output struct was left as it
 * was. Exit status 0 either way; 1 when the client itself finds something wrong. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "deltri/triangle.h"

/* The next number of the file (counts and vertex numbers too: they are exact as doubles). */
static double read_real(FILE *f) {
  double x = 0;
  if (fscanf(f, "%lf", &x) != 1) {
    fprintf(stderr, "surface_client: bad input file\n");
    exit(1);
  }
  return x;
}

/* Grows a list by one item (the lists are small). */
static int read_count(FILE *f) { return (int)read_real(f); }

static void *grow(void *list, size_t count, size_t size) {
  void *p = realloc(list, (count + 1) * size);
  if (p == NULL) exit(1);
  return p;
}

static void read_facets(FILE *f, struct deltri_facets *in) {
  int k, c, p, h, markers;
  memset(in, 0, sizeof *in);
  in->numberofpoints = read_count(f);
  markers = read_count(f);
  in->pointlist = malloc(3 * sizeof(double) * (size_t)(in->numberofpoints + 1));
  in->pointmarkerlist = markers ? malloc(sizeof(int) * (size_t)(in->numberofpoints + 1)) : NULL;
  for (k = 0; k < in->numberofpoints; ++k) {
    for (c = 0; c < 3; ++c) in->pointlist[3 * k + c] = read_real(f);
    if (markers) in->pointmarkerlist[k] = read_count(f);
  }
  in->numberoffacets = read_count(f);
  in->facetpolygonlist = malloc(sizeof(int) * (size_t)(in->numberoffacets + 1));
  in->facetholelist = malloc(sizeof(int) * (size_t)(in->numberoffacets + 1));
  in->facetmarkerlist = malloc(sizeof(int) * (size_t)(in->numberoffacets + 1));
  for (k = 0; k < in->numberoffacets; ++k) {
    int corners_total;
    in->facetpolygonlist[k] = read_count(f);
    in->facetholelist[k] = read_count(f);
    in->facetmarkerlist[k] = read_count(f);
    for (p = 0; p < in->facetpolygonlist[k]; ++p) {
      in->polygonsizelist = grow(in->polygonsizelist, (size_t)in->numberofpolygons, sizeof(int));
      in->polygonsizelist[in->numberofpolygons] = read_count(f);
      corners_total = 0;
      for (c = 0; c < in->numberofpolygons; ++c) corners_total += in->polygonsizelist[c];
      for (c = 0; c < in->polygonsizelist[in->numberofpolygons]; ++c) {
        in->cornerlist = grow(in->cornerlist, (size_t)(corners_total + c), sizeof(int));
        in->cornerlist[corners_total + c] = read_count(f);
      }
      ++in->numberofpolygons;
    }
    for (h = 0; h < in->facetholelist[k]; ++h) {
      in->holelist = grow(in->holelist, (size_t)(3 * in->numberofholes + 2), sizeof(double));
      for (c = 0; c < 3; ++c) in->holelist[3 * in->numberofholes + c] = read_real(f);
      ++in->numberofholes;
    }
  }
}

static void print_surface(const struct deltri_surface *s) {
  int k;
  printf("points %d %d\n", s->numberofpoints, s->pointmarkerlist != NULL);
  for (k = 0; k < s->numberofpoints; ++k) {
    printf("%.17g %.17g %.17g", s->pointlist[3 * k], s->pointlist[3 * k + 1], s->pointlist[3 * k + 2]);
    if (s->pointmarkerlist) printf(" %d", s->pointmarkerlist[k]);
    printf("\n");
  }
  printf("triangles %d\n", s->numberoftriangles);
  for (k = 0; k < s->numberoftriangles; ++k)
    printf("%d %d %d %.17g %d\n", s->trianglelist[3 * k], s->trianglelist[3 * k + 1], s->trianglelist[3 * k + 2],
           s->triangleattributelist[k], s->trianglefacetlist[k]);
  printf("edges %d %d\n", s->numberofedges, s->edgemarkerlist != NULL);
  for (k = 0; k < s->numberofedges; ++k) {
    printf("%d %d", s->edgelist[2 * k], s->edgelist[2 * k + 1]);
    if (s->edgemarkerlist) printf(" %d", s->edgemarkerlist[k]);
    printf("\n");
  }
}

int main(int argc, char **argv) {
  struct deltri_facets in;
  struct deltri_surface out, before;
  struct deltri_status status;
  FILE *f;
  int code;
  if (argc != 3 || (f = fopen(argv[2], "r")) == NULL) {
    fprintf(stderr, "usage: surface_client SWITCHES INPUT.flat\n");
    return 1;
  }
  read_facets(f, &in);
  fclose(f);
  memset(&out, 0x5a, sizeof out); /* garbage a failing call must not touch */
  before = out;
  code = deltri_mesh_surface(argv[1], &in, &out, &status);
  if (code != DELTRI_OK) {
    printf("status %d %s\n", code, status.message);
    if (status.code != code || memcmp(&out, &before, sizeof out) != 0) {
      fprintf(stderr, "surface_client: the failing call changed its output or status\n");
      return 1;
    }
  } else {
    print_surface(&out);
    deltri_surface_free(&out);
    if (out.pointlist != NULL || out.numberoftriangles != 0) {
      fprintf(stderr, "surface_client: deltri_surface_free left the struct set\n");
      return 1;
    }
  }
  free(in.pointlist);
  free(in.pointmarkerlist);
  free(in.cornerlist);
  free(in.polygonsizelist);
  free(in.holelist);
  free(in.facetpolygonlist);
  free(in.facetholelist);
  free(in.facetmarkerlist);
  return 0;
}
