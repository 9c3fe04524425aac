#include "io/output_set.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <system_error>
#include <thread>

#include "pslg/errors.h"

namespace deltri {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& reason) { throw OutputError(path + ": " + reason); }

std::string errno_text(int error) { return error ? std::strerror(error) : "write failed"; }

// Unique per process and call without any platform process id.
std::string temporary_name(const std::string& final_path) {
  static std::mt19937_64 rng{std::random_device{}()};
  static const char kHex[] = "0123456789abcdef";
  std::string name = final_path + ".tmp.";
  std::uint64_t bits = rng();
  for (int i = 0; i < 12; ++i, bits >>= 4) name += kHex[bits & 15];
  return name;
}

// Writes to a temporary file, reporting failures under the final name the user knows.
class FileSink final : public ByteSink {
 public:
  FileSink(const std::string& temp_path, const std::string& final_path) : final_path_(final_path) {
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

// At most this many files are handled at once: the target machine has two cores, and the large
// outputs (.node, .ele) are each bound by one core formatting numbers.
constexpr std::size_t kMaxWorkers = 2;

// Runs task(k) for k = 0, 1, ..., count - 1 on up to kMaxWorkers threads, starting them in order
// of k; once a task has thrown, no further task starts. Returns the exception of the lowest k that
// threw, if any. Every task skipped after a failure comes after the failed one, so that is the
// exception a plain loop over k would have stopped at.
std::exception_ptr run_in_order(std::size_t count, const std::function<void(std::size_t)>& task) {
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
  };
  {
    std::vector<std::jthread> helpers;
    for (std::size_t w = 1; w < std::min(kMaxWorkers, count); ++w) {
      try {
        helpers.emplace_back(work);
      } catch (const std::system_error&) {
        break;  // no thread to be had: fewer workers do the same work
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

void OutputSet::write_temporary(File& f, const std::string& temp_path) {
  if (f.final_path == kStandardOutput) return write_standard_output(f);
  FileSink sink(temp_path, f.final_path);
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

void OutputSet::commit() {
  // Named here, in one thread: temporary_name's generator is not shared safely.
  std::vector<std::string> temps;
  for (const File& f : files_) temps.push_back(f.final_path == kStandardOutput ? std::string() : temporary_name(f.final_path));
  std::exception_ptr error = run_in_order(files_.size(), [&](std::size_t k) { write_temporary(files_[k], temps[k]); });
  // A rename can still fail when something that is not a file stands in the way; find that before
  // the first rename, so that a failed run leaves every old output as it was.
  if (!error)
    error = run_in_order(files_.size(), [&](std::size_t k) {
      if (!temps[k].empty()) check_replaceable(files_[k].final_path);
    });
  // Renaming over an existing file frees the old one's blocks and cached pages, which for a large
  // .ele takes tens of milliseconds: worth sharing between threads too.
  if (!error) {
    error = run_in_order(files_.size(), [&](std::size_t k) {
      if (temps[k].empty()) return;
      std::error_code ec;
      std::filesystem::rename(temps[k], files_[k].final_path, ec);
      if (ec) fail(files_[k].final_path, "cannot be put in place: " + ec.message());
      temps[k].clear();
    });
  }
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
}

}  // namespace deltri
