#include "io/output_set.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>
#include <thread>
#include <tuple>
#include <utility>

#include "io/range_pool.h"
#include "util/errors.h"

#if __has_include(<sys/file.h>) && __has_include(<unistd.h>)
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#define DELTRI_POSIX_OUTPUT 1
#endif

namespace deltri {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& reason) { throw OutputError(path + ": " + reason); }

std::string errno_text(int error) { return error ? std::strerror(error) : "write failed"; }

std::string directory_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

std::string file_name_of(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// The longest file name the directory takes (255 on most file systems).
[[maybe_unused]] std::size_t longest_name(const std::string& dir) {
#ifdef DELTRI_POSIX_OUTPUT
  errno = 0;
  const long n = pathconf(dir.c_str(), _PC_NAME_MAX);
  if (n > 0) return static_cast<std::size_t>(n);
#else
  (void)dir;
#endif
  return 255;
}

// How much of a final file name a temporary keeps in front of `suffix_size` more characters: all
// of it when that fits in the directory's longest name, else as much as fits. Without the cut an
// output whose name is within a few dozen characters of the limit could not be written at all.
std::size_t stem_size(std::size_t final_size, std::size_t suffix_size, std::size_t longest) {
  return std::min(final_size, longest > suffix_size ? longest - suffix_size : std::size_t{1});
}

// Where an output lands: its directory's device and inode (however the directory is spelt: a
// symbolic link, a bind mount, "." or its full path) and its file name. Two outputs with the same
// target are one file; with the directory not there yet, its spelling stands in.
struct Target {
  std::string dir;  // as first spelt
  std::uint64_t device = 0, inode = 0;
  bool identified = false;
  std::string name;
  std::tuple<bool, std::uint64_t, std::uint64_t, std::string, std::string> key() const {
    return {identified, device, inode, identified ? std::string() : dir, name};
  }
  bool operator<(const Target& o) const { return key() < o.key(); }
  bool operator==(const Target& o) const { return key() == o.key(); }
};

// The targets of `paths`. A directory is asked for its identity (once, however many outputs it
// holds) only where the outputs spell two or more directories: with one spelling, the spelling
// tells the files apart and orders them as the identity would (by name within the directory), so
// the order every run takes its temporaries in stays one order.
std::vector<Target> targets_of(const std::vector<std::string>& paths) {
  std::vector<Target> targets;
  for (const std::string& path : paths) targets.push_back({directory_of(path), 0, 0, false, file_name_of(path)});
  const bool one_spelling = std::all_of(targets.begin(), targets.end(), [&](const Target& t) { return t.dir == targets[0].dir; });
  if (one_spelling) return targets;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    Target& t = targets[k];
    const auto known = std::find_if(targets.begin(), targets.begin() + static_cast<std::ptrdiff_t>(k), [&](const Target& o) { return o.dir == t.dir; });
    if (known != targets.begin() + static_cast<std::ptrdiff_t>(k)) {
      std::tie(t.identified, t.device, t.inode) = std::tuple{known->identified, known->device, known->inode};
      continue;
    }
#ifdef DELTRI_POSIX_OUTPUT
    struct stat st;
    if (stat(t.dir.c_str(), &st) == 0) {
      t.device = static_cast<std::uint64_t>(st.st_dev);
      t.inode = static_cast<std::uint64_t>(st.st_ino);
      t.identified = true;
    }
#endif
  }
  return targets;
}

// FNV-1a of a file name: the same in every build, so that two deltri programs agree on the name
// of the temporary of one output (where the two runs meet).
std::uint64_t name_hash(const std::string& name) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : name) h = (h ^ c) * 1099511628211ull;
  return h;
}

// FINAL.tmp.HASH, HASH the final file name's name_hash in 16 hex digits. A name made from the
// final name alone is what lets a later run of the same output find what a killed run left (no
// directory scan) and makes two runs writing one output meet at one file, whose lock puts them in
// turn (no lock file); the hash keeps names apart where FINAL has to be cut short.
constexpr std::size_t kAnyLength = SIZE_MAX;  // a directory's longest name not asked: the whole name
std::string temporary_name(const std::string& final_path, std::size_t longest) {
  const std::string name = file_name_of(final_path);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(name_hash(name)));
  const std::string suffix = std::string(".tmp.") + hex;
  const std::string dir_part = final_path.substr(0, final_path.size() - name.size());
  return dir_part + name.substr(0, stem_size(name.size(), suffix.size(), longest)) + suffix;
}

