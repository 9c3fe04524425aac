// All-or-nothing output.
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness/check.h"
#include "io/output_set.h"
#include "io_test_util.h"

using namespace deltri;
namespace fs = std::filesystem;

namespace {
std::size_t files_in(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}
}  // namespace

TEST(output_set_writes_all_files) {
  const fs::path dir = iotest::scratch_dir() / "out_ok";
  fs::create_directories(dir);
  OutputSet set;
  set.add((dir / "a.1.node").string(), "node text\n");
  set.add_stream((dir / "a.1.ele").string(), [](ByteSink& sink) {
    TextWriter w(sink);
    for (int i = 0; i < 100000; ++i) {
      w.integer(i);
      w.end_line();
    }
    w.finish();
  });
  set.commit();
  CHECK_EQ(iotest::read_file((dir / "a.1.node").string()), "node text\n");
  CHECK_EQ(iotest::read_file((dir / "a.1.ele").string()).size(), 588890u);
  CHECK_EQ(files_in(dir), 2u);
}

TEST(output_set_failure_leaves_nothing_and_keeps_old_files) {
  const fs::path dir = iotest::scratch_dir() / "out_fail";
  fs::create_directories(dir);
  const std::string old_path = (dir / "a.1.node").string();
  iotest::write_file("out_fail/a.1.node", "old\n");
  const std::string blocker = (dir / "not_a_dir").string();
  iotest::write_file("out_fail/not_a_dir", "x");
  for (const std::string& bad : {(dir / "missing" / "a.1.ele").string(), blocker + "/a.1.ele"}) {
    OutputSet set;
    set.add(old_path, "new\n");
    set.add(bad, "ele\n");
    bool threw = false;
    try {
      set.commit();
    } catch (const OutputError& e) {
      threw = true;
      CHECK(std::string(e.what()).starts_with(bad + ": "));
    }
    CHECK(threw);
    CHECK_EQ(iotest::read_file(old_path), "old\n");
    CHECK_EQ(files_in(dir), 2u);  // no temporaries left behind
  }
}

TEST(output_set_producer_failure_cleans_up) {
  const fs::path dir = iotest::scratch_dir() / "out_throw";
  fs::create_directories(dir);
  OutputSet set;
  set.add((dir / "x.node").string(), "x\n");
  set.add_stream((dir / "x.ele").string(), [](ByteSink&) { throw OutputError("boom"); });
  CHECK_THROWS(set.commit());
  CHECK_EQ(files_in(dir), 0u);
}

TEST(output_set_parallel_writes_are_complete) {
  // Several large streamed files written at once must each come out whole and in order.
  const fs::path dir = iotest::scratch_dir() / "out_parallel";
  fs::create_directories(dir);
  OutputSet set;
  for (int f = 0; f < 5; ++f) {
    set.add_stream((dir / ("p" + std::to_string(f))).string(), [f](ByteSink& sink) {
      TextWriter w(sink);
      for (int i = 0; i < 200000; ++i) {
        TextWriter::Line line = w.line(2);
        line.integer(f);
        line.next_integer(i);
        line.end_line();
      }
      w.finish();
    });
  }
  set.commit();
  CHECK_EQ(files_in(dir), 5u);
  for (int f = 0; f < 5; ++f) {
    const std::string text = iotest::read_file((dir / ("p" + std::to_string(f))).string());
    std::string expected;
    for (int i = 0; i < 200000; ++i) expected += std::to_string(f) + " " + std::to_string(i) + "\n";
    CHECK(text == expected);
  }
}

TEST(output_set_earliest_failure_is_reported_and_nothing_changes) {
  // Failures in several files, some while another file is being written: the error of the
  // earliest-added failing file is reported, as writing one file after another would, and no
  // final file is touched.
  const fs::path dir = iotest::scratch_dir() / "out_first_error";
  fs::create_directories(dir);
  const std::string old_path = (dir / "keep.node").string();
  iotest::write_file("out_first_error/keep.node", "old\n");
  const auto big = [](ByteSink& sink) {
    TextWriter w(sink);
    for (int i = 0; i < 300000; ++i) {
      w.integer(i);
      w.end_line();
    }
    w.finish();
  };
  for (int round = 0; round < 20; ++round) {
    const std::string bad1 = (dir / "missing1" / "a.ele").string();
    const std::string bad2 = (dir / "missing2" / "a.edge").string();
    OutputSet set;
    set.add_stream(old_path, big);
    set.add_stream((dir / "new.ele").string(), big);
    if (round % 2) set.add_stream((dir / "thrower").string(), [](ByteSink&) { throw OutputError("first"); });
    set.add(bad1, "x\n");
    set.add_stream((dir / "late.neigh").string(), big);
    set.add(bad2, "y\n");
    std::string message = "no error";
    try {
      set.commit();
    } catch (const OutputError& e) {
      message = e.what();
    }
    if (round % 2) CHECK_EQ(message, "first");
    else CHECK(message.starts_with(bad1 + ": "));
    CHECK_EQ(iotest::read_file(old_path), "old\n");
    CHECK_EQ(files_in(dir), 1u);  // only keep.node: no temporaries, no new files
  }
}

