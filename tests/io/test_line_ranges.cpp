// Large files formatted in ranges by several threads (io/range_pool.h): the bytes must be those of
// one thread writing every line in order, across range boundaries and for any number of writers.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/check.h"
#include "io/output_set.h"
#include "io_test_util.h"

using namespace deltri;
namespace fs = std::filesystem;

namespace {

// Line i of file `f`: built here with std::to_string, independently of TextWriter.
std::string expected_line(std::size_t f, std::size_t i) {
  return std::to_string(i) + " " + std::to_string(static_cast<long long>(i * i) - 7) + " " + std::to_string(f) + "\n";
}

std::string expected_file(std::size_t f, std::size_t lines) {
  std::string text = "header " + std::to_string(lines) + "\n";
  for (std::size_t i = 0; i < lines; ++i) text += expected_line(f, i);
  return text + "tail\n";
}

// Lines [begin, end) of file `f` through TextWriter.
void format_lines(TextWriter& part, std::size_t f, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    TextWriter::Line line = part.line(3);
    line.integer(static_cast<long long>(i));
    line.next_integer(static_cast<long long>(i * i) - 7);
    line.next_integer(static_cast<long long>(f));
    line.end_line();
  }
}

// A file as the writers make one: a header, the body in ranges of `per_range` lines, a tail.
void produce(ByteSink& sink, std::size_t f, std::size_t lines, std::size_t per_range) {
  TextWriter out(sink);
  out.text("header ");
  out.integer(static_cast<long long>(lines));
  out.end_line();
  out.finish();
  sink.write_ranges({lines, per_range, [f](TextWriter& part, std::size_t begin, std::size_t end) {
                       format_lines(part, f, begin, end);
                     }});
  out.text("tail\n");
  out.finish();
}

}  // namespace

TEST(line_ranges_match_one_thread_in_order) {
  constexpr std::size_t per = 7;
  const std::vector<std::size_t> counts{0, 1, per - 1, per, per + 1, 2 * per, 9 * per + 3, 40 * per + 1};
  const fs::path dir = iotest::scratch_dir() / "ranges";
  fs::create_directories(dir);
  for (std::size_t workers = 1; workers <= 4; ++workers) {
    // Every count once as a file of its own, all in one set: workers done with their small files
    // help with the others' ranges.
    OutputSet set(workers);
    for (std::size_t f = 0; f < counts.size(); ++f)
      set.add_stream((dir / ("f" + std::to_string(f))).string(),
                     [f, lines = counts[f]](ByteSink& sink) { produce(sink, f, lines, per); });
    set.commit();
    for (std::size_t f = 0; f < counts.size(); ++f)
      CHECK_EQ(iotest::read_file((dir / ("f" + std::to_string(f))).string()), expected_file(f, counts[f]));
  }
}

TEST(line_ranges_in_memory_are_the_same_text) {
  // The library's path: a string sink formats the ranges on the calling thread.
  for (const std::size_t lines : {0u, 1u, 6u, 7u, 8u, 66u}) {
    std::string text;
    StringSink sink(text);
    produce(sink, 3, lines, 7);
    CHECK_EQ(text, expected_file(3, lines));
  }
}

TEST(write_lines_crosses_real_range_boundaries) {
  const std::size_t per = TextWriter::kItemsPerRange;
  const fs::path dir = iotest::scratch_dir() / "write_lines";
  fs::create_directories(dir);
  const std::vector<std::size_t> counts{per - 1, per, per + 1, 3 * per + 5};
  OutputSet set;
  for (std::size_t f = 0; f < counts.size(); ++f)
    set.add_stream((dir / ("w" + std::to_string(f))).string(), [f, lines = counts[f]](ByteSink& sink) {
      TextWriter out(sink);
      out.text("header ");
      out.integer(static_cast<long long>(lines));
      out.end_line();
      out.write_lines(lines, [f](TextWriter& part, std::size_t begin, std::size_t end) {
        format_lines(part, f, begin, end);
      });
      out.text("tail\n");
      out.finish();
    });
  set.commit();
  for (std::size_t f = 0; f < counts.size(); ++f)
    CHECK_EQ(iotest::read_file((dir / ("w" + std::to_string(f))).string()), expected_file(f, counts[f]));
}

TEST(line_ranges_failure_leaves_no_file) {
  const fs::path dir = iotest::scratch_dir() / "ranges_fail";
  fs::create_directories(dir);
  for (std::size_t workers = 1; workers <= 4; ++workers) {
    OutputSet set(workers);
    set.add_stream((dir / "small").string(), [](ByteSink& sink) { produce(sink, 0, 3, 7); });
    set.add_stream((dir / "big").string(), [](ByteSink& sink) {
      sink.write_ranges({1000, 7, [](TextWriter& part, std::size_t begin, std::size_t) {
                           if (begin == 7 * 90) throw std::runtime_error("range 90 failed");
                           part.text("x\n");
                         }});
    });
    bool threw = false;
    try {
      set.commit();
    } catch (const std::runtime_error& e) {
      threw = std::string(e.what()) == "range 90 failed";
    }
    CHECK(threw);
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    CHECK_EQ(files, 0u);
  }
}
