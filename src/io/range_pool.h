// Lets the threads of one OutputSet commit share the formatting of large files. A thread writing
// a file whose body comes as LineRanges formats ranges itself while the threads whose own files
// are done format the next ranges into buffers of their own; the buffers are written to the file
// strictly in order, with at most a few in flight, so the bytes are those of one thread writing
// the ranges one after another and the memory stays well under a megabyte.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <vector>

#include "io/text_writer.h"

namespace deltri {

class RangeJob;

class RangePool {
 public:
  // `workers`: how many threads run files and, once done with their files, help().
  explicit RangePool(std::size_t workers) : workers_(workers), working_(workers) {}
  RangePool(const RangePool&) = delete;
  RangePool& operator=(const RangePool&) = delete;

  // Writes `ranges` to `sink` in order, formatting ranges on this thread and on helping ones.
  // Throws what a format or a sink write threw (the first failure; later ranges are dropped).
  void write(ByteSink& sink, const LineRanges& ranges);
  // Called by a worker that will start no further file: formats ranges of the other workers'
  // files until every worker has left its files.
  void help();
  // Called for a worker whose thread could not be started: it will never help.
  void absent();

 private:
  RangeJob* open_job();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<RangeJob*> jobs_;
  const std::size_t workers_;
  std::size_t working_;  // workers not yet in help()
};

}  // namespace deltri