constexpr int kNameTooLong = -2;  // hold_temporary's answer to a name the directory does not take

#ifdef DELTRI_POSIX_OUTPUT
// Whether the open file `fd` is still the one at `path` (another run may have renamed it away
// between this run's open and its lock).
bool still_at(int fd, const std::string& path) {
  struct stat mine, there;
  return fstat(fd, &mine) == 0 && stat(path.c_str(), &there) == 0 && mine.st_dev == there.st_dev &&
         mine.st_ino == there.st_ino;
}

#ifdef O_TMPFILE
#define DELTRI_UNNAMED_OUTPUT 1
// Links the unnamed file `fd` at `path`: 0, or the errno (EEXIST: the name is taken).
int link_unnamed(int fd, const std::string& path) {
  if (linkat(fd, "", AT_FDCWD, path.c_str(), AT_EMPTY_PATH) == 0) return 0;
  if (errno == EEXIST) return EEXIST;
  char self[40];  // AT_EMPTY_PATH asks for CAP_DAC_READ_SEARCH; /proc does not
  std::snprintf(self, sizeof self, "/proc/self/fd/%d", fd);
  return linkat(AT_FDCWD, self, AT_FDCWD, path.c_str(), AT_SYMLINK_FOLLOW) == 0 ? 0 : errno;
}

// Creates `temp` already locked: the inode is made unnamed (O_TMPFILE), locked, then linked at the
// name. Making the inode is most of the cost of creating a file (ext4 without a journal steps past
// every inode freed in the last minutes), and an O_CREAT open does it holding the directory's lock,
// so runs creating files in one folder took turns at it; an unnamed inode is made without that
// lock. Locked before it has a name, the file is never seen unlocked. Returns -1 where the kernel or
// file system does not allow this (then `works` is cleared: the run's other outputs go by name at
// once), or the name is taken: the caller then goes by the name; kNameTooLong for a name longer
// than the directory takes.
int create_locked(const std::string& temp, bool& works) {
  const int fd = open(directory_of(temp).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd < 0) {
    works = false;
    return -1;
  }
  if (flock(fd, LOCK_EX | LOCK_NB) == 0) {
    const int error = link_unnamed(fd, temp);
    if (error == 0) return fd;
    if (error == ENAMETOOLONG) {
      close(fd);
      return kNameTooLong;
    }
    works = error == EEXIST;
  } else {
    works = false;
  }
  close(fd);
  return -1;
}
#endif

// Opens `temp` for writing, created if absent, locked exclusively and still at its name; returns
// the descriptor, which holds the lock until it is closed. `waited`: another run held it first.
// `stale`: a file with no holder was there (a killed run's), now emptied for reuse.
// Where the file system has no flock the temporary is used unlocked, as a run alone would.
// `unnamed`: whether to try create_locked first (cleared where it cannot work). kNameTooLong
// (nothing made) where `temp` is longer than the directory takes.
int hold_temporary(const std::string& temp, const std::string& final_path, bool& waited, bool& stale, bool& unnamed) {
#ifdef O_TMPFILE
  if (unnamed)
    if (const int fd = create_locked(temp, unnamed); fd >= 0 || fd == kNameTooLong) return fd;
#else
  (void)unnamed;
#endif
  for (;;) {
    bool fresh = true;
    int fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0 && errno == EEXIST) {
      fresh = false;
      fd = open(temp.c_str(), O_WRONLY | O_CLOEXEC | O_NOFOLLOW);
      if (fd < 0 && errno == ENOENT) continue;  // renamed or removed meanwhile: create it now
    }
    if (fd < 0 && errno == ENAMETOOLONG) return kNameTooLong;
    if (fd < 0) fail(final_path, "cannot be created: " + errno_text(errno));
    if (flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
      waited = true;
      while (flock(fd, LOCK_EX) != 0 && errno == EINTR) {
      }
    }
    if (!still_at(fd, temp)) {
      close(fd);  // its holder renamed or removed it: take the file now at that name
      continue;
    }
    stale = stale || !fresh;
    if (!fresh && ftruncate(fd, 0) != 0) {
      const int error = errno;
      close(fd);
      fail(final_path, "cannot be created: " + errno_text(error));
    }
    return fd;
  }
}
#endif

