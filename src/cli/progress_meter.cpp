#include "cli/progress_meter.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace deltri {
namespace {

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

bool shows_rate(const char* stage) {
  return std::strcmp(stage, "Delaunay") == 0 || std::strcmp(stage, "refinement") == 0;
}

}  // namespace

ProgressMeter::ProgressMeter(const Switches& sw, std::FILE* out, bool terminal)
    : on_(sw.progress > 0 || (sw.progress == 0 && !sw.quiet && !std::getenv(kOffVariable))), forced_(sw.progress > 0),
      terminal_(terminal), out_(out) {
  if (const char* tick = std::getenv(kTickVariable)) tick_ = std::chrono::milliseconds(std::clamp(std::atoi(tick), 1, 10000));
  // Without a terminal there is no line to rewrite: the stage lines need no thread of their own
  // unless some are held back for kDelay.
  if (on_ && (terminal_ || !forced_)) thread_ = std::thread([this] { watch(); });
}

ProgressMeter::~ProgressMeter() { stop(); }

void ProgressMeter::begin(const char* stage) {
  if (on_) progress_.begin(stage);
}

bool ProgressMeter::due() const {
  return forced_ || std::chrono::steady_clock::now() - start_ >= kDelay;
}

void ProgressMeter::write_held() {
  for (const std::string& line : held_) std::fprintf(out_, "%s%s\n", terminal_ ? "\r\x1b[K" : "", line.c_str());
  held_.clear();
  meter_shown_ = false;
  std::fflush(out_);
}

void ProgressMeter::stage_ended(const char* stage, double seconds, std::int64_t triangles) {
  if (!on_) return;
  char line[160];
  int n = std::snprintf(line, sizeof line, "deltri: %s %.2f s", stage, seconds);
  if (triangles > 0) {
    n += std::snprintf(line + n, sizeof line - n, ", %lld triangles", static_cast<long long>(triangles));
    const std::int64_t before = std::strcmp(stage, "refinement") == 0
                                    ? progress_.refine_start_triangles.load(std::memory_order_relaxed) : 0;
    if (shows_rate(stage) && seconds > 0)
      std::snprintf(line + n, sizeof line - n, ", %.0f triangles/s", static_cast<double>(triangles - before) / seconds);
  }
  const std::lock_guard lock(mutex_);
  held_.push_back(line);
  if (due()) write_held();
}

std::string ProgressMeter::meter_line(double seconds) const {
  const char* stage = progress_.stage.load(std::memory_order_relaxed);
  char line[200];
  int n = std::snprintf(line, sizeof line, "deltri: %s... %.1f s", stage ? stage : "working", seconds);
  if (stage && std::strcmp(stage, "refinement") == 0) {
    std::snprintf(line + n, sizeof line - n, ", about %lld triangles, %.0f triangles/s, queue %lld (about %.0f%% done)",
                  static_cast<long long>(last_triangles_), rate_,
                  static_cast<long long>(progress_.queued.load(std::memory_order_relaxed)), 100.0 * shown_fraction_);
  }
  return line;
}

void ProgressMeter::watch() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, tick_, [this] { return stopping_; })) {
    const auto now = std::chrono::steady_clock::now();
    const std::uint32_t stage = progress_.stage_number.load(std::memory_order_acquire);
    if (stage != stage_seen_) {  // a new stage: its counts start afresh
      stage_seen_ = stage;
      stage_start_ = now;
      last_triangles_ = -1;
      rate_ = 0;
      shown_fraction_ = 0;
    }
    const std::int64_t vertices = progress_.refine_vertices.load(std::memory_order_relaxed);
    const std::int64_t queued = progress_.queued.load(std::memory_order_relaxed);
    // Each vertex inserted makes two triangles more (one for a split on the boundary: an estimate).
    const std::int64_t triangles = progress_.refine_start_triangles.load(std::memory_order_relaxed) + 2 * vertices;
    if (last_triangles_ >= 0 && now > last_tick_)
      rate_ = static_cast<double>(triangles - last_triangles_) / seconds_between(last_tick_, now);
    last_triangles_ = triangles;
    last_tick_ = now;
    // The part done, estimated as the vertices inserted against those plus one per queued triangle.
    if (vertices + queued > 0)
      shown_fraction_ = std::max(shown_fraction_, static_cast<double>(vertices) / static_cast<double>(vertices + queued));
    if (!due()) continue;
    if (!held_.empty()) write_held();
    if (!terminal_) continue;
    std::fprintf(out_, "\r%s\x1b[K", meter_line(seconds_between(start_, now)).c_str());
    std::fflush(out_);
    meter_shown_ = true;
  }
}

void ProgressMeter::stop() {
  {
    const std::lock_guard lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
    if (meter_shown_) std::fprintf(out_, "\r\x1b[K");
    if (on_ && !held_.empty() && due()) write_held();
    meter_shown_ = false;
    std::fflush(out_);
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

}  // namespace deltri
