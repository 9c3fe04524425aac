/* Every bad input of the reliability table (docs/reliability.md, "Error discipline") that can be
 * given through the C library, and the library's own misuses: each call must return an error
 * status with the expected message, leave the output structs byte for byte as they were, print
 * nothing (standard output and error are captured for the whole run), leak nothing (the
 * AddressSanitizer build, make check-sanitize, runs this with LeakSanitizer) and let the process
 * go on. The table's rows that only a text file can have (syntax, numbering, files) have no
 * counterpart here; docs/library.md lists the mapping. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "deltri/triangle.h"

static double square[] = {0, 0, 3, 0, 3, 3, 0, 3};
static int square_segments[] = {1, 2, 2, 3, 3, 4, 4, 1};
static int failures = 0, cases = 0;
static FILE *report;
static int no_vorout = 0; /* pass vorout as NULL */

static void base(struct triangulateio *in) {
  memset(in, 0, sizeof *in);
  in->pointlist = square;
  in->numberofpoints = 4;
  in->segmentlist = square_segments;
  in->numberofsegments = 4;
}

/* Runs deltri_triangulate on in with switches; the message must contain `expect`. */
static void expect_error(const char *row, const char *switches, struct triangulateio *in, int code, const char *expect) {
  struct triangulateio out, vor, out_before, vor_before;
  struct deltri_status status;
  int got;
  /* NULL output pointers (so that an unexpected success cannot write through garbage), and counts
     no call would set. */
  memset(&out, 0, sizeof out);
  memset(&vor, 0, sizeof vor);
  out.numberofpoints = out.numberoftriangles = out.numberofedges = out.numberofsegments = -7;
  vor.numberofpoints = vor.numberofedges = -7;
  out_before = out;
  vor_before = vor;
  ++cases;
  got = deltri_triangulate(switches, in, &out, no_vorout ? NULL : &vor, &status);
  if (got != code || status.code != code || strstr(status.message, expect) == NULL) {
    fprintf(report, "FAIL %s: -%s gave %d '%s', expected %d '...%s...'\n", row, switches, got, status.message, code, expect);
    ++failures;
  } else if (strchr(status.message, '\n') != NULL) {
    fprintf(report, "FAIL %s: the message is more than one line\n", row);
    ++failures;
  } else if (memcmp(&out, &out_before, sizeof out) != 0 || memcmp(&vor, &vor_before, sizeof vor) != 0) {
    fprintf(report, "FAIL %s: the output structs were changed by a failing call\n", row);
    ++failures;
  } else {
    fprintf(report, "ok %-28s %s\n", row, status.message);
  }
}