#ifdef DELTRI_POSIX_OUTPUT
// A file's inode, size and time as file_identity() tells them.
std::string identity_text(const struct stat& st) {
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
         std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
}
#endif

// An identity of what is at `path` now (inode, size and time; of a symbolic link itself, which is
// what a rename replaces), to see whether another process replaced it; empty when nothing is
// there. Throws OutputError when it is something a rename could not replace (a directory, say), or
// (with `inputs`) one of the files this run reads, also through a symbolic link.
std::string file_identity(const std::string& path, const std::vector<FileId>* inputs = nullptr) {
#ifdef DELTRI_POSIX_OUTPUT
  struct stat st;
  if (lstat(path.c_str(), &st) != 0) return {};
  if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode)) fail(path, "cannot be replaced: it exists and is not a regular file");
  if (inputs && !inputs->empty()) {
    struct stat target = st;
    if (S_ISLNK(st.st_mode) && stat(path.c_str(), &target) != 0) target = st;
    const FileId id{static_cast<std::uint64_t>(target.st_dev), static_cast<std::uint64_t>(target.st_ino)};
    if (std::find(inputs->begin(), inputs->end(), id) != inputs->end())
      fail(path, "is an input of this run, not overwritten (no files written)");
  }
  return identity_text(st);
#else
  (void)inputs;
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  if (!ec && status.type() != std::filesystem::file_type::not_found && status.type() != std::filesystem::file_type::regular &&
      status.type() != std::filesystem::file_type::symlink)
    fail(path, "cannot be replaced: it exists and is not a regular file");
  return {};
#endif
}

// Writes to a held temporary file through a buffer of its own of up to 64 KiB (a small output is
// one write), reporting failures under the final name the user knows. The buffer grows from 8 KiB
// as the output does: a small run's three 64 KiB buffers took heap pages for a few KiB each. The
// descriptor stays open after close(): its lock is held until the renames are done.
class FileSink final : public ByteSink {
 public:
  FileSink(const std::string& temp_path, int fd, const std::string& final_path, RangePool* pool)
      : final_path_(final_path), pool_(pool), fd_(fd) {
#ifndef DELTRI_POSIX_OUTPUT
    errno = 0;
    file_ = std::fopen(temp_path.c_str(), "wb");
    if (!file_) fail(final_path_, "cannot be created: " + errno_text(errno));
#else
    (void)temp_path;
#endif
  }
  ~FileSink() override {
    if (file_) std::fclose(file_);
  }
  void write(const char* data, std::size_t size) override {
    if (size == 0) return;  // no buffer may be there yet to copy nothing into
    if (size > capacity_ - used_) grow(used_ + size);
    if (size > capacity_ - used_) {
      flush();
      if (size >= kBuffer) return put(data, size);
    }
    std::memcpy(buffer_.get() + used_, data, size);
    used_ += size;
  }
  void write_ranges(const LineRanges& ranges) override {
    if (pool_) pool_->write(*this, ranges);
    else ByteSink::write_ranges(ranges);
  }
  void close() {
    flush();
    if (file_ && std::fclose(std::exchange(file_, nullptr)) != 0) fail(final_path_, errno_text(errno));
  }

