// The executable: arguments in, exit status out. Everything else happens in run().
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <system_error>
#include <vector>

#include "cli/run.h"
#include "options/switches.h"
#include "options/version.h"
#include "util/errors.h"

namespace {

using namespace deltri;

// f()'s exit status; an error it throws is printed as one line and mapped to its status.
template <class F>
int reporting_errors(F&& f) {
  try {
    return f();
  } catch (const RefusedSwitchError& e) {
    std::fprintf(stderr, "deltri: %s\n", e.what());
    return kExitInput;  // Triangle's status for the values it refuses
  } catch (const UsageError& e) {
    std::fprintf(stderr, "deltri: %s\n", e.what());
    return kExitUsage;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitInput;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitOutput;
  } catch (const MemoryError& e) {
    std::fprintf(stderr, "deltri: %s\n", e.what());
    return kExitInternal;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "deltri: out of memory\n");
    return kExitInternal;
  } catch (const std::system_error& e) {
    // Under a memory limit a worker thread's stack may be what cannot be had (EAGAIN).
    if (e.code() == std::errc::resource_unavailable_try_again) {
      std::fprintf(stderr, "deltri: out of memory (cannot start a thread)\n");
      return kExitInternal;
    }
    std::fprintf(stderr, "deltri: internal error: %s\n", e.what());
    return kExitInternal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "deltri: internal error: %s\n", e.what());
    return kExitInternal;
  }
}

// --each: every input meshed in turn as if alone, so a batch pays for one process instead of one
// per file. A failed input does not stop the others; the status is the first non-zero one, and
// the failures are counted at the end, where a batch script's log shows them.
int run_each(const Switches& all) {
  int status = kExitOk;
  std::vector<std::string> failed;
  for (const std::string& input : all.inputs) {
    Switches one = all;
    one.input = input;
    const int s = reporting_errors([&] { return run(one); });
    if (s == kExitOk) continue;
    if (status == kExitOk) status = s;
    failed.push_back(input + " (status " + std::to_string(s) + ")");
  }
  if (!failed.empty()) {
    std::string list;
    for (const std::string& f : failed) list += (list.empty() ? "" : ", ") + f;
    std::fprintf(stderr, "deltri: --each: %zu of %zu inputs did not end with status 0: %s\n", failed.size(),
                 all.inputs.size(), list.c_str());
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  return reporting_errors([&] {
    Switches switches = parse_switches(argc, argv);
    // The machine's core count, read once: each stage asking for it again cost a read of sysfs.
    switches.threads = threads_to_use(switches);
    if (switches.version) {
      std::printf("deltri %s\n", version());
      return kExitOk;
    }
    if (switches.man) {
      std::fputs(man_page().c_str(), stdout);
      return kExitOk;
    }
    if (switches.help || switches.input.empty()) {
      std::fputs(help_text().c_str(), switches.help ? stdout : stderr);
      return switches.help ? kExitOk : kExitUsage;
    }
    return switches.each ? run_each(switches) : run(switches);
  });
}
