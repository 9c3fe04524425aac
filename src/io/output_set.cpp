#include "io/output_set.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <system_error>
#include <thread>

#include "io/range_pool.h"
#include "pslg/errors.h"

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

long process_id() {
#ifdef DELTRI_POSIX_OUTPUT
  return static_cast<long>(getpid());
#else
  return 0;
#endif
}

// FINAL.tmp.PID.RANDOM: the process id lets a later run prove a leftover stale (its process is
// gone); the random part keeps names unique within the process. `rng` belongs to one commit().
std::string temporary_name(const std::string& final_path, std::mt19937_64& rng) {
  static const char kHex[] = "0123456789abcdef";
  std::string name = final_path + ".tmp." + std::to_string(process_id()) + ".";
  std::uint64_t bits = rng();
  for (int i = 0; i < 12; ++i, bits >>= 4) name += kHex[bits & 15];
  return name;
}

// The process id of a temporary of `final_name` (a file name, no directory), or -1 if `name` is
// not one: FINAL.tmp.<digits>.<12 hex digits>.
long temporary_owner(const std::string& name, const std::string& final_name) {
  const std::string prefix = final_name + ".tmp.";
  if (name.size() <= prefix.size() + 14 || name.compare(0, prefix.size(), prefix) != 0) return -1;
  const std::string rest = name.substr(prefix.size());
  const std::size_t dot = rest.find('.');
  if (dot == 0 || dot == std::string::npos || dot > 10 || rest.size() - dot - 1 != 12) return -1;
  for (std::size_t i = 0; i < dot; ++i)
    if (rest[i] < '0' || rest[i] > '9') return -1;
  for (std::size_t i = dot + 1; i < rest.size(); ++i)
    if (!std::isxdigit(static_cast<unsigned char>(rest[i]))) return -1;
  return std::stol(rest.substr(0, dot));
}

bool process_gone(long pid) {
#ifdef DELTRI_POSIX_OUTPUT
  return pid > 0 && pid != process_id() && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
#else
  (void)pid;
  return false;
#endif
}

// Exclusive advisory locks of the output directories, taken in sorted order (no deadlock between
// runs) and released on destruction. Readers that do not lock see renames as before.
class DirectoryLocks {
 public:
  explicit DirectoryLocks(std::vector<std::string> dirs) {
    // One lock per directory, however its path is spelt: a second flock of the same directory on
    // another descriptor would wait for this process itself (out/x.msh beside x.1.ele named
    // /abs/out/x.msh hung).
    for (std::string& d : dirs) {
      std::error_code ec;
      const std::filesystem::path canonical = std::filesystem::weakly_canonical(d.empty() ? "." : d, ec);
      if (!ec) d = canonical.string();
    }
    std::sort(dirs.begin(), dirs.end());
    dirs.erase(std::unique(dirs.begin(), dirs.end()), dirs.end());
#ifdef DELTRI_POSIX_OUTPUT
    for (const std::string& d : dirs) {
      const int fd = open(d.c_str(), O_RDONLY | O_CLOEXEC);
      if (fd < 0) continue;  // then the renames fail or succeed without the lock's protection
      if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        waited_ = true;
        while (flock(fd, LOCK_EX) != 0 && errno == EINTR) {}
      }
      fds_.push_back(fd);
    }
#endif
  }
  ~DirectoryLocks() {
#ifdef DELTRI_POSIX_OUTPUT
    for (const int fd : fds_) close(fd);  // closing releases the lock
#endif
  }
  DirectoryLocks(const DirectoryLocks&) = delete;
  DirectoryLocks& operator=(const DirectoryLocks&) = delete;
  bool waited() const { return waited_; }

 private:
  std::vector<int> fds_;
  bool waited_ = false;
};

std::string directory_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// An identity of what is at `path` now (inode, size and time), to see whether another process
// replaced it; empty when nothing is there.
std::string file_identity(const std::string& path) {
#ifdef DELTRI_POSIX_OUTPUT
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return {};
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
         std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
#else
  (void)path;
  return {};
#endif
}

