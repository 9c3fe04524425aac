#include "cli/interrupt_cleanup.h"

#include <atomic>
#include <csignal>

#if __has_include(<unistd.h>)
#include <unistd.h>
#define DELTRI_HAVE_UNLINK 1
#endif

namespace deltri {
namespace {

// The paths are copied into `storage` in normal context; the handler sees them only through
// `published` and `count`, which are set after the copy is complete and cleared before the next
// change, so it never reads a list being rebuilt. Lock-free atomics are async-signal-safe.
struct Registry {
  std::vector<std::string> storage;
  std::vector<const char*> pointers;
  std::atomic<const char* const*> published{nullptr};
  std::atomic<std::size_t> count{0};
  bool installed = false;
};

Registry& registry() {
  static Registry r;  // process-wide by necessity: see the header
  return r;
}

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  Registry& r = registry();
  const char* const* paths = r.published.load();
  const std::size_t n = r.count.load();
#ifdef DELTRI_HAVE_UNLINK
  for (std::size_t i = 0; paths && i < n; ++i) unlink(paths[i]);
#endif
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace

void set_interrupt_cleanup(const std::vector<std::string>& paths) {
  Registry& r = registry();
  r.count.store(0);
  r.published.store(nullptr);
  r.storage.clear();
  r.pointers.clear();
  for (const std::string& p : paths)
    if (!p.empty()) r.storage.push_back(p);
  for (const std::string& p : r.storage) r.pointers.push_back(p.c_str());
  if (!r.installed && !r.storage.empty()) {
    for (const int s : {SIGINT, SIGTERM,
#ifdef SIGHUP
                        SIGHUP
#endif
         }) {
      // A signal the user chose to ignore (nohup) stays ignored.
      if (std::signal(s, remove_temporaries_and_reraise) == SIG_IGN) std::signal(s, SIG_IGN);
    }
    r.installed = true;
  }
  r.published.store(r.pointers.data());
  r.count.store(r.pointers.size());
}

}  // namespace deltri
