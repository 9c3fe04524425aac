// The kernel's one Lawson routine: flips on the link of a new vertex until no edge opposite it may
// be flipped. Which edges may flip is the caller's test (an incircle test, a half-plane test for
// ghost triangles, a lookup in a known cavity); the flips themselves are the kernel's flip in its
// Turn layout (mesh/operations.h), so every caller sees the same slots afterwards.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/mesh.h"
#include "mesh/operations.h"

namespace deltri {
namespace detail {

// The flip stack: a vertex's link is short, so the common case needs no allocation (insertion
// runs once per Steiner point, and the allocator showed in refinement's profile).
class EdgeStack {
 public:
  void push_back(EdgeRef e) {
    if (size_ < kInline) {
      inline_[size_++] = e;
      return;
    }
    spill_.push_back(e);
    ++size_;
  }
  EdgeRef back() const { return size_ > kInline ? spill_.back() : inline_[size_ - 1]; }
  void pop_back() {
    if (size_ > kInline) spill_.pop_back();
    --size_;
  }
  bool empty() const { return size_ == 0; }

 private:
  static constexpr std::size_t kInline = 64;
  EdgeRef inline_[kInline];
  std::size_t size_ = 0;
  std::vector<EdgeRef> spill_;
};

}  // namespace detail

// Lawson's flips on the link of v, where `out` leaves v: the edges opposite v in every triangle
// around it (the fan may be open at the boundary) are stacked, turning counter-clockwise from out
// and then clockwise; each popped edge that still has v as its apex and passes may_flip(e) is
// flipped, and the two edges it brings opposite v are stacked. may_flip must refuse boundary
// edges and subsegments. Returns the last flip's new edge (it left v when made), or kNone.
template <class MayFlip>
EdgeRef flip_link(Mesh& m, VertexId v, EdgeRef out, MayFlip&& may_flip) {
  detail::EdgeStack stack;
  EdgeRef e = out;
  do {
    stack.push_back(lnext(e));
    e = m.link[lprev(e)];
  } while (e != kNone && e != out);
  if (e != out)
    for (EdgeRef s = m.link[out]; s != kNone; s = m.link[e]) {
      e = lnext(s);
      stack.push_back(lnext(e));
    }
  EdgeRef last = kNone;
  while (!stack.empty()) {
    const EdgeRef x = stack.back();
    stack.pop_back();
    if (m.apex(x) != v || !may_flip(x)) continue;
    const EdgeRef f = m.link[x];
    last = flip(m, x);  // v -> old apex of f; the link of v is now lnext(last), lprev(f)
    stack.push_back(lnext(last));
    stack.push_back(lprev(f));
  }
  return last;
}

}  // namespace deltri
