// 8 threads calling the C++ API at once, each on a different input with different switches, must
// give results byte for byte equal to the same calls made one at a time; and again with the
// threads given the inputs in another order. Built also under ThreadSanitizer (make check-tsan),
// which must report nothing.
//   test_api_threads DATA_DIR
#define DELTRI_INTERNAL
#include "deltri/deltri.hpp"

#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "io/node_file.h"
#include "io/poly_file.h"

namespace {

struct Job {
  std::string file;
  std::string switches;
  bool sized = false;  // with a C++ size function as well
};

deltri::api::Input input_of(const std::string& path, int first) {
  const bool poly = path.ends_with(".poly");
  const deltri::Pslg pslg = poly ? deltri::read_poly_file(path) : deltri::read_node_file(path);
  deltri::api::Input in;
  for (const deltri::Point& p : pslg.points) in.points.insert(in.points.end(), {p.x, p.y});
  in.point_attribute_count = pslg.num_attributes;
  in.point_attributes = pslg.attributes;
  in.point_markers = pslg.markers;
  // The library numbers from 0 with z, else from 1; the Pslg's segments are 0-based.
  for (const auto& s : pslg.segments) in.segments.insert(in.segments.end(), {int(s.a) + first, int(s.b) + first});
  for (const auto& s : pslg.segments)
    if (pslg.has_segment_markers) in.segment_markers.push_back(s.marker);
  for (const deltri::Point& h : pslg.holes) in.holes.insert(in.holes.end(), {h.x, h.y});
  for (const auto& r : pslg.regions) in.regions.insert(in.regions.end(), {r.at.x, r.at.y, r.attribute, r.max_area});
  return in;
}

template <class T>
bool same(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same(const deltri::api::Mesh& a, const deltri::api::Mesh& b) {
  return a.point_count == b.point_count && a.triangle_count == b.triangle_count && a.edge_count == b.edge_count &&
         a.segment_count == b.segment_count && same(a.points, b.points) && same(a.point_attributes, b.point_attributes) &&
         same(a.point_markers, b.point_markers) && same(a.triangles, b.triangles) &&
         same(a.triangle_attributes, b.triangle_attributes) && same(a.neighbors, b.neighbors) &&
         same(a.segments, b.segments) && same(a.segment_markers, b.segment_markers) && same(a.edges, b.edges) &&
         same(a.edge_markers, b.edge_markers) && same(a.voronoi_points, b.voronoi_points) &&
         same(a.voronoi_edges, b.voronoi_edges) && same(a.voronoi_normals, b.voronoi_normals);
}

deltri::api::Mesh run(const deltri::api::Input& in, const Job& job) {
  // Finer towards the left: a size function that reads nothing but its arguments.
  const deltri::api::SizeFunction size = [](const double* a, const double* b, const double* c, double area) {
    const double x = (a[0] + b[0] + c[0]) / 3.0;
    return area > 0.5 + 0.2 * x;
  };
  return deltri::api::triangulate(in, job.switches, job.sized ? size : deltri::api::SizeFunction{});
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return std::fprintf(stderr, "usage: test_api_threads DATA_DIR\n"), 2;
  const std::string data = argv[1];
  const std::vector<Job> jobs = {
      {"guitar.poly", "pq30a0.05evn"},    {"water.poly", "pq25"},         {"box.poly", "pq30a0.01o2A"},
      {"ukraine.node", "q30ev"},         {"corner_cases.poly", "pq"},   {"crossing-edges.poly", "pcen"},
      {"eberly-6.poly", "pDq", true},    {"Constrained_Sweden.poly", "pzq20j"},
  };
  std::vector<deltri::api::Input> inputs;
  for (const Job& job : jobs) inputs.push_back(input_of(data + "/" + job.file, job.switches.find('z') == std::string::npos ? 1 : 0));
  std::vector<deltri::api::Mesh> serial;
  for (std::size_t k = 0; k < jobs.size(); ++k) serial.push_back(run(inputs[k], jobs[k]));
  int failures = 0;
  for (int round = 0; round < 2; ++round) {
    std::vector<deltri::api::Mesh> parallel(jobs.size());
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < jobs.size(); ++t) {
      // Round 1 gives thread t the job t; round 2 the jobs in reverse, so that no thread always has the same.
      const std::size_t k = round == 0 ? t : jobs.size() - 1 - t;
      threads.emplace_back([&, k] { parallel[k] = run(inputs[k], jobs[k]); });
    }
    for (std::thread& t : threads) t.join();
    for (std::size_t k = 0; k < jobs.size(); ++k)
      if (!same(serial[k], parallel[k])) {
        std::printf("FAIL: %s -%s: the result of 8 threads at once differs from the serial one (round %d)\n",
                    jobs[k].file.c_str(), jobs[k].switches.c_str(), round + 1);
        ++failures;
      }
  }
  // The switches' --threads=N: the same mesh with one thread and with three as with the default.
  for (const char* threads : {" --threads=1", " --threads=3"}) {
    const Job job{"water.poly", "pq25" + std::string(threads)};
    if (!same(serial[1], run(inputs[1], job))) {
      std::printf("FAIL: water.poly -pq25%s differs from -pq25\n", threads);
      ++failures;
    }
  }
  // --algorithm= reaches refinement through the library: terminator is the default's mesh, chew another.
  if (!same(serial[0], run(inputs[0], Job{"guitar.poly", "pq30a0.05evn --algorithm=terminator"})) ||
      same(serial[0], run(inputs[0], Job{"guitar.poly", "pq30a0.05evn --algorithm=chew"}))) {
    std::printf("FAIL: guitar.poly: --algorithm=terminator should give the default's mesh, --algorithm=chew another\n");
    ++failures;
  }
  if (failures) return 1;
  long triangles = 0;
  for (const deltri::api::Mesh& m : serial) triangles += m.triangle_count;
  std::printf("8 threads at once, twice, gave byte-identical results to serial calls (%zu inputs, %ld triangles)\n",
              jobs.size(), triangles);
  return 0;
}