 private:
  void flush() {
    put(buffer_.get(), used_);
    used_ = 0;
  }
  // Doubles the buffer until it holds `wanted` bytes or reaches kBuffer; what it holds is kept.
  void grow(std::size_t wanted) {
    std::size_t capacity = capacity_;
    while (capacity < kBuffer && capacity < wanted) capacity = capacity ? 2 * capacity : kFirstBuffer;
    if (capacity == capacity_) return;
    auto bigger = std::make_unique_for_overwrite<char[]>(capacity);
    if (used_ > 0) std::memcpy(bigger.get(), buffer_.get(), used_);
    buffer_ = std::move(bigger);
    capacity_ = capacity;
  }
  void put(const char* data, std::size_t size) {
    while (size > 0) {
      errno = 0;
#ifdef DELTRI_POSIX_OUTPUT
      const ssize_t n = ::write(fd_, data, size);
      if (n < 0 && errno == EINTR) continue;
#else
      const long n = static_cast<long>(std::fwrite(data, 1, size, file_));
#endif
      if (n <= 0) fail(final_path_, errno_text(errno));
      data += n;
      size -= static_cast<std::size_t>(n);
    }
  }
  static constexpr std::size_t kBuffer = 65536;
  static constexpr std::size_t kFirstBuffer = 8192;
  std::string final_path_;
  RangePool* pool_;
  int fd_;
  std::FILE* file_ = nullptr;  // without POSIX: the temporary, opened by name
  std::size_t used_ = 0;
  std::size_t capacity_ = 0;
  std::unique_ptr<char[]> buffer_;
};

void remove_quietly(const std::vector<std::string>& paths) {
  std::error_code ignored;
  for (const auto& p : paths)
    if (!p.empty()) std::filesystem::remove(p, ignored);  // empty: already renamed into place
}

}  // namespace

void OutputSet::add(std::string final_path, std::string contents) {
  files_.push_back({std::move(final_path), std::move(contents), {}});
}

void OutputSet::add_stream(std::string final_path, std::function<void(ByteSink&)> produce) {
  files_.push_back({std::move(final_path), {}, std::move(produce)});
}

namespace {

// Runs task(k) for k = 0, 1, ..., count - 1 on up to `workers` threads, starting them in order
// of k; once a task has thrown, no further task starts. Returns the exception of the lowest k that
// threw, if any. Every task skipped after a failure comes after the failed one, so that is the
// exception a plain loop over k would have stopped at. With `pool`, a thread out of tasks helps
// format the ranges of files the others are still writing.
std::exception_ptr run_in_order(std::size_t count, std::size_t workers, const std::function<void(std::size_t)>& task,
                                RangePool* pool = nullptr) {
  std::vector<std::exception_ptr> errors(count);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  const auto work = [&] {
    for (std::size_t k; !failed.load() && (k = next++) < count;) {
      try {
        task(k);
      } catch (...) {
        errors[k] = std::current_exception();
        failed = true;
      }
    }
    if (pool) pool->help();
  };
  {
    std::vector<std::jthread> helpers;
    for (std::size_t w = 1; w < workers; ++w) {
      try {
        helpers.emplace_back(work);
      } catch (const std::system_error&) {
        for (; w < workers; ++w)
          if (pool) pool->absent();  // no thread to be had: fewer workers do the same work
        break;
      }
    }
    work();
  }  // joins the helpers
  for (std::exception_ptr& error : errors)
    if (error) return error;
  return nullptr;
}

}  // namespace

void OutputSet::write_standard_output(File& f) {
  if (f.produce) {
    StringSink sink(f.contents);
    f.produce(sink);
    f.produce = nullptr;
  }
}

void OutputSet::write_temporary(File& f, const std::string& temp_path, int fd, RangePool* pool) {
  if (f.final_path == kStandardOutput) return write_standard_output(f);
  FileSink sink(temp_path, fd, f.final_path, pool);
  if (f.produce) f.produce(sink);
  else sink.write(f.contents.data(), f.contents.size());
  sink.close();
}

