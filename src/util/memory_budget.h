// How much memory this process may use: the machine's physical memory, or less where a limit says
// so (ulimit -v or -d, a cgroup's memory.max). Refinement asks for it once a run may need it
// (RefineOptions::probe_memory, which the command line and the library set), so that no input and
// no switch value makes deltri grow until the kernel kills it.
#pragma once

namespace deltri {

// Bytes; 0 when nothing could be learnt.
double memory_budget();

}  // namespace deltri
