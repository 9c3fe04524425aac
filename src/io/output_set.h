// All-or-nothing output: a run either leaves every output file in place or changes nothing.
// Each file is first written in full to a temporary (unnamed where the file system allows, else
// named in its own directory), so it gets its final name (a link or an atomic rename) only once
// every byte of every file is safely written.
#pragma once

#include <functional>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/text_writer.h"

namespace deltri {

// What commit() met besides its own files, for the caller to report.
struct CommitNotes {
  // Another run held the temporary of one of this run's output names, so this one waited for it
  // (the other run's set is now wholly replaced by this one's). Runs writing other names never wait.
  bool waited_for_other_run = false;
  // Output files that changed on disk (another process replaced them) while this run was writing.
  std::size_t replaced_meanwhile = 0;
  // Temporaries of earlier runs that died before renaming them (killed: nothing removed them),
  // found at this run's own temporary names and reused.
  std::size_t stale_temporaries_removed = 0;
};

// What commit() tells the CLI, which keeps it where a signal handler can reach it (the library
// itself keeps no global state).
struct CommitListener {
  // Every temporary path this run holds so far ("" for one not yet held) and its final name; told
  // again as each temporary is taken, so a handler only ever removes temporaries of this run (a
  // temporary's name is shared with other runs writing the same output); two empty lists once
  // nothing is left to remove or rename.
  std::function<void(const std::vector<std::string>& temporaries, const std::vector<std::string>& finals)> pending;
  // Asked just before the first rename or link at a final name. true: from now on an interrupted
  // run must put the whole set in place rather than remove what is left (a mix of new and old
  // files is never left); false: the run is already being interrupted and nothing may be renamed.
  std::function<bool()> begin_renames;
  // Told once the set is in place (or the renames failed), before the temporaries' locks are let
  // go. Need not return if a signal came meanwhile (the run ends by it; the set is whole).
  std::function<void()> end_renames;
};

class RangePool;

// A file by device and inode.
using FileId = std::pair<std::uint64_t, std::uint64_t>;

class OutputSet {
 public:
  // How many threads write at once (the command line passes --threads; two is the target
  // machine's cores). A large file's body (LineRanges) is formatted by whichever of them is free,
  // so the writing takes about the total work divided by the threads rather than as long as the
  // largest file.
  static constexpr std::size_t kDefaultWorkers = 2;
  explicit OutputSet(std::size_t workers = kDefaultWorkers) : workers_(workers) {}

  // The writers for a mesh of `items` vertices and elements with `threads` allowed: one below
  // kLeastItemsForThreads, where a second thread costs more than it saves (starting and joining
  // it, and on a busy machine the wait to be scheduled, against well under a millisecond of
  // formatting).
  static constexpr std::size_t kLeastItemsForThreads = 32768;
  static std::size_t workers_for(std::size_t items, std::size_t threads) {
    return items < kLeastItemsForThreads ? 1 : threads;
  }

  // A file whose text is already in memory.
  void add(std::string final_path, std::string contents);
  // A file produced during commit(): `produce` writes into a sink that goes straight to the
  // temporary file, so a large .ele never has to exist as one string.
  void add_stream(std::string final_path, std::function<void(ByteSink&)> produce);

  // The name that stands for standard output: such a file is produced in memory with the others
  // and written out only after every real file is in place, so a failed run prints nothing.
  static constexpr const char* kStandardOutput = "-";

  // Writes every file, then renames them into place. Up to `workers` temporaries are written at
  // once, and ranges of a large file by several threads (the producers must not modify shared
  // state). Throws OutputError("path: reason") if any
  // write, flush or close fails (with several failures: the one of the earliest-added file);
  // then every temporary is removed and existing files are untouched. (Should a rename itself
  // fail after others succeeded, those stay renamed: the remaining renames are within the same
  // directories and in practice cannot fail.)
  //
  // Two outputs naming the same file (also through another spelling of its directory) are refused
  // with OutputError before anything is written.
  //
  // Where every output name and its temporary's name are free (a batch's fresh folder) and the
  // file system makes unnamed files (O_TMPFILE), each file is written unnamed and then linked at
  // its final name: no temporary name, lock or rename. Should another run (or process) take one of
  // the names meanwhile, the run puts its whole set in place again by temporaries, as below, so
  // the last run leaves all of its set (put_unnamed in the .cpp has the argument).
  //
  // Otherwise temporaries are named FINAL.tmp.HASH (16 hex digits of the final file name's hash),
  // FINAL cut short where the whole would exceed the directory's longest file name (so any output
  // name the file system takes can be written). A temporary is held (an exclusive flock on the
  // open file) from its creation until after the renames, the temporaries taken in one order
  // (directory, then name) by every run. Two runs writing one output name meet at its temporary:
  // the later waits until the earlier has renamed its whole set, so they leave one run's complete
  // set, never a mix, while runs writing other names never wait for each other; no lock file and
  // no directory scan. A temporary found at this run's name with no holder (a killed run's) is
  // reused.
  CommitNotes commit(const CommitListener& listener = {});

  std::size_t size() const { return files_.size(); }

  // The files this run reads: commit() refuses an output that is one of them (by another name or
  // through a symbolic link too) with OutputError before anything is written. Checked in the one
  // look commit() takes at each output name before writing, not in a second one of its own.
  void keep_intact(std::vector<FileId> inputs) { inputs_ = std::move(inputs); }

 private:
  struct File {
    std::string final_path;
    std::string contents;
    std::function<void(ByteSink&)> produce;  // empty: use contents
  };
  struct Plan;
  bool put_unnamed(Plan& p, const CommitListener& listener);
  void put_by_temporaries(Plan& p, const CommitListener& listener, bool renames_begun);
  static void write_temporary(File& f, const std::string& temp_path, int fd, RangePool* pool);
  static void write_standard_output(File& f);
  std::size_t workers_;
  std::vector<File> files_;
  std::vector<FileId> inputs_;
};

}  // namespace deltri
