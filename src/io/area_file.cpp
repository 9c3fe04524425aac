#include "io/area_file.h"

#include <algorithm>
#include <climits>

#include "io/line_reader.h"

namespace deltri {

std::vector<double> read_area_file(const std::string& path, std::uint32_t expected_count, int threads) {
  LineReader in = LineReader::open(path, threads);
  if (!in.next_line()) in.fail("unexpected end of file: the area header is missing");
  const auto count = static_cast<std::uint32_t>(in.read_int({"area header", -1, "number of triangles"}, 0, 0xFFFFFFF0LL));
  if (expected_count != 0xFFFFFFFFu && count != expected_count)
    in.fail("area header: " + std::to_string(count) + " triangles, but the mesh has " + std::to_string(expected_count));
  std::vector<double> areas;
  areas.reserve(std::min<std::size_t>(count, in.bytes_left() / 4 + 1));
  for (std::uint32_t k = 0; k < count; ++k) {
    if (!in.next_line()) in.fail("unexpected end of file: " + std::to_string(count) + " areas announced, " + std::to_string(k) + " found");
    in.read_int({"triangle", static_cast<long long>(k) + 1, "index"}, LLONG_MIN, LLONG_MAX);
    areas.push_back(in.read_double({"triangle", static_cast<long long>(k) + 1, "maximum area"}));
  }
  return areas;
}

}  // namespace deltri
