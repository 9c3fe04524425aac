// Runtime checks of key invariants, each O(1), cheap enough to keep in the sanitizer build: on
// without NDEBUG (make check-debug) and with DELTRI_ASSERTS defined (make check-sanitize, which
// keeps NDEBUG and so leaves the per-stage mesh checks of pipeline/pipeline.cpp off). Off, the condition
// is not evaluated. A failed check is a bug, not bad input: it throws std::logic_error naming the
// file, the line and the condition, as a failed per-stage check does.
#pragma once

#if !defined(NDEBUG) || defined(DELTRI_ASSERTS)
#include <stdexcept>
#include <string>

namespace deltri {
[[noreturn]] inline void invariant_failed(const char* condition, const char* file, int line) {
  throw std::logic_error(std::string(file) + ":" + std::to_string(line) + ": invariant failed: " + condition);
}
}  // namespace deltri

#define DELTRI_ASSERT(condition) ((condition) ? (void)0 : ::deltri::invariant_failed(#condition, __FILE__, __LINE__))
#else
#define DELTRI_ASSERT(condition) ((void)sizeof(condition))
#endif
