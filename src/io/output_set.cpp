#include "io/output_set.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <optional>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <system_error>
#include <thread>
#include <tuple>

#include "io/range_pool.h"
#include "util/errors.h"

#if __has_include(<sys/file.h>) && __has_include(<unistd.h>)
#include <dirent.h>
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

long process_id() {
#ifdef DELTRI_POSIX_OUTPUT
  return static_cast<long>(getpid());
#else
  return 0;
#endif
}

std::string directory_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

std::string file_name_of(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// The longest file name the directory takes (255 on most file systems).
std::size_t longest_name(const std::string& dir) {
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

// FINAL.tmp.PID.RANDOM: the process id lets a later run prove a leftover stale (its process is
// gone); the random part keeps names unique within the process. `rng` belongs to one commit().
std::string temporary_name(const std::string& final_path, std::size_t longest, std::mt19937_64& rng) {
  static const char kHex[] = "0123456789abcdef";
  std::string suffix = ".tmp." + std::to_string(process_id()) + ".";
  std::uint64_t bits = rng();
  for (int i = 0; i < 12; ++i, bits >>= 4) suffix += kHex[bits & 15];
  const std::string name = file_name_of(final_path);
  const std::string dir_part = final_path.substr(0, final_path.size() - name.size());
  return dir_part + name.substr(0, stem_size(name.size(), suffix.size(), longest)) + suffix;
}

// The process id of a temporary of `final_name` (a file name, no directory), or -1 if `name` is
// not one: STEM.tmp.<digits>.<12 hex digits>, STEM being `final_name` or, for a name too long for
// the whole to fit in `longest` characters, as much of it as temporary_name() keeps.
long temporary_owner(const std::string& name, const std::string& final_name, std::size_t longest) {
  if (name.size() < 13) return -1;
  const std::size_t random_at = name.size() - 12;
  for (std::size_t i = random_at; i < name.size(); ++i)
    if (!std::isxdigit(static_cast<unsigned char>(name[i]))) return -1;
  if (name[random_at - 1] != '.') return -1;
  std::size_t digits_at = random_at - 1;
  while (digits_at > 0 && name[digits_at - 1] >= '0' && name[digits_at - 1] <= '9') --digits_at;
  const std::size_t digits = random_at - 1 - digits_at;
  constexpr std::string_view kTmp = ".tmp.";
  if (digits == 0 || digits > 10 || digits_at < kTmp.size() + 1 ||
      name.compare(digits_at - kTmp.size(), kTmp.size(), kTmp) != 0)
    return -1;
  const std::size_t stem = digits_at - kTmp.size();
  if (stem != stem_size(final_name.size(), name.size() - stem, longest) || final_name.compare(0, stem, name, 0, stem) != 0)
    return -1;
  return std::stol(name.substr(digits_at, digits));
}

bool process_gone(long pid) {
#ifdef DELTRI_POSIX_OUTPUT
  return pid > 0 && pid != process_id() && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
#else
  (void)pid;
  return false;
#endif
}

// Where an output lands: its directory's device and inode (however the directory is spelt: a
// symbolic link, a bind mount, "." or its full path) and its file name. Two outputs with the same
// target are one file; with the directory not there yet, its spelling stands in.
struct Target {
  std::string dir;  // as first spelt, for the lock file's path
  std::uint64_t device = 0, inode = 0;
  bool identified = false;
  std::string name;
  std::size_t longest = 255;  // the directory's longest file name
  std::tuple<bool, std::uint64_t, std::uint64_t, std::string, std::string> key() const {
    return {identified, device, inode, identified ? std::string() : dir, name};
  }
  bool operator<(const Target& o) const { return key() < o.key(); }
  bool operator==(const Target& o) const { return key() == o.key(); }
};

// The targets of `paths`, each directory asked once for its identity and longest name, however
// many outputs it holds.
std::vector<Target> targets_of(const std::vector<std::string>& paths) {
  std::vector<Target> targets;
  for (const std::string& path : paths) {
    Target t;
    t.dir = directory_of(path);
    t.name = file_name_of(path);
    const auto known = std::find_if(targets.begin(), targets.end(), [&](const Target& o) { return o.dir == t.dir; });
    if (known != targets.end()) {
      std::tie(t.identified, t.device, t.inode, t.longest) = std::tuple{known->identified, known->device, known->inode, known->longest};
      targets.push_back(std::move(t));
      continue;
    }
    t.longest = longest_name(t.dir);
#ifdef DELTRI_POSIX_OUTPUT
    struct stat st;
    if (stat(t.dir.c_str(), &st) == 0) {
      t.device = static_cast<std::uint64_t>(st.st_dev);
      t.inode = static_cast<std::uint64_t>(st.st_ino);
      t.identified = true;
    }
#endif
    targets.push_back(std::move(t));
  }
  return targets;
}

// FNV-1a of a file name: the same in every build, so that two deltri programs agree on the name
// of the lock file of one output.
std::uint64_t name_hash(const std::string& name) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : name) h = (h ^ c) * 1099511628211ull;
  return h;
}

