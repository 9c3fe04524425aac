// The progress meter on standard error (--progress, --no-progress; docs/manual.md, "Progress").
// The run owns one and hands its Progress (util/progress.h) to the pipeline; a thread of the
// meter's own reads the counts a few times a second, so the stages' loops only store relaxed
// atomics. On a terminal one line is rewritten in place (stage, triangles so far, rate, and in
// refinement the queue and an estimate of the part done) and each finished stage leaves one line;
// elsewhere only the finished stages' lines are written. By default nothing appears before the run
// has worked for kDelay (the stages that ended sooner are then written at once), and -Q turns it off.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "options/switches.h"
#include "util/progress.h"

namespace deltri {

class ProgressMeter {
 public:
  static constexpr std::chrono::milliseconds kDelay{2000};
  static constexpr std::chrono::milliseconds kTick{250};
  // Test hook: DELTRI_PROGRESS_TICK_MS=n in the environment rewrites the meter line every n ms
  // instead of kTick, so that a test's short run shows the line updating (docs/manual.md).
  static constexpr const char* kTickVariable = "DELTRI_PROGRESS_TICK_MS";
  // DELTRI_NO_PROGRESS set (to anything) makes --no-progress the default: the test suite sets it,
  // so that a run slowed past kDelay by a busy machine writes the same standard error as before.
  static constexpr const char* kOffVariable = "DELTRI_NO_PROGRESS";

  // Off with -Q or --no-progress; on from the start with --progress; else on after kDelay.
  ProgressMeter(const Switches& sw, std::FILE* out, bool terminal);
  ~ProgressMeter();
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  // The counts the pipeline publishes to, or null when the meter is off.
  Progress* progress() { return on_ ? &progress_ : nullptr; }
  // A stage began (the pipeline names its own through progress()).
  void begin(const char* stage);
  // A stage ended after `seconds`; `triangles` < 0: no count to show (reading, writing).
  void stage_ended(const char* stage, double seconds, std::int64_t triangles);
  // Ends the meter's thread and clears its line; the run's own messages follow.
  void stop();

 private:
  void watch();
  bool due() const;
  void write_held();
  std::string meter_line(double seconds) const;

  bool on_ = false;
  bool forced_ = false;
  bool terminal_ = false;
  std::FILE* out_;
  Progress progress_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex mutex_;  // the output and the fields below, between the run's thread and the meter's
  std::condition_variable wake_;
  bool stopping_ = false;
  bool meter_shown_ = false;             // a line to rewrite is on the terminal
  std::vector<std::string> held_;        // finished stages' lines not yet due
  std::chrono::steady_clock::time_point stage_start_ = start_;
  std::uint32_t stage_seen_ = 0;         // progress_.stage_number at stage_start_
  double shown_fraction_ = 0;            // the refinement estimate never goes back
  std::int64_t last_triangles_ = -1;     // for the rate: triangles at last_tick_
  std::chrono::steady_clock::time_point last_tick_ = start_;
  double rate_ = 0;
  std::chrono::milliseconds tick_ = kTick;
  std::thread thread_;
};

}  // namespace deltri
