// Removing the output temporaries when the run is interrupted (SIGINT, SIGTERM, SIGHUP).
//
// This is the program's one piece of process-wide mutable state, and it has to be: a signal is
// delivered to the process, and its handler can reach only what is global. It lives here in the
// CLI, not in the library (io/output_set.h only reports its temporary names to a listener).
// The handler is async-signal-safe: it walks a list prepared before the temporaries exist,
// unlinks each, restores the default action and raises the signal again, so the exit status
// still says which signal ended the run.
#pragma once

#include <string>
#include <vector>

namespace deltri {

// Installs the handlers (once) and makes `paths` the temporaries to remove; an empty list once
// they are renamed or removed. Not thread-safe: called from the thread that commits the outputs.
void set_interrupt_cleanup(const std::vector<std::string>& paths);

}  // namespace deltri
