// How much memory this process may use: the machine's physical memory, or less where a limit says
// so (ulimit -v or -d, a cgroup's memory.max). The command line hands it to refinement
// (RefineOptions::memory_budget), so that no input and no switch value makes deltri grow until
// the kernel kills it.
#pragma once

namespace deltri {

// Bytes; 0 when nothing could be learnt.
double memory_budget();

}  // namespace deltri
