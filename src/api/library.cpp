// deltri::api::triangulate: the switch string, the input arrays and a size function through the
// pipeline (pipeline/pipeline.h) to the output arrays, every failure as one deltri::api::Error.
#include <exception>
#include <string>

#include "api/input_arrays.h"
#include "api/library_support.h"
#include "api/output_arrays.h"
#include "pipeline/pipeline.h"

namespace deltri {
namespace {

// The size function sees plain arrays; an exception it throws is carried past the pipeline and
// rethrown as it was.
struct SizeFunctionThrew {};

SizeTest size_test_of(const api::SizeFunction& size, std::exception_ptr& thrown) {
  return [&size, &thrown](const Point& a, const Point& b, const Point& c, double area) {
    const double org[2] = {a.x, a.y}, dest[2] = {b.x, b.y}, apex[2] = {c.x, c.y};
    try {
      return size(org, dest, apex, area);
    } catch (...) {
      thrown = std::current_exception();
      throw SizeFunctionThrew{};
    }
  };
}

api::Mesh run(const api::Input& input, const Options& sw, const api::SizeFunction& size, std::exception_ptr& thrown) {
  const int first_index = sw.zero_based ? 0 : 1;
  Pslg pslg = pslg_from_input(input, first_index, sw.poly);
  PipelineSource source;
  source.name = "input";
  source.is_poly = sw.poly;
  PreviousMesh previous;
  if (sw.refine) {
    previous = previous_from_input(input, first_index, sw.variable_area);
    source.previous = &previous;
  }
  const SizeTest test = size ? size_test_of(size, thrown) : SizeTest{};
  if (size) source.size_test = &test;
  RunReport report;
  report.options = &sw;
  const PipelineResult result = run_pipeline(pslg, source, sw, report);
  if (result.check_failed)
    throw api::Error(DELTRI_CHECK_FAILED, "C: the mesh is not consistent: " + report.check->summary());
  return output_arrays(result, sw, first_index, sw.poly);
}

}  // namespace

api::Mesh triangulate_parsed(const api::Input& input, const Options& sw, const api::SizeFunction& size) {
  std::exception_ptr thrown;
  try {
    return run(input, sw, size, thrown);
  } catch (const SizeFunctionThrew&) {
    std::rethrow_exception(thrown);
  } catch (...) {
    rethrow_as_library_error();
  }
}

api::Mesh api::triangulate(const Input& input, const std::string& switches, const SizeFunction& size) {
  return triangulate_parsed(input, parse_library_switches(switches, static_cast<bool>(size)), size);
}

}  // namespace deltri