namespace {

// Two outputs of one run naming the same file would leave only one of them, and which one would
// depend on the order of the renames: refused, as an output naming an input is. `paths[k]` is
// where `targets[k]` was spelt.
void refuse_duplicate_names(const std::vector<std::string>& paths, const std::vector<Target>& targets) {
  std::vector<std::size_t> order(targets.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return targets[a] < targets[b]; });
  for (std::size_t i = 1; i < order.size(); ++i)
    if (targets[order[i]] == targets[order[i - 1]]) {
      const std::string& first = paths[std::min(order[i], order[i - 1])];
      const std::string& second = paths[std::max(order[i], order[i - 1])];
      fail(second, first == second ? "named by two outputs of this run (no files written)"
                                   : "the same file as " + first + ", another output of this run (no files written)");
    }
}


// Renames temps[k] onto finals[k] for the files in `order` ("" temporaries skipped, and cleared
// once renamed). The last one in the order, whose temporary another run writing the same names
// takes last, is renamed after all the others: such a run can start its own renames only once
// this run's set is wholly in place. Renaming over an existing file frees the old one's blocks and
// cached pages, which for a large .ele takes tens of milliseconds: worth sharing between threads.
std::exception_ptr rename_into_place(std::vector<std::string>& temps, const std::vector<std::string>& finals,
                                     const std::vector<std::size_t>& order, std::size_t workers) {
  const auto rename_one = [&](std::size_t k) {
    if (temps[k].empty()) return;
    std::error_code ec;
    std::filesystem::rename(temps[k], finals[k], ec);
    if (ec) fail(finals[k], "cannot be put in place: " + ec.message());
    temps[k].clear();
  };
  if (order.empty()) return nullptr;
  const std::size_t first = order.size() - 1;  // renamed before the last
  std::exception_ptr error = run_in_order(first, std::clamp<std::size_t>(workers, 1, std::max<std::size_t>(first, 1)),
                                          [&](std::size_t i) { rename_one(order[i]); });
  if (!error) error = run_in_order(1, 1, [&](std::size_t) { rename_one(order.back()); });
  return error;
}

// The targets in the one order every run takes them in: by directory, then by name.
std::vector<std::size_t> taking_order(const std::vector<Target>& targets) {
  std::vector<std::size_t> order(targets.size());
  for (std::size_t t = 0; t < order.size(); ++t) order[t] = t;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return targets[a] < targets[b]; });
  return order;
}

// The temporaries a commit holds: taken in one order by every run (directory, then final name),
// so that two runs with some output names in common never wait for each other in a circle, and
// let go (closed) only after the renames.
class HeldTemporaries {
 public:
  explicit HeldTemporaries(const std::vector<Target>& targets) : order_(taking_order(targets)), fds_(targets.size(), -1) {}
  ~HeldTemporaries() { release(); }
  HeldTemporaries(const HeldTemporaries&) = delete;
  HeldTemporaries& operator=(const HeldTemporaries&) = delete;
  // The targets in the order they are taken and renamed (the last one renamed last).
  const std::vector<std::size_t>& order() const { return order_; }
  int fd(std::size_t t) const { return fds_[t]; }
  // Holds `temp`, cut short to the directory's longest name where the whole is longer (asked only
  // then: a statfs a run saved).
  void hold(std::size_t t, std::string& temp, const std::string& final_path, CommitNotes& notes) {
#ifdef DELTRI_POSIX_OUTPUT
    bool stale = false;
    fds_[t] = hold_temporary(temp, final_path, notes.waited_for_other_run, stale, unnamed_);
    if (fds_[t] == kNameTooLong) {
      temp = temporary_name(final_path, longest_name(directory_of(final_path)));
      fds_[t] = hold_temporary(temp, final_path, notes.waited_for_other_run, stale, unnamed_);
      if (fds_[t] == kNameTooLong) fail(final_path, "cannot be created: " + errno_text(ENAMETOOLONG));
    }
    notes.stale_temporaries_removed += stale;
#else
    (void)temp, (void)final_path, (void)notes;
#endif
  }
  void release() {
#ifdef DELTRI_POSIX_OUTPUT
    for (int& fd : fds_)
      if (fd >= 0) close(std::exchange(fd, -1));
#endif
  }

 private:
  std::vector<std::size_t> order_;
  std::vector<int> fds_;
  bool unnamed_ = true;  // temporaries made unnamed first (hold_temporary)
};

}  // namespace