// The part of an output's file name its lock stands for: the name without its last extension
// ("box.1" for box.1.node, box.1.ele and box.1.poly). Two runs writing one file share its stem, so
// they still rename in turn; a run's usual outputs share one stem, so it takes one lock, not one
// per file (each lock file is a create and an unlink in the directory).
std::string lock_stem(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

// Exclusive advisory locks (flock), one per stem of the final output names (lock_stem): a hidden
// file DIR/.deltri-lock.<16 hex digits of the stem's hash>, short whatever the output's name.
// Locking stems rather than directories is what lets runs writing other names into the same
// directory go on without waiting, while two runs writing one name still rename in turn. The lock file exists
// only while it is held: its holder removes it before letting go, and a run that was waiting for
// it then finds the path gone or pointing to a newer file, and locks again. Locks are taken in
// sorted order of (directory device and inode, hash), so two runs cannot deadlock, and each lock
// file once, so no run waits for itself (one directory reached through a bind mount and through
// its own path is the same device and inode). Readers that do not lock see renames as before.
class NameLocks {
 public:
  explicit NameLocks(const std::vector<Target>& targets) {
#ifdef DELTRI_POSIX_OUTPUT
    // Sorted by the lock file's own identity (directory, hash), not by name: two names sharing a
    // lock file (one stem, a hash collision, or one name twice) then share one place in the order too.
    using Key = std::tuple<bool, std::uint64_t, std::uint64_t, std::string, std::uint64_t>;
    std::vector<std::pair<Key, std::string>> locks;
    for (const Target& t : targets) {
      const std::uint64_t hash = name_hash(lock_stem(t.name));
      char hex[17];
      std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
      locks.emplace_back(Key{t.identified, t.device, t.inode, t.identified ? std::string() : t.dir, hash},
                         t.dir + "/.deltri-lock." + hex);
    }
    std::sort(locks.begin(), locks.end());
    for (std::size_t i = 0; i < locks.size(); ++i)
      if (i == 0 || locks[i].first != locks[i - 1].first) lock(locks[i].second);
#else
    (void)targets;
#endif
  }
  ~NameLocks() {
#ifdef DELTRI_POSIX_OUTPUT
    for (const auto& [path, fd] : held_) {
      unlink(path.c_str());  // while still held: see the class comment
      close(fd);             // closing releases the lock
    }
#endif
  }
  NameLocks(const NameLocks&) = delete;
  NameLocks& operator=(const NameLocks&) = delete;
  bool waited() const { return waited_; }
  std::vector<std::string> paths() const {
    std::vector<std::string> p;
#ifdef DELTRI_POSIX_OUTPUT
    for (const auto& held : held_) p.push_back(held.first);
#endif
    return p;
  }

 private:
#ifdef DELTRI_POSIX_OUTPUT
  void lock(const std::string& path) {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      // Read-only is enough for flock, so users who share a directory share its lock files too.
      const int fd = open(path.c_str(), O_RDONLY | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
      if (fd < 0) return;  // then the renames go ahead without this lock's protection
      if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        waited_ = true;
        while (flock(fd, LOCK_EX) != 0 && errno == EINTR) {}
      }
      struct stat held, now;
      if (fstat(fd, &held) == 0 && stat(path.c_str(), &now) == 0 && held.st_dev == now.st_dev && held.st_ino == now.st_ino) {
        held_.emplace_back(path, fd);
        return;
      }
      close(fd);  // its holder removed it: lock the file now at that path
    }
  }
  std::vector<std::pair<std::string, int>> held_;
#endif
  bool waited_ = false;
};

