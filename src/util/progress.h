// What a run has done so far, for a progress meter that another thread reads (the command line's
// cli/progress_meter.h). The pipeline names each stage as it starts and the triangles at its end;
// refinement adds its vertices and queue changes every few hundred queue pops. Everything is a
// relaxed atomic: the writers never wait, lock or call the system, and a reader sees counts that
// are each a little old, which a meter can afford. The library makes none: a caller that wants one
// owns it and passes it in (Switches-independent, never printed by the library).
#pragma once

#include <atomic>
#include <cstdint>

namespace deltri {

struct Progress {
  std::atomic<const char*> stage{nullptr};     // the stage under way (a string literal), or null
  std::atomic<std::uint32_t> stage_number{0};  // counts stage starts, so a reader sees a change of stage
  std::atomic<std::int64_t> triangles{0};      // live triangles when the last stage ended
  // Refinement: vertices inserted less deleted, and bad triangles queued, summed over the parts
  // that refine at once (each publishes the change since its last publication).
  std::atomic<std::int64_t> refine_vertices{0};
  std::atomic<std::int64_t> queued{0};
  std::atomic<std::int64_t> refine_start_triangles{0};

  void begin(const char* name) {
    stage.store(name, std::memory_order_relaxed);
    stage_number.fetch_add(1, std::memory_order_release);
  }
  void set_triangles(std::int64_t n) { triangles.store(n, std::memory_order_relaxed); }
};

// One publisher's share (a Terminator's): what it has already added, so that it adds only changes.
class ProgressShare {
 public:
  void publish(Progress* p, std::int64_t vertices, std::int64_t queued) {
    if (!p) return;
    p->refine_vertices.fetch_add(vertices - vertices_, std::memory_order_relaxed);
    p->queued.fetch_add(queued - queued_, std::memory_order_relaxed);
    vertices_ = vertices;
    queued_ = queued;
  }

 private:
  std::int64_t vertices_ = 0, queued_ = 0;
};

}  // namespace deltri
