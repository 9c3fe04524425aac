/* A test hook preloaded into deltri (LD_PRELOAD) to reach the moment between two renames of its
 * outputs onto their final names, which no timing can hit reliably. After the first rename(2) that
 * succeeds, once per process:
 *   DELTRI_TEST_RENAME_HOOK=term  sends the process SIGTERM (an interrupted run mid-renames);
 *   DELTRI_TEST_RENAME_HOOK=stop  creates the file named by DELTRI_TEST_RENAME_MARK, then stops the
 *                                 process (SIGSTOP) until the test sends SIGCONT, holding whatever
 *                                 locks it holds.
 * Anything else (or nothing): the call is passed through unchanged. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef int (*rename_fn)(const char*, const char*);
static rename_fn real_rename;
static volatile sig_atomic_t fired;

__attribute__((constructor)) static void find_real_rename(void) {
  /* Found before any signal handler can call rename(). */
  real_rename = (rename_fn)dlsym(RTLD_NEXT, "rename");
}

int rename(const char* from, const char* to) {
  const int result = real_rename(from, to);
  if (result != 0 || fired) return result;
  const char* hook = getenv("DELTRI_TEST_RENAME_HOOK");
  if (!hook) return result;
  if (strcmp(hook, "term") == 0) {
    fired = 1;
    kill(getpid(), SIGTERM);
  } else if (strcmp(hook, "stop") == 0) {
    fired = 1;
    const char* mark = getenv("DELTRI_TEST_RENAME_MARK");
    if (mark) {
      const int fd = open(mark, O_WRONLY | O_CREAT, 0644);
      if (fd >= 0) close(fd);
    }
    kill(getpid(), SIGSTOP);
  }
  return result;
}