// What commit() works from: the output files' names and targets, the temporaries' names, what was
// at each name when the run looked first, and the notes so far.
struct OutputSet::Plan {
  std::vector<std::string> paths;  // of the files, standard output left out
  std::vector<std::size_t> file_of;  // the file of each path
  std::vector<Target> targets;  // of the paths
  std::vector<std::string> temps, finals, before;  // of the files
  CommitNotes notes;
};

CommitNotes OutputSet::commit(const CommitListener& listener) {
  Plan p;
  for (std::size_t k = 0; k < files_.size(); ++k)
    if (files_[k].final_path != kStandardOutput) p.paths.push_back(files_[k].final_path), p.file_of.push_back(k);
  p.targets = targets_of(p.paths);
  refuse_duplicate_names(p.paths, p.targets);
  p.temps.resize(files_.size());
  p.before.resize(files_.size());
  for (std::size_t t = 0; t < p.paths.size(); ++t) {
    p.temps[p.file_of[t]] = temporary_name(p.paths[t], kAnyLength);
    p.before[p.file_of[t]] = file_identity(p.paths[t], &inputs_);
  }
  for (const File& f : files_) p.finals.push_back(f.final_path);
  struct Unlisten {
    const CommitListener& l;
    ~Unlisten() {
      if (l.pending) l.pending({}, {});
    }
  } unlisten{listener};
  if (!put_unnamed(p, listener)) put_by_temporaries(p, listener, false);
  for (const File& f : files_) {
    if (f.final_path != kStandardOutput) continue;
    errno = 0;
    if (std::fwrite(f.contents.data(), 1, f.contents.size(), stdout) != f.contents.size() || std::fflush(stdout) != 0)
      fail("standard output", errno_text(errno));
  }
  files_.clear();
  return p.notes;
}

// Where every output name and every temporary name is free (a batch's fresh folder), each file is
// written to an unnamed file and then linked at its final name: one new directory entry a file,
// with no lock and no rename. A run on other names meets nothing here. Two runs on one name
// cannot both link it: the one that finds a name taken (or any other file there, from any
// process) puts its whole set in place again by temporaries (put_by_temporaries, files written
// anew), which meets every other run as that protocol does, so the last run to put a set in place
// leaves all of it. A run by temporaries that renames over a name this run linked does so before
// this run links its later names (or this run finds one taken and goes by temporaries after it),
// since both go through the names in one order: either way no two runs' files are mixed. A
// temporary already at one of the names (a killed run's, or one another run is writing) sends the
// run by temporaries from the start, which meets the other run or removes the killed one's.
// A link that fails for another reason goes the same way (the temporaries report what fails).
// Signals wait until the set is in place (CommitListener). Returns false, having changed nothing,
// where this does not apply or the file system makes no unnamed files.
bool OutputSet::put_unnamed(Plan& p, const CommitListener& listener) {
#ifdef DELTRI_UNNAMED_OUTPUT
  struct stat st;
  for (std::size_t t = 0; t < p.paths.size(); ++t)
    if (!p.before[p.file_of[t]].empty() || lstat(p.temps[p.file_of[t]].c_str(), &st) == 0 || errno != ENOENT) return false;
  std::vector<int> fds(files_.size(), -1);
  struct Close {
    std::vector<int>& fds;
    ~Close() {
      for (const int fd : fds)
        if (fd >= 0) close(fd);
    }
  } close_all{fds};
  for (std::size_t t = 0; t < p.paths.size(); ++t)
    if ((fds[p.file_of[t]] = open(directory_of(p.paths[t]).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666)) < 0) return false;
  const std::size_t writers = std::max<std::size_t>(1, workers_);
  RangePool pool(writers);
  if (const std::exception_ptr error = run_in_order(files_.size(), writers, [&](std::size_t k) {
        write_temporary(files_[k], p.temps[k], fds[k], &pool);
      }, &pool))
    std::rethrow_exception(error);  // nothing has a name: nothing to remove
  if (listener.begin_renames && !listener.begin_renames()) throw OutputError("interrupted before the outputs were put in place");
  struct EndRenames {
    const CommitListener& l;
    ~EndRenames() {
      if (l.end_renames) l.end_renames();
    }
  } end_renames{listener};
  const std::vector<std::size_t> order = taking_order(p.targets);
  std::size_t linked = 0;
  for (; linked < order.size(); ++linked) {
    const std::size_t t = order[linked];
    // A taken name (EEXIST), or a link the kernel refuses here (no /proc for a caller without
    // CAP_DAC_READ_SEARCH, say): the temporaries below do without links to final names.
    if (link_unnamed(fds[p.file_of[t]], p.paths[t]) != 0) break;
  }
  if (linked == order.size()) return true;
  for (std::size_t i = 0; i < linked; ++i) {  // this run's own files are not "changed meanwhile"
    const std::size_t k = p.file_of[order[i]];
    p.before[k] = fstat(fds[k], &st) == 0 ? identity_text(st) : std::string();
  }
  put_by_temporaries(p, listener, true);
  return true;
#else
  (void)p, (void)listener;
  return false;
#endif
}

