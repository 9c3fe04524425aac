/* The C library from a CMake consumer: Triangle's call on a square, quiet and numbered from 0. */
#include <stdio.h>
#include <string.h>

#include <deltri/triangle.h>

int main(void) {
  double points[] = {0, 0, 1, 0, 1, 1, 0, 1};
  struct triangulateio in, out;
  memset(&in, 0, sizeof in);
  memset(&out, 0, sizeof out);
  in.pointlist = points;
  in.numberofpoints = 4;
  triangulate("zQa0.1", &in, &out, NULL);
  if (out.numberoftriangles < 10 || out.trianglelist == NULL) {
    printf("FAIL: %d triangles\n", out.numberoftriangles);
    return 1;
  }
  printf("ok: %d triangles, %d points (deltri %s)\n", out.numberoftriangles, out.numberofpoints, deltri_version());
  trifree(out.pointlist);
  trifree(out.pointmarkerlist);
  trifree(out.trianglelist);
  return 0;
}
