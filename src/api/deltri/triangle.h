/* deltri's C library: the interface of Jonathan Shewchuk's Triangle (struct triangulateio,
 * triangulate(), trifree()), so that a program written for Triangle's library compiles against it
 * unchanged, plus entry points that return a status and a message instead of printing
 * (deltri_triangulate) and take a size test with a user pointer (deltri_triangulate_sized), and
 * one for facets in 3-D (deltri_mesh_surface).
 * Plain C (C89 and later, C++, and Fortran through ISO_C_BINDING). See docs/library.md.
 *
 * Reentrant: the library keeps no global state, so any number of threads may call it at once
 * (each with its own structs). */
#ifndef DELTRI_TRIANGLE_H
#define DELTRI_TRIANGLE_H

#include <stddef.h>

#if defined(_WIN32) || !defined(__GNUC__)
#define DELTRI_EXPORT
#else
#define DELTRI_EXPORT __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Triangle's fields in Triangle's order and types (REAL is double). Input and output share the
 * type; which fields are read and written follows the switches (docs/library.md). Item numbers in
 * segmentlist, trianglelist and edgelist start at 1, or at 0 with the switch z. */
struct triangulateio {
  double *pointlist;               /* 2 per point: x, y */
  double *pointattributelist;      /* numberofpointattributes per point */
  int *pointmarkerlist;            /* 1 per point; NULL on input: all 0 */
  int numberofpoints;
  int numberofpointattributes;

  int *trianglelist;               /* numberofcorners per triangle, counter-clockwise (r: input) */
  double *triangleattributelist;   /* numberoftriangleattributes per triangle */
  double *trianglearealist;        /* input only: 1 per triangle (r with a bare a) */
  int *neighborlist;               /* output only (n): 3 per triangle, -1 where none */
  int numberoftriangles;
  int numberofcorners;             /* 3, or 6 with o2 */
  int numberoftriangleattributes;

  int *segmentlist;                /* 2 per segment */
  int *segmentmarkerlist;          /* 1 per segment; NULL on input: all 0 */
  int numberofsegments;

  double *holelist;                /* input (p): 2 per hole; the pointer is copied to the output */
  int numberofholes;

  double *regionlist;              /* input (p): x, y, attribute, maximum area per region; copied too */
  int numberofregions;

  int *edgelist;                   /* output only (e; and v into the Voronoi struct): 2 per edge */
  int *edgemarkerlist;             /* output only (e, not B): 1 per edge */
  double *normlist;                /* output only (v): 2 per Voronoi edge, the ray's direction */
  int numberofedges;
};

/* Triangle's call: switches without the dash ("pq30a0.1zQ"); in and out never NULL; vorout only
 * read with v. Output arrays NULL on entry are allocated (release them with trifree); others are
 * written into and must be large enough. On an error the message is printed to standard error, the
 * outputs are left untouched and the call returns: it never exits the caller's process. */
DELTRI_EXPORT void triangulate(char *switches, struct triangulateio *in, struct triangulateio *out,
                               struct triangulateio *vorout);
/* Releases an array the library allocated (free()). */
DELTRI_EXPORT void trifree(void *memory);

/* What went wrong, for the entry points below. */
enum {
  DELTRI_OK = 0,
  DELTRI_INPUT_ERROR = 1,   /* the input arrays are malformed: message names the item */
  DELTRI_USAGE_ERROR = 2,   /* the switch string is wrong */
  DELTRI_CHECK_FAILED = 5,  /* C: the consistency check found faults (a bug: please report it) */
  DELTRI_MEMORY_ERROR = 6,  /* out of memory, or the size bounds need more than the machine has */
  DELTRI_INTERNAL_ERROR = 7
};

#define DELTRI_MESSAGE_SIZE 512
struct deltri_status {
  int code;                            /* DELTRI_OK or one of the errors above */
  char message[DELTRI_MESSAGE_SIZE];   /* empty, or one line such as
                                          "segment 3: second endpoint 7 is not a vertex (...)" */
};

/* As triangulate(), but never prints (whatever the switches) and never exits: returns status->code
 * (status may be NULL). On an error the outputs are untouched. */
DELTRI_EXPORT int deltri_triangulate(const char *switches, struct triangulateio *in, struct triangulateio *out,
                                     struct triangulateio *vorout, struct deltri_status *status);

