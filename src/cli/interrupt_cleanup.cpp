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
  kRenaming = 1,  // finish the renames
  kHandling = 2,  // a handler is removing them: nothing may be renamed any more
  kFinishing = 3, // a handler is finishing the renames: the temporaries' locks are its until the process ends
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
  bool installed = false;
};

Registry& registry() {
  static Registry r;  // process-wide by necessity: see the header
  return r;
}

extern "C" void finish_or_remove_and_reraise(int signal_number) {
  Registry& r = registry();
  // Either this claims the files before any rename (and the committing thread will not start
  // renaming), or the renames have begun and this claims finishing them (and the committing
  // thread will not let go of the locks). A second signal while a handler runs finds kHandling
  // (remove again) or kFinishing (rename again): both harmless repeats.
  int phase = r.phase.load();
  while ((phase == kWriting && !r.phase.compare_exchange_weak(phase, kHandling)) ||
         (phase == kRenaming && !r.phase.compare_exchange_weak(phase, kFinishing))) {
  }
  const bool remove = phase == kWriting || phase == kHandling;
  const char* const* paths = r.published.load();
  const std::size_t n = r.count.load();
#ifdef DELTRI_HAVE_UNLINK
  for (std::size_t i = 0; paths && i < n; ++i) {
    // A temporary already renamed is no longer there: the call fails with ENOENT, harmlessly.
    if (remove) unlink(paths[2 * i]);
    else std::rename(paths[2 * i], paths[2 * i + 1]);
  }
#endif
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
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
  if (!r.installed && !r.storage.empty()) {
    for (const int s : {SIGINT, SIGTERM,
#ifdef SIGHUP
                        SIGHUP
#endif
         }) {
      // A signal the user chose to ignore (nohup) stays ignored.
      if (std::signal(s, finish_or_remove_and_reraise) == SIG_IGN) std::signal(s, SIG_IGN);
    }
    r.installed = true;
  }
  r.published.store(r.pointers.data());
  r.count.store(r.pointers.size() / 2);
}

bool begin_interrupt_renames() {
  Registry& r = registry();
  int phase = kWriting;
  return r.phase.compare_exchange_strong(phase, kRenaming);
}

void end_interrupt_renames() {
  Registry& r = registry();
  int phase = kRenaming;
  if (!r.phase.compare_exchange_strong(phase, kWriting)) {
    // A handler on another thread is finishing the renames and then ends the process; letting go
    // of the temporaries' locks now would let another run take the names it is renaming.
    for (;;) {
#ifdef DELTRI_HAVE_UNLINK
      pause();
#endif
    }
  }
}

CommitListener interrupt_listener() { return {set_interrupt_cleanup, begin_interrupt_renames, end_interrupt_renames}; }

}  // namespace deltri