// Writes to a temporary file, reporting failures under the final name the user knows.
class FileSink final : public ByteSink {
 public:
  FileSink(const std::string& temp_path, const std::string& final_path, RangePool* pool)
      : final_path_(final_path), pool_(pool) {
    errno = 0;
    file_ = std::fopen(temp_path.c_str(), "wb");
    if (!file_) fail(final_path_, "cannot be created: " + errno_text(errno));
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
  std::string final_path_;
  RangePool* pool_;
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

// Throws OutputError when `path` exists but is not a regular file (a directory, say), which a
// rename could not replace.
void check_replaceable(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  if (ec || status.type() == std::filesystem::file_type::not_found) return;
  if (status.type() != std::filesystem::file_type::regular && status.type() != std::filesystem::file_type::symlink)
    fail(path, "cannot be replaced: it exists and is not a regular file");
}

std::size_t OutputSet::remove_stale_temporaries() const {
  std::size_t removed = 0;
  std::vector<std::pair<std::string, std::string>> seen;  // (directory, file name)
  for (const File& f : files_) {
    if (f.final_path == kStandardOutput) continue;
    const std::string dir = directory_of(f.final_path);
    const std::string name = std::filesystem::path(f.final_path).filename().string();
    if (std::find(seen.begin(), seen.end(), std::make_pair(dir, name)) != seen.end()) continue;
    seen.emplace_back(dir, name);
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      const long owner = temporary_owner(it->path().filename().string(), name);
      if (owner < 0 || !process_gone(owner)) continue;
      std::error_code ignored;
      removed += std::filesystem::remove(it->path(), ignored);
    }
  }
  return removed;
}

CommitNotes OutputSet::commit(const TemporaryListener& listener) {
  CommitNotes notes;
  notes.stale_temporaries_removed = remove_stale_temporaries();
  std::mt19937_64 rng{std::random_device{}()};
  std::vector<std::string> temps, before;
  for (const File& f : files_) {
    temps.push_back(f.final_path == kStandardOutput ? std::string() : temporary_name(f.final_path, rng));
    before.push_back(f.final_path == kStandardOutput ? std::string() : file_identity(f.final_path));
  }
  if (listener) listener(temps);
  struct Unlisten {
    const TemporaryListener& l;
    ~Unlisten() {
      if (l) l({});
    }
  } unlisten{listener};
  // Every worker writes: one with no file of its own left formats ranges of the others' files.
  const std::size_t writers = std::max<std::size_t>(1, workers_);
  RangePool pool(writers);
  std::exception_ptr error =
      run_in_order(files_.size(), writers, [&](std::size_t k) { write_temporary(files_[k], temps[k], &pool); }, &pool);
  const std::size_t workers = std::max<std::size_t>(1, std::min(workers_, files_.size()));
  // A rename can still fail when something that is not a file stands in the way; find that before
  // the first rename, so that a failed run leaves every old output as it was.
  if (!error)
    error = run_in_order(files_.size(), workers, [&](std::size_t k) {
      if (!temps[k].empty()) check_replaceable(files_[k].final_path);
    });
  // Renaming over an existing file frees the old one's blocks and cached pages, which for a large
  // .ele takes tens of milliseconds: worth sharing between threads too.
  std::vector<std::string> dirs;
  for (const File& f : files_)
    if (f.final_path != kStandardOutput) dirs.push_back(directory_of(f.final_path));
  std::optional<DirectoryLocks> locks;
  if (!error) {
    locks.emplace(dirs);
    notes.waited_for_other_run = locks->waited();
    for (std::size_t k = 0; k < files_.size(); ++k)
      if (!temps[k].empty() && file_identity(files_[k].final_path) != before[k]) ++notes.replaced_meanwhile;
  }
  if (!error) {
    error = run_in_order(files_.size(), workers, [&](std::size_t k) {
      if (temps[k].empty()) return;
      std::error_code ec;
      std::filesystem::rename(temps[k], files_[k].final_path, ec);
      if (ec) fail(files_[k].final_path, "cannot be put in place: " + ec.message());
      temps[k].clear();
    });
  }
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
