// A C++ client of deltri::triangulate (deltri/deltri.hpp), for tests/api/cross_interface.py: the
// same input file and printout as cross_client.c, through the C++ API's value types.
//   cross_client_cpp SWITCHES INPUT.flat
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "deltri/deltri.hpp"

namespace {

template <class T>
std::vector<T> values(std::istream& in, std::size_t count) {
  std::vector<T> v(count);
  for (T& x : v) {
    std::string word;  // read as text: operator>> of a double does not take nan or inf
    in >> word;
    x = static_cast<T>(std::strtod(word.c_str(), nullptr));
  }
  return v;
}

deltri::Input read(std::istream& in) {
  deltri::Input input;
  std::string name;
  std::size_t rows = 0, columns = 0;
  while (in >> name >> rows >> columns) {
    const std::size_t n = rows * columns;
    if (name == "points") input.points = values<double>(in, n);
    else if (name == "point_markers") input.point_markers = values<int>(in, n);
    else if (name == "segments") input.segments = values<int>(in, n);
    else if (name == "holes") input.holes = values<double>(in, n);
    else if (name == "regions") input.regions = values<double>(in, n);
    else throw std::runtime_error("unknown section " + name);
  }
  if (!in.eof()) throw std::runtime_error("bad input file");
  return input;
}

void print(const deltri::Mesh& m) {
  std::printf("points %d\n", m.point_count);
  for (int k = 0; k < m.point_count; ++k) std::printf("%.17g %.17g\n", m.points[2 * k], m.points[2 * k + 1]);
  std::printf("triangles %d %d %d\n", m.triangle_count, m.corner_count, m.triangle_attribute_count);
  for (int k = 0; k < m.triangle_count; ++k) {
    for (int c = 0; c < m.corner_count; ++c) std::printf("%s%d", c ? " " : "", m.triangles[k * m.corner_count + c]);
    for (int c = 0; c < m.triangle_attribute_count; ++c)
      std::printf(" %.17g", m.triangle_attributes[k * m.triangle_attribute_count + c]);
    std::printf("\n");
  }
  std::printf("segments %d\n", m.segment_count);
  for (int k = 0; k < m.segment_count; ++k) std::printf("%d %d\n", m.segments[2 * k], m.segments[2 * k + 1]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: cross_client_cpp SWITCHES INPUT.flat\n");
    return 1;
  }
  std::ifstream file(argv[2]);
  try {
    print(deltri::triangulate(read(file), argv[1]));
  } catch (const deltri::Error& e) {
    std::printf("status %d %s\n", e.code(), e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cross_client_cpp: %s\n", e.what());
    return 1;
  }
  return 0;
}