TEST(output_set_directory_in_the_way_changes_nothing) {
  const fs::path dir = iotest::scratch_dir() / "out_dir_blocks";
  fs::remove_all(dir);
  fs::create_directories(dir / "a.1.poly");  // a directory where an output file must go
  iotest::write_file("out_dir_blocks/a.1.node", "old\n");
  OutputSet set;
  set.add((dir / "a.1.node").string(), "new\n");
  set.add((dir / "a.1.poly").string(), "poly\n");
  bool threw = false;
  try {
    set.commit();
  } catch (const OutputError& e) {
    threw = true;
    CHECK(std::string(e.what()).starts_with((dir / "a.1.poly").string() + ": "));
  }
  CHECK(threw);
  CHECK_EQ(iotest::read_file((dir / "a.1.node").string()), "old\n");  // renamed only if all can be
  CHECK_EQ(files_in(dir), 2u);
}

TEST(output_set_refuses_two_outputs_naming_one_file) {
  const fs::path dir = iotest::scratch_dir() / "out_twice";
  fs::create_directories(dir);
  OutputSet set;
  set.add((dir / "a.1.node").string(), "node\n");
  set.add((dir / "a.1.ele").string(), "ele\n");
  set.add((dir / "." / "a.1.node").string(), "json\n");  // the same file, spelt another way
  bool threw = false;
  try {
    set.commit();
  } catch (const OutputError& e) {
    threw = true;
    CHECK(std::string(e.what()).find("another output of this run (no files written)") != std::string::npos);
  }
  CHECK(threw);
  CHECK_EQ(files_in(dir), 0u);
}

TEST(output_set_writes_names_near_the_longest) {
  // A temporary named FINAL.tmp.HASH would be 21 characters longer than the limit.
  const fs::path dir = iotest::scratch_dir() / "out_long";
  fs::create_directories(dir);
  const std::string name = std::string(247, 'n') + ".ele";  // 251 characters, under 255
  OutputSet set;
  set.add((dir / name).string(), "ele\n");
  set.commit();
  CHECK_EQ(iotest::read_file((dir / name).string()), "ele\n");
  CHECK_EQ(files_in(dir), 1u);
}

TEST(output_set_keeps_inputs_intact) {
  // An output that is an input of the run (by its own name, or a symbolic link to it) is refused
  // before anything is written; an output beside them is not (the check looks at each name once).
  const fs::path dir = iotest::scratch_dir() / "out_inputs";
  fs::create_directories(dir);
  iotest::write_file("out_inputs/in.poly", "input\n");
  const fs::path input = dir / "in.poly", link = dir / "link.msh";
  fs::remove(link);
  fs::create_symlink("in.poly", link);
  struct stat st;
  CHECK(stat(input.c_str(), &st) == 0);
  const FileId id{static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)};
  for (const fs::path& named : {input, link}) {
    OutputSet set;
    set.keep_intact({id});
    set.add((dir / "in.1.node").string(), "node\n");
    set.add(named.string(), "not the input\n");
    bool threw = false;
    try {
      set.commit();
    } catch (const OutputError& e) {
      threw = std::string(e.what()) == named.string() + ": is an input of this run, not overwritten (no files written)";
    }
    CHECK(threw);
    CHECK_EQ(iotest::read_file(input.string()), "input\n");
    CHECK(fs::is_symlink(link));
    CHECK_EQ(files_in(dir), 2u);
  }
  OutputSet set;
  set.keep_intact({id});
  set.add((dir / "in.1.node").string(), "node\n");
  set.commit();
  CHECK_EQ(files_in(dir), 3u);
}

