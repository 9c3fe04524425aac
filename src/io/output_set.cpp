#include "io/output_set.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <system_error>

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
  for (const auto& p : paths) std::filesystem::remove(p, ignored);
}

}  // namespace

void OutputSet::add(std::string final_path, std::string contents) {
  files_.push_back({std::move(final_path), std::move(contents), {}});
}

void OutputSet::add_stream(std::string final_path, std::function<void(ByteSink&)> produce) {
  files_.push_back({std::move(final_path), {}, std::move(produce)});
}

void OutputSet::commit() {
  std::vector<std::string> temps;
  try {
    for (File& f : files_) {
      temps.push_back(temporary_name(f.final_path));
      FileSink sink(temps.back(), f.final_path);
      if (f.produce) f.produce(sink);
      else sink.write(f.contents.data(), f.contents.size());
      sink.close();
    }
    for (std::size_t k = 0; k < files_.size(); ++k) {
      std::error_code ec;
      std::filesystem::rename(temps[k], files_[k].final_path, ec);
      if (ec) fail(files_[k].final_path, "cannot be put in place: " + ec.message());
      temps[k].clear();
    }
  } catch (...) {
    remove_quietly(temps);
    throw;
  }
  files_.clear();
}

}  // namespace deltri