// An identity of what is at `path` now (inode, size and time; of a symbolic link itself, which is
// what a rename replaces), to see whether another process replaced it; empty when nothing is
// there. Throws OutputError when it is something a rename could not replace (a directory, say).
std::string file_identity(const std::string& path) {
#ifdef DELTRI_POSIX_OUTPUT
  struct stat st;
  if (lstat(path.c_str(), &st) != 0) return {};
  if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode)) fail(path, "cannot be replaced: it exists and is not a regular file");
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
         std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
#else
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  if (!ec && status.type() != std::filesystem::file_type::not_found && status.type() != std::filesystem::file_type::regular &&
      status.type() != std::filesystem::file_type::symlink)
    fail(path, "cannot be replaced: it exists and is not a regular file");
  return {};
#endif
}

// Writes to a temporary file, reporting failures under the final name the user knows.
class FileSink final : public ByteSink {
 public:
  FileSink(const std::string& temp_path, const std::string& final_path, RangePool* pool)
      : final_path_(final_path), pool_(pool) {
    errno = 0;
    file_ = std::fopen(temp_path.c_str(), "wbx");  // the name is new: never another run's file
    if (!file_) fail(final_path_, "cannot be created: " + errno_text(errno));
    // A buffer of our own: stdio then neither asks the file system for its block size nor writes
    // a small output in several pieces.
    std::setvbuf(file_, buffer_.get(), _IOFBF, kBuffer);
  }
  ~FileSink() override {
    if (file_) std::fclose(file_);
  }
  void write(const char* data, std::size_t size) override {
    errno = 0;
    if (std::fwrite(data, 1, size, file_) != size) fail(final_path_, errno_text(errno));
  }
  void write_ranges(const LineRanges& ranges) override {
    if (pool_) pool_->write(*this, ranges);
    else ByteSink::write_ranges(ranges);
  }
  void close() {
    errno = 0;
    const bool flushed = std::fflush(file_) == 0;
    const int flush_error = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!flushed) fail(final_path_, errno_text(flush_error));
    if (!closed) fail(final_path_, errno_text(errno));
  }

 private:
  static constexpr std::size_t kBuffer = 65536;
  std::string final_path_;
  RangePool* pool_;
  std::unique_ptr<char[]> buffer_ = std::make_unique_for_overwrite<char[]>(kBuffer);
  std::FILE* file_ = nullptr;
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

void OutputSet::write_temporary(File& f, const std::string& temp_path, RangePool* pool) {
  if (f.final_path == kStandardOutput) return write_standard_output(f);
  FileSink sink(temp_path, f.final_path, pool);
  if (f.produce) f.produce(sink);
  else sink.write(f.contents.data(), f.contents.size());
  sink.close();
}

namespace {

// Calls visit(file name) for each entry of `dir` (none if it cannot be read). With POSIX, opendir
// and readdir: std::filesystem's iterator added an fstat and two fcntl calls to each small run.
template <class Visit>
void for_each_name_in(const std::string& dir, Visit&& visit) {
#ifdef DELTRI_POSIX_OUTPUT
  DIR* d = opendir(dir.c_str());
  if (!d) return;
  while (const dirent* e = readdir(d)) visit(std::string(e->d_name));
  closedir(d);
#else
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    visit(it->path().filename().string());
#endif
}

// One pass over each output directory, however many outputs it holds: in a batch folder of
// thousands of files a pass per output name was most of a small run's time in the file system.
std::size_t remove_stale_temporaries(const std::vector<Target>& targets) {
  std::vector<std::pair<const Target*, std::vector<std::string>>> names_by_dir;  // directory, file names
  for (const Target& t : targets) {
    auto it = std::find_if(names_by_dir.begin(), names_by_dir.end(), [&](const auto& d) { return d.first->dir == t.dir; });
    if (it == names_by_dir.end()) it = names_by_dir.insert(names_by_dir.end(), {&t, {}});
    it->second.push_back(t.name);
  }
  std::size_t removed = 0;
  for (const auto& by_dir : names_by_dir) {
    const Target* dir = by_dir.first;  // not a structured binding: clang 14 cannot capture one in a lambda
    const std::vector<std::string>& names = by_dir.second;
    for_each_name_in(dir->dir, [&](const std::string& entry) {
      for (const std::string& name : names) {
        const long owner = temporary_owner(entry, name, dir->longest);
        if (owner < 0 || !process_gone(owner)) continue;
        std::error_code ignored;
        removed += std::filesystem::remove(std::filesystem::path(dir->dir) / entry, ignored);
        break;
      }
    });
  }
  return removed;
}

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

}  // namespace

