// Input/output base names.
#include "harness/check.h"
#include "io/output_names.h"

using namespace deltri;

TEST(input_base_strips_known_extensions) {
  struct Case { const char* path; const char* base; const char* ext; };
  for (const Case& c : {Case{"points.node", "points", "node"}, Case{"box.poly", "box", "poly"}, Case{"box", "box", ""},
                        Case{"mesh.3.ele", "mesh.3", "ele"}, Case{"mesh.3.area", "mesh.3", "area"},
                        Case{"dir.v2/box", "dir.v2/box", ""}, Case{"a.txt", "a.txt", ""}, Case{".node", ".node", ""},
                        Case{"d/x.1.node", "d/x.1", "node"}}) {
    std::string ext = "junk";
    CHECK_EQ(input_base(c.path, &ext), std::string(c.base));
    CHECK_EQ(ext, std::string(c.ext));
  }
  CHECK_EQ(input_base("x.poly", nullptr), "x");
}

TEST(output_base_iteration_numbers) {
  struct Case { const char* in; bool no_iteration; const char* out; };
  for (const Case& c : {Case{"points", false, "points.1"}, Case{"x.3", false, "x.4"}, Case{"x.9", false, "x.10"},
                        Case{"x.09", false, "x.10"}, Case{"x.03", false, "x.4"}, Case{"x", true, "x"},
                        Case{"x.3", true, "x.3"}, Case{"dir.3/box", false, "dir.3/box.1"}, Case{"a.b", false, "a.b.1"},
                        Case{"m.1.2", false, "m.1.3"}, Case{"x.", false, "x..1"},
                        Case{"x.99999999999999999999", false, "x.100000000000000000000"}})
    CHECK_EQ(output_base(c.in, c.no_iteration), std::string(c.out));
}
