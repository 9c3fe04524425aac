/* A test hook preloaded into deltri (LD_PRELOAD) to reach the moment between two renames of its
 * outputs onto their final names, which no timing can hit reliably. After the first rename(2) that
 * succeeds, or the first linkat(2) that succeeds at a name other than a temporary's (an unnamed
 * file linked at its final name), once per process:
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
typedef int (*linkat_fn)(int, const char*, int, const char*, int);
static rename_fn real_rename;
static linkat_fn real_linkat;
static volatile sig_atomic_t fired;

__attribute__((constructor)) static void find_real_calls(void) {
  /* Found before any signal handler can call them. */
  real_rename = (rename_fn)dlsym(RTLD_NEXT, "rename");
  real_linkat = (linkat_fn)dlsym(RTLD_NEXT, "linkat");
}

static int after_first_placed(int result);

int rename(const char* from, const char* to) {
  return after_first_placed(real_rename(from, to));
}

int linkat(int from_dir, const char* from, int to_dir, const char* to, int flags) {
  const int result = real_linkat(from_dir, from, to_dir, to, flags);
  return strstr(to, ".tmp.") ? result : after_first_placed(result);
}

static int after_first_placed(int result) {
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
