// The executable: arguments in, exit status out. Everything else happens in run().
#include <cstdio>
#include <exception>
#include <new>
#include <system_error>

#include "cli/run.h"
#include "options/switches.h"
#include "options/version.h"
#include "util/errors.h"

int main(int argc, char** argv) {
  using namespace deltri;
  try {
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
    return run(switches);
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
