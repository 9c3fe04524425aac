/* deltri's C library: the interface of Jonathan Shewchuk's Triangle (struct triangulateio,
 * triangulate(), trifree()), so that a program written for Triangle's library compiles against it
 * unchanged, plus entry points that return a status and a message instead of printing
 * (deltri_triangulate) and take a size test with a user pointer (deltri_triangulate_sized).
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

/* The library's version, "MAJOR.MINOR.PATCH". */
DELTRI_EXPORT const char *deltri_version(void);

#ifdef __cplusplus
}
#endif

#endif