CommitNotes OutputSet::commit(const CommitListener& listener) {
  std::vector<std::string> paths;  // of the files, standard output left out
  for (const File& f : files_)
    if (f.final_path != kStandardOutput) paths.push_back(f.final_path);
  const std::vector<Target> targets = targets_of(paths);
  refuse_duplicate_names(paths, targets);
  CommitNotes notes;
  notes.stale_temporaries_removed = remove_stale_temporaries(targets);
  // The random part only keeps this process's names apart (the process id keeps processes apart,
  // and O_EXCL refuses a name that exists), so the clock is seed enough; std::random_device's
  // set-up had been a measurable part of a small run.
  std::mt19937_64 rng{static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count())};
  std::vector<std::string> temps, before, finals;
  for (std::size_t k = 0, t = 0; k < files_.size(); ++k) {
    const bool real = files_[k].final_path != kStandardOutput;
    temps.push_back(real ? temporary_name(files_[k].final_path, targets[t].longest, rng) : std::string());
    before.push_back(real ? file_identity(files_[k].final_path) : std::string());
    finals.push_back(files_[k].final_path);
    t += real;
  }
  if (listener.pending) listener.pending(temps, finals);
  struct Unlisten {
    const CommitListener& l;
    ~Unlisten() {
      if (l.pending) l.pending({}, {});
    }
  } unlisten{listener};
  // Every worker writes: one with no file of its own left formats ranges of the others' files.
  const std::size_t writers = std::max<std::size_t>(1, workers_);
  RangePool pool(writers);
  std::exception_ptr error =
      run_in_order(files_.size(), writers, [&](std::size_t k) { write_temporary(files_[k], temps[k], &pool); }, &pool);
  const std::size_t workers = std::max<std::size_t>(1, std::min(workers_, files_.size()));
  std::optional<NameLocks> locks;
  if (!error) {
    locks.emplace(targets);
    notes.waited_for_other_run = locks->waited();
    // Under the locks and before the first rename, one look at each final name: whether another
    // process replaced it meanwhile, and whether something that is not a file stands in the way of
    // the rename (then the run fails leaving every old output as it was).
    try {
      for (std::size_t k = 0; k < files_.size(); ++k)
        if (!temps[k].empty() && file_identity(files_[k].final_path) != before[k]) ++notes.replaced_meanwhile;
    } catch (...) {
      error = std::current_exception();
    }
  }
  // Past this point a signal finishes the renames instead of removing the temporaries left (see
  // cli/interrupt_cleanup.h); if one is already being handled, nothing is renamed.
  bool renaming = false;
  if (!error && listener.begin_renames && !(renaming = listener.begin_renames(locks->paths())))
    error = std::make_exception_ptr(OutputError("interrupted before the outputs were put in place"));
  // Renaming over an existing file frees the old one's blocks and cached pages, which for a large
  // .ele takes tens of milliseconds: worth sharing between threads too.
  if (!error) {
    error = run_in_order(files_.size(), workers, [&](std::size_t k) {
      if (temps[k].empty()) return;
      std::error_code ec;
      std::filesystem::rename(temps[k], files_[k].final_path, ec);
      if (ec) fail(files_[k].final_path, "cannot be put in place: " + ec.message());
      temps[k].clear();
    });
  }
  if (renaming && listener.end_renames) listener.end_renames();
  locks.reset();
  if (error) {
    remove_quietly(temps);
    std::rethrow_exception(error);
  }
  for (const File& f : files_) {
    if (f.final_path != kStandardOutput) continue;
    errno = 0;
    if (std::fwrite(f.contents.data(), 1, f.contents.size(), stdout) != f.contents.size() || std::fflush(stdout) != 0)
      fail("standard output", errno_text(errno));
  }
  files_.clear();
  return notes;
}

}  // namespace deltri
