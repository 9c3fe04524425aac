// The C library (deltri/triangle.h): struct triangulateio to and from the C++ API's value types,
// Triangle's ownership rules for the output arrays, and statuses instead of exceptions.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "api/c_support.h"
#include "api/library_support.h"
#include "options/version.h"

namespace deltri {
namespace {

// Before anything is read through the pointer: a count beyond the readers' limit is refused, not
// trusted (the arrays' sizes are otherwise the caller's word, as in Triangle).
void check_attribute_count(int count, const char* name) {
  constexpr int kMaxAttributes = 1 << 20;  // as the .node and .ele readers
  if (count < 0 || count > kMaxAttributes)
    fail(DELTRI_INPUT_ERROR, std::string(name) + " must be between 0 and " + std::to_string(kMaxAttributes) + ", not " +
                                 std::to_string(count));
}

// Which arrays are read follows the parsed switches, as for the command line's files: segments
// with p; holes and regions with p but not r (a refinement keeps the previous mesh's holes); the
// triangles, their attributes and area bounds with r.
api::Input input_of(const triangulateio& in, const Options& sw) {
  api::Input input;
  input.points = input_array(in.pointlist, in.numberofpoints, 2, "pointlist", "numberofpoints");
  check_attribute_count(in.numberofpointattributes, "numberofpointattributes");
  input.point_attribute_count = in.numberofpointattributes;
  input.point_attributes = input_array(in.pointattributelist, in.numberofpoints, in.numberofpointattributes,
                                       "pointattributelist", "numberofpoints", false, "numberofpointattributes");
  input.point_markers = input_array(in.pointmarkerlist, in.numberofpoints, 1, "pointmarkerlist", "numberofpoints", true);
  const bool refine = sw.refine;
  if (sw.poly) {
    input.segments = input_array(in.segmentlist, in.numberofsegments, 2, "segmentlist", "numberofsegments");
    input.segment_markers = input_array(in.segmentmarkerlist, in.numberofsegments, 1, "segmentmarkerlist", "numberofsegments", true);
    if (!refine) {
      input.holes = input_array(in.holelist, in.numberofholes, 2, "holelist", "numberofholes");
      input.regions = input_array(in.regionlist, in.numberofregions, 4, "regionlist", "numberofregions");
    }
  }
  if (refine) {
    input.corner_count = in.numberoftriangles == 0 ? 3 : in.numberofcorners;  // none: the message says so
    if (input.corner_count != 3 && input.corner_count != 6)
      fail(DELTRI_INPUT_ERROR, "numberofcorners must be 3 or 6, not " + std::to_string(in.numberofcorners));
    input.triangles = input_array(in.trianglelist, in.numberoftriangles, input.corner_count, "trianglelist", "numberoftriangles");
    check_attribute_count(in.numberoftriangleattributes, "numberoftriangleattributes");
    input.triangle_attribute_count = in.numberoftriangleattributes;
    input.triangle_attributes = input_array(in.triangleattributelist, in.numberoftriangles, in.numberoftriangleattributes,
                                            "triangleattributelist", "numberoftriangles", false, "numberoftriangleattributes");
    input.triangle_areas = input_array(in.trianglearealist, in.numberoftriangles, 1, "trianglearealist", "numberoftriangles", true);
  }
  return input;
}

// One output array: into the caller's memory when the pointer is set, else into memory allocated
// here (released with trifree). Allocation happens for every array before any is written, so
// that a failure leaves every output as it was.
struct Destination {
  void** pointer;
  const void* data;
  std::size_t bytes;
  bool allocated = false;
};

class Outputs {
 public:
  template <class T>
  void add(T** pointer, const std::vector<T>& values) {
    if (values.empty()) return;
    list_.push_back({reinterpret_cast<void**>(pointer), values.data(), values.size() * sizeof(T)});
  }
  template <class T>
  void share(T** pointer, T* value) { shared_.push_back({reinterpret_cast<void**>(pointer), value}); }

  // Allocates the missing arrays; on failure frees them again and throws.
  void allocate() {
    for (Destination& d : list_) {
      if (*d.pointer != nullptr) continue;
      void* memory = std::malloc(d.bytes);
      if (memory == nullptr) {
        release();
        fail(DELTRI_MEMORY_ERROR, "out of memory for the output arrays");
      }
      d.allocated = true;
      allocations_.push_back({&d, memory});
    }
  }
  void write() {
    for (auto& [d, memory] : allocations_) *d->pointer = memory;
    for (Destination& d : list_) std::memcpy(*d.pointer, d.data, d.bytes);
    for (auto& [pointer, value] : shared_) *pointer = value;
  }