/* Facets in 3-D (deltri_mesh_surface): a unit square in the plane z = 0 as one facet. */
static double square3[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static int square3_corners[] = {1, 2, 3, 4}, square3_sizes[] = {4}, one_polygon[] = {1};

static void base_facets(struct deltri_facets *in) {
  memset(in, 0, sizeof *in);
  in->pointlist = square3;
  in->numberofpoints = 4;
  in->cornerlist = square3_corners;
  in->polygonsizelist = square3_sizes;
  in->numberofpolygons = 1;
  in->facetpolygonlist = one_polygon;
  in->numberoffacets = 1;
}

/* As expect_error, for deltri_mesh_surface: the output struct must be left as it was. */
static void expect_surface_error(const char *row, struct deltri_facets *in, int code, const char *expect) {
  struct deltri_surface out, before;
  struct deltri_status status;
  int got;
  memset(&out, 0, sizeof out);
  out.numberofpoints = out.numberoftriangles = out.numberofedges = -7;
  before = out;
  ++cases;
  got = deltri_mesh_surface("pq30", in, in ? &out : NULL, &status);
  if (got != code || status.code != code || strstr(status.message, expect) == NULL) {
    fprintf(report, "FAIL %s: gave %d '%s', expected %d '...%s...'\n", row, got, status.message, code, expect);
    ++failures;
  } else if (memcmp(&out, &before, sizeof out) != 0) {
    fprintf(report, "FAIL %s: the output struct was changed by a failing call\n", row);
    ++failures;
  } else {
    fprintf(report, "ok %-28s %s\n", row, status.message);
  }
}

int main(void) {
  struct triangulateio in;
  double p[16];
  int segments[8], triangles[6];
  double holes[2], regions[8];
  char captured[] = "/tmp/deltri_bad_input_XXXXXX";
  int fd = mkstemp(captured), saved_out = dup(1), saved_err = dup(2);
  long printed;
  report = fdopen(dup(1), "w");
  setvbuf(report, NULL, _IONBF, 0);
  /* Everything the library might print goes to the file from here on. */
  fflush(stdout);
  dup2(fd, 1);
  dup2(fd, 2);

  base(&in); in.numberofpoints = 0;
  expect_error("1 empty / 33 no vertices", "pQ", &in, DELTRI_INPUT_ERROR, "needs at least 3 vertices, the input has 0");
  base(&in); in.pointlist = NULL; in.numberofpoints = 5;
  expect_error("3 fewer vertices (NULL)", "pQ", &in, DELTRI_INPUT_ERROR, "pointlist is NULL but numberofpoints is 5");
  base(&in); in.numberofpoints = -3;
  expect_error("4 negative vertex count", "pQ", &in, DELTRI_INPUT_ERROR, "numberofpoints is -3, must not be negative");
  base(&in); in.numberofpoints = 1;
  expect_error("8 one vertex", "Q", &in, DELTRI_INPUT_ERROR, "needs at least 3 vertices, the input has 1");
  memcpy(p, square, sizeof square); p[2] = NAN; base(&in); in.pointlist = p;
  expect_error("10 NaN coordinate", "pQ", &in, DELTRI_INPUT_ERROR, "vertex 2: x coordinate is not a finite number (nan)");
  memcpy(p, square, sizeof square); p[5] = INFINITY; base(&in); in.pointlist = p;
  expect_error("11/12 Inf coordinate", "pQ", &in, DELTRI_INPUT_ERROR, "vertex 3: y coordinate is not a finite number (inf)");
  base(&in); in.numberofpointattributes = -1;
  expect_error("18 negative attributes", "pQ", &in, DELTRI_INPUT_ERROR, "numberofpointattributes must be between 0 and 1048576, not -1");
  base(&in); in.numberofpointattributes = 100000000;
  expect_error("19 1e8 attributes", "pQ", &in, DELTRI_INPUT_ERROR, "numberofpointattributes must be between 0 and 1048576, not 100000000");
  memcpy(segments, square_segments, sizeof segments); segments[3] = 9; base(&in); in.segmentlist = segments;
  expect_error("22 endpoint out of range", "pQ", &in, DELTRI_INPUT_ERROR, "segment 2: second endpoint 9 is not a vertex (vertices are numbered 1 to 4)");
  segments[3] = 0;
  expect_error("23 endpoint 0, from 1", "pQ", &in, DELTRI_INPUT_ERROR, "segment 2: second endpoint 0 is not a vertex (vertices are numbered 1 to 4)");
  segments[3] = 4;
  expect_error("23 endpoint 4, from 0 (z)", "pzQ", &in, DELTRI_INPUT_ERROR, "segment 1: second endpoint 4 is not a vertex (vertices are numbered 0 to 3)");
  base(&in); in.segmentlist = NULL;
  expect_error("25 segments missing", "pQ", &in, DELTRI_INPUT_ERROR, "segmentlist is NULL but numberofsegments is 4");
  base(&in); in.numberofpointattributes = 3;
  expect_error("point attributes missing", "pQ", &in, DELTRI_INPUT_ERROR,
               "pointattributelist is NULL but numberofpoints times numberofpointattributes is 12 (4 times 3)");
  triangles[0] = 1; triangles[1] = 2; triangles[2] = 3; triangles[3] = 1; triangles[4] = 3; triangles[5] = 4;
  base(&in); in.numberoftriangles = 2; in.numberofcorners = 3; in.trianglelist = triangles; in.numberoftriangleattributes = 5;
  expect_error("triangle attributes missing", "rQ", &in, DELTRI_INPUT_ERROR,
               "triangleattributelist is NULL but numberoftriangles times numberoftriangleattributes is 10 (2 times 5)");
  base(&in); in.numberofholes = 1;
  expect_error("26/28 holes missing", "pQ", &in, DELTRI_INPUT_ERROR, "holelist is NULL but numberofholes is 1");
  base(&in); in.numberofholes = -1; in.holelist = holes;
  expect_error("27 negative hole count", "pQ", &in, DELTRI_INPUT_ERROR, "numberofholes is -1, must not be negative");
  holes[0] = NAN; holes[1] = 1; base(&in); in.holelist = holes; in.numberofholes = 1;
  expect_error("29 hole at NaN", "pQ", &in, DELTRI_INPUT_ERROR, "hole 1: x coordinate is not a finite number (nan)");
  /* Issue 47: the long options hold an r (threads, range-restricted): the holes and regions are read
     all the same, as the parsed switches say (p, no r), not a scan of the string's letters. */
  expect_error("29 hole at NaN, --threads=2", "pQ --threads=2", &in, DELTRI_INPUT_ERROR, "hole 1: x coordinate is not a finite number (nan)");
  expect_error("29 hole at NaN, --range-restricted", "pq30Q --range-restricted", &in, DELTRI_INPUT_ERROR,
               "hole 1: x coordinate is not a finite number (nan)");
  base(&in); in.numberofregions = 2;
  expect_error("30 regions missing, --corner-lopping", "pq30Q --corner-lopping", &in, DELTRI_INPUT_ERROR,
               "regionlist is NULL but numberofregions is 2");
  base(&in); in.numberofregions = 2;
  expect_error("30 regions missing", "pQ", &in, DELTRI_INPUT_ERROR, "regionlist is NULL but numberofregions is 2");
  regions[0] = 1; regions[1] = 1; regions[2] = INFINITY; regions[3] = 0.1; base(&in); in.regionlist = regions; in.numberofregions = 1;
  expect_error("31 region attribute inf", "pAQ", &in, DELTRI_INPUT_ERROR, "region 1: attribute is not a finite number (inf)");
  /* Refinement scales an input beyond +-2^200 or below 2^-150 by a power of two (exact), unless
     its coordinates span more than the exponent range: 1e77 beside 1e-300 cannot be scaled. */
  memcpy(p, square, sizeof square); p[2] = 1e77; p[1] = 1e-300; base(&in); in.pointlist = p;
  expect_error("40 coordinates 1e77 and 1e-300", "pq", &in, DELTRI_INPUT_ERROR, "cannot be scaled into it exactly");
  base(&in);
  expect_error("42/47 r without triangles", "rQ", &in, DELTRI_INPUT_ERROR, "r: the input lists no triangles: the mesh is empty");
  base(&in); in.numberoftriangles = 2; in.numberofcorners = 3;
  expect_error("47 r, trianglelist NULL", "rQ", &in, DELTRI_INPUT_ERROR, "trianglelist is NULL but numberoftriangles is 2");
  expect_error("43 unknown switch", "ptQ", &in, DELTRI_USAGE_ERROR, "-t: unknown switch");
  /* A newline in the switches (found by fuzz_library) was echoed into a two-line message. */
  expect_error("43b newline in the switches", "pQ\n", &in, DELTRI_USAGE_ERROR,
               "the switches hold a control character (byte 0x0a) at position 2");
  expect_error("44 angle 60", "pq60Q", &in, DELTRI_USAGE_ERROR, "the minimum angle must be at least 0 and below 60 degrees");
  expect_error("45 area 0", "pa0Q", &in, DELTRI_USAGE_ERROR, "the maximum area must be a positive number");
  expect_error("46 negative angle", "pq-5Q", &in, DELTRI_USAGE_ERROR, "-q-5: the minimum angle must be at least 0");
  /* Issue 17's empty-mesh and overlap rows, and the library's own misuses. */
  p[0] = p[2] = p[4] = 1; p[1] = p[3] = p[5] = 2; base(&in); in.pointlist = p; in.numberofpoints = 3;
  expect_error("7b three vertices at one point", "Q", &in, DELTRI_INPUT_ERROR, "needs at least 3 distinct vertices");
  triangles[0] = 1; triangles[1] = 2; triangles[2] = 3; triangles[3] = 1; triangles[4] = 2; triangles[5] = 7;
  base(&in); in.trianglelist = triangles; in.numberoftriangles = 2; in.numberofcorners = 3;
  expect_error("r corner out of range", "rQ", &in, DELTRI_INPUT_ERROR, "triangle 2: corner 3 (7) is not a vertex (vertices are numbered 1 to 4)");
  triangles[3] = 1; triangles[4] = 2; triangles[5] = 4;  /* both on the same side of edge 1-2 */
  expect_error("2 r: overlapping triangles", "rQ", &in, DELTRI_INPUT_ERROR, "overlap");
  in.numberofcorners = 4;
  expect_error("r: 4 corners", "rQ", &in, DELTRI_INPUT_ERROR, "numberofcorners must be 3 or 6, not 4");
  base(&in);
  no_vorout = 1;
  expect_error("v without vorout", "pvQ", &in, DELTRI_USAGE_ERROR, "v: the Voronoi output struct is NULL");
  no_vorout = 0;
  expect_error("bare u without a test", "puQ", &in, DELTRI_USAGE_ERROR, "u: a bare u asks for a size test");
  /* The paper's algorithms (issue 22): combinations Shewchuk 2001 rules out, and unknown names. */
  expect_error("chew with D", "pDqQ --algorithm=chew", &in, DELTRI_USAGE_ERROR, "makes constrained Delaunay meshes only");
  expect_error("interior bound with the Terminator", "pqQ --interior-bound=1", &in, DELTRI_USAGE_ERROR,
               "Sec. 7.2 strengthens Ruppert's or Chew's algorithm");
  expect_error("unknown algorithm", "pqQ --algorithm=lawson", &in, DELTRI_USAGE_ERROR, "terminator, ruppert or chew");
  expect_error("NULL structs", "pQ", NULL, DELTRI_USAGE_ERROR, "must not be NULL");

  /* After all that, a good call still works. */
  {
    struct triangulateio out;
    struct deltri_status status;
    base(&in);
    memset(&out, 0, sizeof out);
    if (deltri_triangulate("pq30a0.5", &in, &out, NULL, &status) != DELTRI_OK || out.numberoftriangles < 18) {
      fprintf(report, "FAIL: a good call after the bad ones: %d triangles, '%s'\n", out.numberoftriangles, status.message);
      ++failures;
    }
    trifree(out.pointlist); trifree(out.pointmarkerlist); trifree(out.trianglelist);
    trifree(out.segmentlist); trifree(out.segmentmarkerlist);
  }

  /* Facets in 3-D: the C struct's own misuses (the facets' contents are tests/api/surface_clients.py's). */
  {
    struct deltri_facets f;
    double bent[12];
    int corners[4] = {1, 2, 3, 5}, two[1] = {2}, sizes[1] = {-1};
    base_facets(&f); f.cornerlist = NULL;
    expect_surface_error("surface: NULL corners", &f, DELTRI_INPUT_ERROR, "cornerlist is NULL but the sum of polygonsizelist is 4");
    base_facets(&f); f.numberoffacets = -1;
    expect_surface_error("surface: negative facets", &f, DELTRI_INPUT_ERROR, "numberoffacets is -1, must not be negative");
    base_facets(&f); f.facetpolygonlist = two;
    expect_surface_error("surface: polygon runs", &f, DELTRI_INPUT_ERROR, "facetpolygonlist adds up to 2, but numberofpolygons is 1");
    base_facets(&f); f.polygonsizelist = sizes;
    expect_surface_error("surface: negative size", &f, DELTRI_INPUT_ERROR, "polygonsizelist holds a negative size, -1");
    base_facets(&f); f.numberofholes = 1; f.holelist = square3;
    expect_surface_error("surface: holes, no runs", &f, DELTRI_INPUT_ERROR, "holelist has hole points but facetholelist is NULL");
    base_facets(&f); f.cornerlist = corners;
    expect_surface_error("surface: corner range", &f, DELTRI_INPUT_ERROR, "facet 1: corner 5 is not a point (points are numbered 1 to 4)");
    base_facets(&f); f.numberofpolygons = 0; f.facetpolygonlist = sizes + 0; sizes[0] = 0;
    expect_surface_error("surface: empty facet", &f, DELTRI_INPUT_ERROR, "facet 1: it has no polygons");
    memcpy(bent, square3, sizeof bent); bent[8] = 0.5; base_facets(&f); f.pointlist = bent;
    expect_surface_error("surface: not planar", &f, DELTRI_INPUT_ERROR, "facet 1: not planar: a point lies 0.118 from the best plane");
    bent[8] = NAN;
    expect_surface_error("surface: NaN", &f, DELTRI_INPUT_ERROR, "point 3: a coordinate is not a finite number");
    expect_surface_error("surface: NULL structs", NULL, DELTRI_USAGE_ERROR, "the input and output structs must not be NULL");
  }
  {
    struct deltri_facets f;
    struct deltri_surface out;
    struct deltri_status status;
    base_facets(&f);
    memset(&out, 0, sizeof out);
    if (deltri_mesh_surface("pq30a0.1", &f, &out, &status) != DELTRI_OK || out.numberoftriangles < 10 ||
        out.trianglefacetlist[0] != 1 || out.edgelist == NULL) {
      fprintf(report, "FAIL: a good surface call after the bad ones: %d triangles, '%s'\n", out.numberoftriangles, status.message);
      ++failures;
    }
    deltri_surface_free(&out);
    deltri_surface_free(NULL);
  }

  fflush(stdout);
  fflush(stderr);
  printed = lseek(fd, 0, SEEK_END);
  dup2(saved_out, 1);
  dup2(saved_err, 2);
  close(fd);
  unlink(captured);
  if (printed != 0) {
    fprintf(report, "FAIL: the library printed %ld bytes\n", printed);
    ++failures;
  }
  /* Triangle's own call prints the message to standard error, leaves the outputs and returns. */
  {
    char name[] = "/tmp/deltri_bad_input_stderr_XXXXXX", text[256] = "";
    int err = mkstemp(name);
    FILE *f;
    struct triangulateio out;
    memcpy(segments, square_segments, sizeof segments);
    segments[3] = 9;
    base(&in);
    in.segmentlist = segments;
    memset(&out, 0, sizeof out);
    dup2(err, 2);
    triangulate("pQ", &in, &out, NULL);
    fflush(stderr);
    dup2(saved_err, 2);
    f = fopen(name, "r");
    if (!f || !fgets(text, sizeof text, f) || out.numberoftriangles != 0 || out.pointlist != NULL ||
        strcmp(text, "deltri: segment 2: second endpoint 9 is not a vertex (vertices are numbered 1 to 4)\n") != 0) {
      fprintf(report, "FAIL: triangulate() on a bad segment printed '%s'\n", text);
      ++failures;
    } else {
      fprintf(report, "ok triangulate() printed to stderr and returned: %s", text);
    }
    if (f) fclose(f);
    close(err);
    unlink(name);
  }
  fprintf(report, "%d bad inputs through the C library: %s; nothing printed\n", cases, failures ? "FAILED" : "each an error status and message, outputs untouched");
  fclose(report);
  return failures ? 1 : 0;
}
