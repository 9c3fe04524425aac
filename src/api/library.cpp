// deltri::api::triangulate: the switch string, the input arrays and a size function through the
// pipeline (api/pipeline.h) to the output arrays, every failure as one deltri::api::Error.
#include <exception>
#include <new>
#include <string>
#include <system_error>
#include <vector>

#include "api/input_arrays.h"
#include "api/output_arrays.h"
#include "api/pipeline.h"
#include "pslg/errors.h"

namespace deltri {
namespace {

// A bare u (no length after it) asks for the caller's size test, as Triangle's u does; the
// command-line parser knows only u<length>, so the library takes a bare one out first.
std::string without_bare_u(const std::string& switches, bool& bare_u) {
  std::string rest;
  for (std::size_t i = 0; i < switches.size(); ++i) {
    const char next = i + 1 < switches.size() ? switches[i + 1] : '\0';
    if (switches[i] == 'u' && !((next >= '0' && next <= '9') || next == '.')) {
      bare_u = true;
      continue;
    }
    rest += switches[i];
  }
  return rest;
}

Switches parse_library_switches(const std::string& given, bool size_function) {
  bool bare_u = false;
  std::string word = without_bare_u(given, bare_u);
  if (!word.empty() && word[0] == '-') word.erase(0, 1);
  if (bare_u && !size_function)
    throw api::Error(DELTRI_USAGE_ERROR, "u: a bare u asks for a size test, and none was given (or give a length, u0.05)");
  std::vector<std::string> args = {"deltri"};
  if (!word.empty()) args.push_back("-" + word);
  args.push_back("input");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  Switches sw = parse_switches(static_cast<int>(argv.size()), argv.data());
  sw.quiet = true;
  return sw;
}

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

std::string without_suffix(std::string text, const std::string& suffix) {
  if (text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0)
    text.erase(text.size() - suffix.size());
  return text;
}

api::Mesh run(const api::Input& input, const std::string& switches, const api::SizeFunction& size,
              std::exception_ptr& thrown) {
  const Switches sw = parse_library_switches(switches, static_cast<bool>(size));
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
  report.switches = &sw;
  const PipelineResult result = run_pipeline(pslg, source, sw, report);
  if (result.check_failed)
    throw api::Error(DELTRI_CHECK_FAILED, "C: the mesh is not consistent: " + report.check->summary());
  return output_arrays(result, sw, first_index, sw.poly);
}

}  // namespace

api::Mesh api::triangulate(const Input& input, const std::string& switches, const SizeFunction& size) {
  std::exception_ptr thrown;
  try {
    return run(input, switches, size, thrown);
  } catch (const Error&) {
    throw;
  } catch (const SizeFunctionThrew&) {
    std::rethrow_exception(thrown);
  } catch (const InputError& e) {
    throw Error(DELTRI_INPUT_ERROR, e.what());
  } catch (const UsageError& e) {
    throw Error(DELTRI_USAGE_ERROR, without_suffix(e.what(), " (see deltri -h)"));
  } catch (const MemoryError& e) {
    throw Error(DELTRI_MEMORY_ERROR, e.what());
  } catch (const std::bad_alloc&) {
    throw Error(DELTRI_MEMORY_ERROR, "out of memory");
  } catch (const std::system_error& e) {
    if (e.code() == std::errc::resource_unavailable_try_again) throw Error(DELTRI_MEMORY_ERROR, "out of memory (cannot start a thread)");
    throw Error(DELTRI_INTERNAL_ERROR, std::string("internal error: ") + e.what());
  } catch (const std::exception& e) {
    throw Error(DELTRI_INTERNAL_ERROR, std::string("internal error: ") + e.what());
  }
}

}  // namespace deltri