 private:
  void release() {
    for (auto& a : allocations_) std::free(a.second);
    allocations_.clear();
  }
  std::vector<Destination> list_;
  std::vector<std::pair<Destination*, void*>> allocations_;
  std::vector<std::pair<void**, void*>> shared_;
};

void write_outputs(const api::Mesh& m, const triangulateio& in, triangulateio& out, triangulateio* vorout,
                   const Options& sw) {
  Outputs o;
  o.add(&out.pointlist, m.points);
  o.add(&out.pointattributelist, m.point_attributes);
  o.add(&out.pointmarkerlist, m.point_markers);
  o.add(&out.trianglelist, m.triangles);
  o.add(&out.triangleattributelist, m.triangle_attributes);
  o.add(&out.neighborlist, m.neighbors);
  o.add(&out.segmentlist, m.segments);
  o.add(&out.segmentmarkerlist, m.segment_markers);
  o.add(&out.edgelist, m.edges);
  o.add(&out.edgemarkerlist, m.edge_markers);
  const bool poly = sw.poly && !sw.refine;  // Triangle's rule: then the input's holes and regions are the output's
  if (poly) {
    o.share(&out.holelist, in.holelist);
    o.share(&out.regionlist, in.regionlist);
  }
  if (vorout) {
    o.add(&vorout->pointlist, m.voronoi_points);
    o.add(&vorout->pointattributelist, m.voronoi_point_attributes);
    o.add(&vorout->edgelist, m.voronoi_edges);
    o.add(&vorout->normlist, m.voronoi_normals);
  }
  o.allocate();
  o.write();
  out.numberofpoints = m.point_count;
  out.numberofpointattributes = m.point_attribute_count;
  out.numberoftriangles = m.triangle_count;
  out.numberofcorners = m.corner_count;
  out.numberoftriangleattributes = m.triangle_attribute_count;
  out.numberofsegments = m.segment_count;
  out.numberofedges = m.edge_count;
  if (poly) {
    out.numberofholes = in.numberofholes;
    out.numberofregions = in.numberofregions;
  }
  if (vorout) {
    vorout->numberofpoints = m.triangle_count;
    vorout->numberofpointattributes = m.point_attribute_count;
    vorout->numberofedges = m.edge_count;
  }
}

int triangulate_arrays(const char* switches, triangulateio* in, triangulateio* out, triangulateio* vorout,
                       deltri_size_test test, void* user, deltri_status* status) {
  return with_status(status, [&] {
    if (switches == nullptr) switches = "";
    if (in == nullptr || out == nullptr) fail(DELTRI_USAGE_ERROR, "the input and output structs must not be NULL");
    const Options sw = parse_library_switches(switches, test != nullptr);
    if (sw.voronoi && vorout == nullptr) fail(DELTRI_USAGE_ERROR, "v: the Voronoi output struct is NULL");
    const api::Input input = input_of(*in, sw);
    api::SizeFunction size;
    if (test) size = [test, user](const double* o, const double* d, const double* a, double area) { return test(o, d, a, area, user) != 0; };
    const api::Mesh mesh = triangulate_parsed(input, sw, size);
    write_outputs(mesh, *in, *out, sw.voronoi ? vorout : nullptr, sw);
  });
}

}  // namespace
}  // namespace deltri

extern "C" {

int deltri_triangulate_sized(const char* switches, triangulateio* in, triangulateio* out, triangulateio* vorout,
                             deltri_size_test test, void* user, deltri_status* status) {
  return deltri::triangulate_arrays(switches, in, out, vorout, test, user, status);
}

int deltri_triangulate(const char* switches, triangulateio* in, triangulateio* out, triangulateio* vorout,
                       deltri_status* status) {
  return deltri::triangulate_arrays(switches, in, out, vorout, nullptr, nullptr, status);
}

void triangulate(char* switches, triangulateio* in, triangulateio* out, triangulateio* vorout) {
  deltri_status status;
  if (deltri::triangulate_arrays(switches, in, out, vorout, nullptr, nullptr, &status) != DELTRI_OK)
    std::fprintf(stderr, "deltri: %s\n", status.message);
}

void trifree(void* memory) { std::free(memory); }

const char* deltri_version(void) { return deltri::version(); }

}  // extern "C"
