// Q_s, the queue of encroached subsegments (Fig. 38 l.5, Fig. 39 l.36-37), first in first out.
// An entry remembers the subsegment's endpoints: when it is popped the subsegment may already
// have been split (Fig. 39 l.38, "if s is still an edge of T"), which the endpoints reveal.
#pragma once

#include <cstddef>
#include <deque>

#include "mesh/ids.h"

namespace deltri {

struct EncroachedSubsegment {
  EdgeRef edge;     // where it was seen; may have moved since (flips rewrite slots)
  VertexId a, b;    // its endpoints when queued
};

class EncroachedQueue {
 public:
  void push(const EncroachedSubsegment& s) { items_.push_back(s); }
  EncroachedSubsegment pop() {
    const EncroachedSubsegment s = items_.front();
    items_.pop_front();
    return s;
  }
  bool empty() const { return items_.empty(); }
  std::size_t size() const { return items_.size(); }
  void clear() { items_.clear(); }

 private:
  std::deque<EncroachedSubsegment> items_;
};

}  // namespace deltri
