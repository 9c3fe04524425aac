// The .area format (input for -r with a bare -a): one area bound per triangle of the .ele.
//   <#triangles>
//   <index> <max area>          (<= 0: no bound)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/file_text.h"

namespace deltri {

// Reads the bounds in file order. With `expected_count` other than kNone (0xFFFFFFFF) the
// header must announce exactly that many (the .ele's triangle count). `threads` as for
// read_ele_file.
std::vector<double> read_area_file(const std::string& path, std::uint32_t expected_count = 0xFFFFFFFFu,
                                   int threads = kReadThreads);

}  // namespace deltri
