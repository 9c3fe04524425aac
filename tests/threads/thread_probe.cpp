// Preloaded into deltri by one_thread.sh (LD_PRELOAD): reports on standard error every thread the
// program starts, then starts it as usual. std::thread reaches pthread_create through the C
// library's symbol, which a preloaded definition takes over.
#include <dlfcn.h>
#include <pthread.h>
#include <unistd.h>

namespace {
using Create = int (*)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*);
}

extern "C" int pthread_create(pthread_t* thread, const pthread_attr_t* attr, void* (*start)(void*), void* arg) {
  static const auto real = reinterpret_cast<Create>(dlsym(RTLD_NEXT, "pthread_create"));
  static const char kNote[] = "thread_probe: a thread was started\n";
  [[maybe_unused]] const ssize_t written = write(2, kNote, sizeof kNote - 1);
  return real(thread, attr, start, arg);
}