// Writes every file to its temporary FINAL.tmp.HASH, held locked from its creation until after
// the renames, checks the final names, then renames the temporaries into place (see commit()).
// `renames_begun`: called by put_unnamed() after some files were linked (the listener was told).
void OutputSet::put_by_temporaries(Plan& p, const CommitListener& listener, bool renames_begun) {
  CommitNotes& notes = p.notes;
  std::vector<std::string>& temps = p.temps;
  const std::vector<std::string>& finals = p.finals;
  std::vector<std::string> held(files_.size());
  std::vector<int> fds(files_.size(), -1);
  // A temporary that cannot be created fails its file's write, so that with several failures the
  // one of the earliest-added file is still the one reported.
  std::vector<std::exception_ptr> cannot_hold(files_.size());
  HeldTemporaries holder(p.targets);
  for (const std::size_t t : holder.order()) {
    const std::size_t k = p.file_of[t];
    try {
      holder.hold(t, temps[k], p.paths[t], notes);
    } catch (...) {
      cannot_hold[k] = std::current_exception();
      temps[k].clear();
      continue;
    }
    fds[k] = holder.fd(t);
    held[k] = temps[k];
    if (listener.pending) listener.pending(held, finals);
  }
  // Every worker writes: one with no file of its own left formats ranges of the others' files.
  const std::size_t writers = std::max<std::size_t>(1, workers_);
  RangePool pool(writers);
  std::exception_ptr error = run_in_order(files_.size(), writers, [&](std::size_t k) {
    if (cannot_hold[k]) std::rethrow_exception(cannot_hold[k]);
    write_temporary(files_[k], temps[k], fds[k], &pool);
  }, &pool);
  // Before the first rename, one look at each final name: whether another process replaced it
  // meanwhile, and whether something that is not a file stands in the way of the rename (then the
  // run fails leaving every old output as it was).
  if (!error) {
    try {
      for (std::size_t k = 0; k < files_.size(); ++k)
        if (!temps[k].empty() && file_identity(files_[k].final_path) != p.before[k]) ++notes.replaced_meanwhile;
    } catch (...) {
      error = std::current_exception();
    }
  }
  // Past this point a signal finishes the renames instead of removing the temporaries left (see
  // cli/interrupt_cleanup.h); if one is already being handled, nothing is renamed.
  bool renaming = false;
  if (!error && !renames_begun && listener.begin_renames && !(renaming = listener.begin_renames()))
    error = std::make_exception_ptr(OutputError("interrupted before the outputs were put in place"));
  if (!error) {
    std::vector<std::size_t> rename_order;  // files, in the order their temporaries were taken
    for (const std::size_t t : holder.order()) rename_order.push_back(p.file_of[t]);
    error = rename_into_place(temps, finals, rename_order, std::min(workers_, files_.size()));
  }
  if (renaming && listener.end_renames) listener.end_renames();
  if (error) {
    remove_quietly(temps);  // while still held: no other run has them meanwhile
    holder.release();
    std::rethrow_exception(error);
  }
  holder.release();
}

}  // namespace deltri
