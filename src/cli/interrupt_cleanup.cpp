#include "cli/interrupt_cleanup.h"

#include <atomic>
#include <csignal>
#include <cstdio>

#if __has_include(<unistd.h>)
#include <unistd.h>
#define DELTRI_HAVE_UNLINK 1
#endif

namespace deltri {
namespace {

// What the handler is to do with the published files.
enum Phase : int {
  kWriting = 0,   // remove the temporaries
  kRenaming = 1,  // leave them: the committing thread puts the set in place, then ends the run
  kHandling = 2,  // a handler is removing them: nothing may be renamed any more
  kDeferred = 3,  // a signal came while renaming: the committing thread ends the run by it afterwards
};

// The paths are copied into `storage` in normal context; the handler sees them only through
// `published` and `count`, which are set after the copy is complete and cleared before the next
// change, so it never reads a list being rebuilt. Lock-free atomics are async-signal-safe.
struct Registry {
  std::vector<std::string> storage;  // temporary, final, temporary, final, ...
  std::vector<const char*> pointers;
  std::atomic<const char* const*> published{nullptr};
  std::atomic<std::size_t> count{0};  // pairs
  std::atomic<int> phase{kWriting};
  std::atomic<int> deferred_signal{0};
  bool installed = false;
};

Registry& registry() {
  static Registry r;  // process-wide by necessity: see the header
  return r;
}

extern "C" void remove_or_defer(int signal_number) {
  Registry& r = registry();
  // Either this claims the files before any rename (and the committing thread will not start
  // renaming), or the renames have begun and this leaves the signal to the committing thread,
  // which ends the run by it once the set is in place. A second signal while a handler removes
  // finds kHandling (remove again: a harmless repeat); one after a deferred one, kDeferred.
  r.deferred_signal.store(signal_number);
  int phase = r.phase.load();
  while ((phase == kWriting && !r.phase.compare_exchange_weak(phase, kHandling)) ||
         (phase == kRenaming && !r.phase.compare_exchange_weak(phase, kDeferred))) {
  }
  if (phase == kRenaming || phase == kDeferred) return;
  const char* const* paths = r.published.load();
  const std::size_t n = r.count.load();
#ifdef DELTRI_HAVE_UNLINK
  for (std::size_t i = 0; paths && i < n; ++i) unlink(paths[2 * i]);
#endif
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// The handlers, once: before the first temporary has a name, or before the first file is put in
// place where none ever has one (unnamed files).
void install(Registry& r) {
  if (r.installed) return;
  for (const int s : {SIGINT, SIGTERM,
#ifdef SIGHUP
                      SIGHUP
#endif
       }) {
    // A signal the user chose to ignore (nohup) stays ignored.
    if (std::signal(s, remove_or_defer) == SIG_IGN) std::signal(s, SIG_IGN);
  }
  r.installed = true;
}

}  // namespace

void set_interrupt_cleanup(const std::vector<std::string>& temporaries, const std::vector<std::string>& finals) {
  Registry& r = registry();
  r.count.store(0);
  r.published.store(nullptr);
  r.storage.clear();
  r.pointers.clear();
  for (std::size_t k = 0; k < temporaries.size() && k < finals.size(); ++k)
    if (!temporaries[k].empty()) {
      r.storage.push_back(temporaries[k]);
      r.storage.push_back(finals[k]);
    }
  for (const std::string& p : r.storage) r.pointers.push_back(p.c_str());
  if (!r.storage.empty()) install(r);
  r.published.store(r.pointers.data());
  r.count.store(r.pointers.size() / 2);
}

bool begin_interrupt_renames() {
  Registry& r = registry();
  install(r);
  int phase = kWriting;
  return r.phase.compare_exchange_strong(phase, kRenaming);
}

void end_interrupt_renames() {
  Registry& r = registry();
  int phase = kRenaming;
  if (r.phase.compare_exchange_strong(phase, kWriting)) return;
  // A signal came while the set was put in place; it is whole now: the run ends by that signal.
  const int signal_number = r.deferred_signal.load();
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

CommitListener interrupt_listener() { return {set_interrupt_cleanup, begin_interrupt_renames, end_interrupt_renames}; }

}  // namespace deltri
