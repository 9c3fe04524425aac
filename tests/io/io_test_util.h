// Shared helpers for the io tests: scratch files in a private temporary directory and a tiny mesh.
#pragma once

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "harness/id_literals.h"
#include "mesh/mesh.h"
#include "util/errors.h"

namespace iotest {

inline std::filesystem::path scratch_dir() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() /
             ("deltri_io_test_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

inline std::string write_file(const std::string& name, const std::string& text) {
  const auto path = (scratch_dir() / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Runs f, expecting an InputError whose message starts with "<path>:<line>:"; returns what().
template <class F>
std::string input_error(F f) {
  try {
    f();
  } catch (const deltri::InputError& e) {
    return e.what();
  }
  return "no error";
}

// Unit square split along the diagonal 0-2: triangles (0,1,2) and (0,2,3) bonded on that edge.
inline deltri::Mesh two_triangles() {
  using namespace deltri;
  Mesh m;
  for (Point p : {Point{0, 0}, Point{1, 0}, Point{1, 1}, Point{0, 1}}) m.add_vertex(p, VertexKind::Input);
  const TriangleId a = m.add_triangle(0_v, 1_v, 2_v);
  const TriangleId b = m.add_triangle(0_v, 2_v, 3_v);
  m.bond(edge_of(a, 2), edge_of(b, 0));  // a's side 2 runs 2->0, b's side 0 runs 0->2
  return m;
}

}  // namespace iotest
