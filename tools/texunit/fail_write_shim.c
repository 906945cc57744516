/* A full disk without privileges, for the output tests (tools/texunit/output_test.sh): loaded with
 * LD_PRELOAD, it makes write(2) / writev(2) to regular files fail with ENOSPC once
 * TU_FAIL_WRITE_AFTER bytes have been written in the process (the write that crosses the limit is
 * short, as on a real file system); with TU_FAIL_CLOSE set, close(2) of a regular file that was
 * written returns ENOSPC after closing it (a delayed-allocation or network file system reports a
 * full disk there). Pipes, terminals and /dev/null are never failed, so messages still arrive. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

static atomic_llong written;
static atomic_uchar dirty[4096]; /* fds written since they were opened */

static int regular(int fd) {
  struct stat st;
  return fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
}

/* Bytes of `n` still allowed for fd (n itself when the limit is off or fd is not a file). */
static size_t allowed(int fd, size_t n) {
  const char* env = getenv("TU_FAIL_WRITE_AFTER");
  if (!regular(fd)) return n;
  if (fd >= 0 && fd < 4096) atomic_store(&dirty[fd], 1);
  if (!env) return n;
  const long long limit = atoll(env);
  const long long before = atomic_fetch_add(&written, (long long)n);
  if (before >= limit) return 0;
  return before + (long long)n <= limit ? n : (size_t)(limit - before);
}

ssize_t write(int fd, const void* buf, size_t n) {
  static ssize_t (*real)(int, const void*, size_t);
  if (!real) real = (ssize_t(*)(int, const void*, size_t))dlsym(RTLD_NEXT, "write");
  const size_t k = allowed(fd, n);
  if (k == 0 && n > 0) {
    errno = ENOSPC;
    return -1;
  }
  return real(fd, buf, k);
}

ssize_t writev(int fd, const struct iovec* iov, int cnt) {
  static ssize_t (*real)(int, const struct iovec*, int);
  if (!real) real = (ssize_t(*)(int, const struct iovec*, int))dlsym(RTLD_NEXT, "writev");
  size_t n = 0;
  for (int i = 0; i < cnt; ++i) n += iov[i].iov_len;
  const size_t k = allowed(fd, n);
  if (k == 0 && n > 0) {
    errno = ENOSPC;
    return -1;
  }
  if (k == n) return real(fd, iov, cnt);
  /* Short: the first k bytes only. */
  size_t left = k;
  ssize_t done = 0;
  for (int i = 0; i < cnt && left > 0; ++i) {
    const size_t m = iov[i].iov_len < left ? iov[i].iov_len : left;
    static ssize_t (*w)(int, const void*, size_t);
    if (!w) w = (ssize_t(*)(int, const void*, size_t))dlsym(RTLD_NEXT, "write");
    const ssize_t r = w(fd, iov[i].iov_base, m);
    if (r < 0) return done ? done : r;
    done += r;
    left -= (size_t)r;
    if ((size_t)r < m) break;
  }
  return done;
}

int close(int fd) {
  static int (*real)(int);
  if (!real) real = (int (*)(int))dlsym(RTLD_NEXT, "close");
  const int was_dirty = fd >= 0 && fd < 4096 && atomic_exchange(&dirty[fd], 0);
  const int rc = real(fd);
  if (rc == 0 && was_dirty && getenv("TU_FAIL_CLOSE")) {
    errno = ENOSPC;
    return -1;
  }
  return rc;
}
