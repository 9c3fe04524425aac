// What an interrupted run (SIGINT, SIGTERM, SIGHUP) does with its output temporaries.
//
// This is the program's one piece of process-wide mutable state, and it has to be: a signal is
// delivered to the process, and its handler can reach only what is global. It lives here in the
// CLI, not in the library (io/output_set.h only reports its temporaries to a listener).
//
// While the temporaries are being written, the handler removes them: the old outputs stay as they
// were (unnamed temporaries need nothing: the kernel frees them with the process). Once the files
// are being put in place (renamed, or linked at their names), removing what is left would leave a
// mixed or partial set (a new .node beside an old .ele), so the handler only notes the signal and
// returns: the committing thread puts the whole set in place and then ends the run by that signal
// (end_interrupt_renames), and the new set is complete. Finishing was chosen over rolling back: a
// rollback would need a copy of every old file kept aside until the end, and its own renames could
// be cut short just the same; what is left are a few system calls. Blocking the signals around the
// renames would not do: a signal to the process goes to any thread that has not blocked it; noting
// it works on whichever thread the handler runs.
//
// Which of the two the handler does is decided by one atomic exchange, so that the handler and the
// thread about to start renaming can never both act (the handler may run on another thread). The
// handler is async-signal-safe: it walks lists prepared before the temporaries exist, then
// restores the default action and raises the signal again, so the exit status still says which
// signal ended the run.
#pragma once

#include <string>
#include <vector>

#include "io/output_set.h"

namespace deltri {

// Installs the handlers (once) and makes `temporaries` (with their final names) the files to
// remove: only those this run holds, since a temporary's name is shared with any other run
// writing the same output; empty lists once they are renamed or removed. Not thread-safe: called from the thread
// that commits the outputs.
void set_interrupt_cleanup(const std::vector<std::string>& temporaries, const std::vector<std::string>& finals);

// Called before the first rename or link at a final name (installs the handlers if no temporary
// did): from then on a signal waits for end_interrupt_renames. false if a signal is already being
// handled (then nothing may be put in place).
bool begin_interrupt_renames();

// Called once the set is in place (or the renames failed): back to removing. If a signal came
// meanwhile, ends the run by it here.
void end_interrupt_renames();

// The two above, as OutputSet::commit() takes them.
CommitListener interrupt_listener();

}  // namespace deltri