TEST(output_set_tells_the_listener_each_phase) {
  const fs::path dir = iotest::scratch_dir() / "out_listener";
  fs::create_directories(dir);
  const std::string node = (dir / "a.1.node").string(), ele = (dir / "a.1.ele").string();
  iotest::write_file("out_listener/a.1.node", "old\n");
  for (const bool allow : {false, true}) {
    std::vector<std::string> temporaries, finals;
    int ended = 0, cleared = 0;
    CommitListener listener;
    listener.pending = [&](const std::vector<std::string>& t, const std::vector<std::string>& f) {
      if (t.empty()) ++cleared;
      else temporaries = t, finals = f;
    };
    listener.begin_renames = [&] {
      for (const std::string& t : temporaries) CHECK(fs::exists(t));
      return allow;
    };
    listener.end_renames = [&] { ++ended; };
    OutputSet set;
    set.add(node, "new\n");
    set.add(ele, "ele\n");
    if (allow) {
      set.commit(listener);
    } else {
      CHECK_THROWS(set.commit(listener));  // a signal is being handled: nothing is renamed
    }
    CHECK_EQ(finals.size(), 2u);
    CHECK_EQ(temporaries.size(), 2u);  // told once both are held
    for (const std::string& t : temporaries) CHECK(!t.empty());
    CHECK_EQ(ended, allow ? 1 : 0);
    CHECK_EQ(cleared, 1);
    CHECK_EQ(iotest::read_file(node), allow ? "new\n" : "old\n");
    CHECK_EQ(files_in(dir), allow ? 2u : 1u);
  }
}

TEST(output_set_links_unnamed_files_only_once_the_listener_allows) {
  // No output name there yet: the files are written unnamed (where the file system makes such
  // files) and linked at their names only after begin_renames allowed it; refused, nothing is
  // left at all, and no temporary was ever named for a signal handler to remove. Where the file
  // system makes no unnamed files (asked here directly), named temporaries stand in.
  const fs::path dir = iotest::scratch_dir() / "out_unnamed";
  fs::create_directories(dir);
  bool unnamed_files = false;
#ifdef O_TMPFILE
  if (const int fd = open(dir.c_str(), O_TMPFILE | O_WRONLY, 0600); fd >= 0) unnamed_files = true, close(fd);
#endif
  for (const bool allow : {false, true}) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::size_t named = 0;
    int begun = 0, ended = 0;
    CommitListener listener;
    listener.pending = [&](const std::vector<std::string>& t, const std::vector<std::string>&) { named += t.size(); };
    listener.begin_renames = [&] {
      ++begun;
      if (unnamed_files) CHECK_EQ(files_in(dir), 0u);  // everything written, nothing named yet
      return allow;
    };
    listener.end_renames = [&] { ++ended; };
    OutputSet set;
    set.add((dir / "a.1.node").string(), "node\n");
    set.add((dir / "a.1.ele").string(), "ele\n");
    if (allow) set.commit(listener);
    else CHECK_THROWS(set.commit(listener));
    CHECK_EQ(begun, 1);
    CHECK_EQ(ended, allow ? 1 : 0);
    if (unnamed_files) CHECK_EQ(named, 0u);
    CHECK_EQ(files_in(dir), allow ? 2u : 0u);
    if (allow) CHECK_EQ(iotest::read_file((dir / "a.1.ele").string()), "ele\n");
  }
}

namespace {
// FNV-1a (64 bits) of a file name, the published hash a temporary's name carries: written out
// here so that the test does not take the name from the code under test.
std::string fnv1a_hex(const std::string& name) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : name) h = (h ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}
}  // namespace

TEST(output_set_reuses_a_killed_runs_temporary_at_its_own_name) {
  // A killed run leaves FINAL.tmp.HASH with part of its content and no holder; the next run of
  // the same output takes that very file (no directory scan), says so, and leaves nothing else.
  const fs::path dir = iotest::scratch_dir() / "out_stale";
  fs::create_directories(dir);
  const std::string node = (dir / "a.1.node").string();
  iotest::write_file("out_stale/a.1.node.tmp." + fnv1a_hex("a.1.node"), "a long partial leftover\n");
  iotest::write_file("out_stale/b.1.node.tmp.0123456789abcdef", "another name's\n");  // not this run's
  OutputSet set;
  set.add(node, "new\n");
  const CommitNotes notes = set.commit();
  CHECK_EQ(notes.stale_temporaries_removed, 1u);
  CHECK(!notes.waited_for_other_run);
  CHECK_EQ(iotest::read_file(node), "new\n");  // truncated before the write: no leftover tail
  CHECK_EQ(files_in(dir), 2u);                 // a.1.node and the other name's file
}
