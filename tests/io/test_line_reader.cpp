// Tokenising and number parsing, independent of any file format.
#include "harness/check.h"
#include "io/line_reader.h"
#include "io_test_util.h"

using namespace deltri;

namespace {

std::string error_of(const std::string& text, void (*body)(LineReader&)) {
  return iotest::input_error([&] {
    LineReader in("t", text);
    body(in);
  });
}

}  // namespace

TEST(line_reader_skips_comments_and_blank_lines) {
  LineReader in("t", "# header comment\n\n   \n1 2.5 # trailing\n\t# only comment\n3,4 , 5\n");
  REQUIRE(in.next_line());
  CHECK_EQ(in.line(), 4);
  CHECK_EQ(in.read_int({"r"}, 0, 10), 1);
  CHECK_EQ(in.read_double({"r"}), 2.5);
  CHECK(!in.has_field());
  REQUIRE(in.next_line());
  CHECK_EQ(in.line(), 6);
  CHECK_EQ(in.read_int({"r"}, 0, 10), 3);
  CHECK_EQ(in.read_int({"r"}, 0, 10), 4);
  CHECK_EQ(in.read_int({"r"}, 0, 10), 5);
  CHECK(!in.next_line());
}

TEST(line_reader_parses_number_forms) {
  LineReader in("t", "+7 -3 1e3 -2.5E-2 .5 +0.25 -0 1e-310\r\n");
  REQUIRE(in.next_line());
  CHECK_EQ(in.read_int({"r"}, -10, 10), 7);
  CHECK_EQ(in.read_int({"r"}, -10, 10), -3);
  CHECK_EQ(in.read_double({"r"}), 1000.0);
  CHECK_EQ(in.read_double({"r"}), -0.025);
  CHECK_EQ(in.read_double({"r"}), 0.5);
  CHECK_EQ(in.read_double({"r"}), 0.25);
  const double negative_zero = in.read_double({"r"});
  CHECK(negative_zero == 0.0 && std::signbit(negative_zero));
  CHECK_EQ(in.read_double({"r"}), 1e-310);
  CHECK(!in.has_field());
}

TEST(line_reader_last_line_without_newline) {
  LineReader in("t", "1\n2");
  REQUIRE(in.next_line());
  REQUIRE(in.next_line());
  CHECK_EQ(in.read_int({"r"}, 0, 9), 2);
  CHECK(!in.next_line());
  CHECK_EQ(in.line(), 2);
}

TEST(line_reader_rejects_bad_numbers) {
  auto read_double = [](LineReader& in) { in.next_line(); in.read_double({"vertex", 7, "y coordinate"}); };
  CHECK_EQ(error_of("\nabc\n", read_double), "t:2: vertex 7: y coordinate is not a number: 'abc'");
  for (const char* bad : {"nan", "inf", "-inf", "infinity", "-nan", "1.5x", "0x10", "1e", "--1", "+-1", "1e999"})
    CHECK(error_of(bad, read_double).starts_with("t:1: vertex 7: y coordinate is"));
  auto read_int = [](LineReader& in) { in.next_line(); in.read_int({"segment", 2, "first endpoint"}, 0, 100); };
  CHECK_EQ(error_of("1.0", read_int), "t:1: segment 2: first endpoint is not an integer: '1.0'");
  CHECK(error_of("0x3", read_int).starts_with("t:1: segment 2: first endpoint is not an integer"));
  CHECK(error_of("101", read_int).starts_with("t:1: segment 2: first endpoint must be between 0 and 100"));
  CHECK(error_of("99999999999999999999999", read_int).starts_with("t:1: segment 2: first endpoint is too large"));
  auto missing = [](LineReader& in) { in.next_line(); in.read_int({"r"}, 0, 1); in.read_int({"r", -1, "x"}, 0, 1); };
  CHECK_EQ(error_of("1 # 2", missing), "t:1: r: x is missing");
}

TEST(line_reader_survives_binary_garbage) {
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk += static_cast<char>((i * 7919) & 0xff);
  const std::string message = error_of(junk, [](LineReader& in) {
    while (in.next_line())
      while (in.has_field()) in.read_double({"r"});
  });
  CHECK(message.starts_with("t:"));
  CHECK(message.find("not a number") != std::string::npos);
}

TEST(line_reader_unreadable_files) {
  const std::string missing = (iotest::scratch_dir() / "no_such_file.node").string();
  CHECK(iotest::input_error([&] { LineReader::open(missing); }).starts_with(missing + ": "));
  const std::string dir = iotest::scratch_dir().string();
  CHECK_EQ(iotest::input_error([&] { LineReader::open(dir); }), dir + ": is a directory, not a file");
}

TEST(line_reader_split_tail_counts_lines_from_its_start) {
  LineReader in("t", "1 a\n2 b\n3 c\n4 d\n");
  LineReader tail = in.tail_after(5);  // inside line 2: the tail starts at line 3
  in.end_at(tail);
  REQUIRE(tail.next_line());
  CHECK_EQ(tail.read_int({"r"}, 0, 9), 3);
  CHECK_EQ(tail.line(), 1);
  int lines = 0;
  while (in.next_line()) ++lines;
  CHECK_EQ(lines, 2);
}