/* A size test (Triangle's triunsuitable, with a user pointer): the corners of a triangle,
 * counter-clockwise, and its area; non-zero means "too big, split it". Called only from the
 * calling thread. */
typedef int (*deltri_size_test)(const double *org, const double *dest, const double *apex, double area,
                                void *user);

/* As deltri_triangulate(), with a size test applied along with the switches' bounds (as with
 * Triangle's u; a bare u in the switches is then accepted and means this test). */
DELTRI_EXPORT int deltri_triangulate_sized(const char *switches, struct triangulateio *in,
                                           struct triangulateio *out, struct triangulateio *vorout,
                                           deltri_size_test test, void *user, struct deltri_status *status);

/* Facets in 3-D (docs/surfaces.md), as TetGen's .poly and .smesh carry them: points in space and
 * planar facets, each a run of polygons (vertex numbers: one is a vertex in the facet, two a segment,
 * three or more a closed loop), a run of hole points in its plane, and a marker. Vertex numbers
 * start at 1, or at 0 with the switch z. Only read by the library. */
struct deltri_facets {
  double *pointlist;               /* 3 per point: x, y, z */
  int *pointmarkerlist;            /* 1 per point, or NULL: none */
  int numberofpoints;
  int *cornerlist;                 /* every polygon's corners, one polygon after another */
  int *polygonsizelist;            /* 1 per polygon: its number of corners */
  int numberofpolygons;
  double *holelist;                /* 3 per hole point: x, y, z */
  int numberofholes;
  int *facetpolygonlist;           /* 1 per facet: how many of the polygons, in order, are its own */
  int *facetholelist;              /* 1 per facet: how many of the hole points, in order; NULL: none */
  int *facetmarkerlist;            /* 1 per facet, or NULL: all 0 */
  int numberoffacets;
};

/* The surface mesh, numbered as the input: the input's points first, then the new ones. Every
 * array is allocated by the library (NULL when empty); release them with deltri_surface_free. */
struct deltri_surface {
  double *pointlist;               /* 3 per point */
  int *pointmarkerlist;            /* 1 per point when the input has markers, unless B (0 for new points) */
  int numberofpoints;
  int *trianglelist;               /* 3 per triangle, wound about its facet's normal */
  double *triangleattributelist;   /* 1 per triangle: its facet's marker (the .ele attribute) */
  int *trianglefacetlist;          /* 1 per triangle: its facet's number */
  int numberoftriangles;
  int *edgelist;                   /* 2 per subsegment (every piece of every input segment) */
  int *edgemarkerlist;             /* 1 per subsegment, unless B: the first facet's marker that holds it */
  int numberofedges;
  /* What the mesh is not, as the command line warns of it (docs/surfaces.md): */
  int *mergedpointlist;            /* 2 per point repeating an earlier point's coordinates: it, the earlier one */
  int numberofmergedpoints;
  int *emptiedfacetlist;           /* facets left with no triangle (a hole point and no inner loop about it) */
  int numberofemptiedfacets;
  int budgetreached;               /* 1: the Steiner budget (-S, or the termination guard's) ended the run */
  int roundsexhausted;             /* 1: the facets did not agree on shared segments within the round cap */
  int numberbelowangle;            /* when either of the two above: triangles below the -q angle */
  int numberabovearea;             /*   and above the -a area */
};

/* Meshes the facets as the switches say ("pq30a0.02": the same mesh as deltri -pq30a0.02 on a .poly
 * with a 3-D node section, and the same items as its .node, .ele and .edge). Never prints, never
 * exits: returns status->code (status may be NULL). On success *out is overwritten (its previous
 * pointers are not freed); on an error it is untouched. A facet that is not planar is an input
 * error naming it and its distance from the best plane. */
DELTRI_EXPORT int deltri_mesh_surface(const char *switches, const struct deltri_facets *in, struct deltri_surface *out,
                                      struct deltri_status *status);
/* Releases the arrays of a deltri_surface and sets them to NULL and its counts to 0. */
DELTRI_EXPORT void deltri_surface_free(struct deltri_surface *surface);

/* The library's version, "MAJOR.MINOR.PATCH". */
DELTRI_EXPORT const char *deltri_version(void);

#ifdef __cplusplus
}
#endif

#endif
