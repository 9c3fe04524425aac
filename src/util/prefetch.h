// A hint to the processor that *p will be read soon; nothing else.
#pragma once

namespace deltri {

inline void prefetch(const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

}  // namespace deltri
