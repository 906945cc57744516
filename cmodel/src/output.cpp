#include "texunit/output.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <utility>

#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace fs = std::filesystem;

namespace tu::out {

// The signal handler's registry. Signal safety decides its form: a handler may not lock, allocate
// or call the C++ library, so it walks a singly linked list of entries, each a C string and a
// kind, and calls only kill(2), waitpid(2), unlink(2), rmdir(2) and _exit(2). Entries are pushed at
// the head with a compare-and-swap (any thread) and never unlinked or freed: retiring one only
// stores kDead in its kind (an atomic int, lock-free), so the handler never follows a freed
// pointer. An entry is one small allocation per output file or directory (a command writes at
// most thousands); that memory is what the lock-free walk costs. Newest first is also the order
// the handler needs: a directory is removed after the files and directories created inside it.
namespace detail {
enum Kind : int { kDead = 0, kFile = 1, kDir = 2, kChild = 3 };
struct Entry {
  Entry* next = nullptr;  // fixed before the entry is published
  std::atomic<int> kind{kDead};
  pid_t pid = 0;
  char* path = nullptr;  // NUL-terminated, fixed before the entry is published
};
}  // namespace detail

namespace {
using detail::Entry;
using detail::Kind;

std::atomic<Entry*> g_head{nullptr};
std::atomic<bool> g_dying{false};
std::atomic<unsigned long> g_serial{0};  // temporaries' names: unique in the process
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free &&
              std::atomic<Entry*>::is_always_lock_free);

Entry* enroll(Kind k, const std::string& path, pid_t pid = 0) {
  auto* e = new Entry;
  e->path = new char[path.size() + 1];
  std::memcpy(e->path, path.c_str(), path.size() + 1);
  e->pid = pid;
  e->kind.store(k, std::memory_order_relaxed);
  Entry* h = g_head.load(std::memory_order_relaxed);
  do e->next = h;
  while (!g_head.compare_exchange_weak(h, e, std::memory_order_seq_cst, std::memory_order_relaxed));
  return e;
}

void retire(Entry* e) {
  if (e) e->kind.store(detail::kDead, std::memory_order_release);
}

extern "C" void on_signal(int sig) {
  if (g_dying.exchange(true)) {  // a second signal (another thread): the first one exits
    for (;;) pause();
  }
  Entry* const head = g_head.load(std::memory_order_seq_cst);
  for (Entry* e = head; e; e = e->next)  // children first: they must stop writing
    if (e->kind.load(std::memory_order_acquire) == detail::kChild) kill(-e->pid, SIGKILL);
  for (Entry* e = head; e; e = e->next)
    if (e->kind.load(std::memory_order_acquire) == detail::kChild)
      while (waitpid(e->pid, nullptr, 0) < 0 && errno == EINTR) {
      }
  for (Entry* e = head; e; e = e->next)
    if (e->kind.load(std::memory_order_acquire) == detail::kFile) unlink(e->path);
  for (Entry* e = head; e; e = e->next)
    if (e->kind.load(std::memory_order_acquire) == detail::kDir) rmdir(e->path);
  _exit(128 + sig);
}

// Streams into a file descriptor, every write(2) checked; the first error stops the stream
// (badbit) and is kept for the message.
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd) : fd_(fd) { setp(buf_, buf_ + sizeof buf_); }
  int error() const { return err_; }
  bool put(const char* p, size_t n) {
    while (n > 0 && err_ == 0) {
      const ssize_t k = ::write(fd_, p, n);
      if (k < 0 && errno == EINTR) continue;
      if (k <= 0) {
        err_ = k < 0 ? errno : EIO;
        break;
      }
      p += k;
      n -= static_cast<size_t>(k);
    }
    return err_ == 0;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const bool ok = put(pbase(), static_cast<size_t>(pptr() - pbase()));
    setp(buf_, buf_ + sizeof buf_);
    return ok;
  }
  int fd_;
  int err_ = 0;
  char buf_[1 << 16];
};

[[noreturn]] void fail(const std::string& name, int err) {
  throw std::runtime_error(name + ": cannot write the file (" + std::strerror(err) + ")");
}

// Opens `tmp`, lets `fill` write, checks the stream, the flush and close(2).
void write_checked(const std::string& tmp, const std::function<void(FdBuf&, std::ostream&)>& fill,
                   const std::string& name) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(name, errno);
  int err = 0;
  {
    FdBuf buf(fd);
    std::ostream os(&buf);
    try {
      fill(buf, os);
    } catch (...) {
      ::close(fd);
      throw;
    }
    os.flush();
    err = buf.error();
    if (err == 0 && !os) err = EIO;  // the writer set the stream's failbit itself
  }
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err) fail(name, err);
}

void reap(pid_t pid, int& status) {
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      status = -1;
      return;
    }
}

// posix_spawn of /bin/sh -c cmd in a new process group, enrolled for the signal handler.
// INT / TERM are blocked in this thread from the spawn to the enrolment; if a handler on another
// thread has started meanwhile (g_dying), the child is killed here, so no child outlives texunit.
pid_t spawn(const std::string& cmd, Entry*& entry, int out_fd, int close_fd) {
  sigset_t block, old;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &block, &old);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &block);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (out_fd >= 0) {
    posix_spawn_file_actions_adddup2(&fa, out_fd, 1);
    posix_spawn_file_actions_addclose(&fa, out_fd);
    posix_spawn_file_actions_addclose(&fa, close_fd);
  }
  const char* argv[] = {"sh", "-c", cmd.c_str(), nullptr};
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, "/bin/sh", &fa, &attr, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) {
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
    throw std::runtime_error("cannot run /bin/sh -c '" + cmd + "' (" + std::strerror(rc) + ")");
  }
  entry = enroll(detail::kChild, "", pid);
  if (g_dying.load(std::memory_order_seq_cst)) kill(-pid, SIGKILL);
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return pid;
}
}  // namespace

std::string fs_message(const std::string& path, const std::string& what, const std::error_code& ec) {
  return path + ": cannot " + what + " (" + ec.message() + ")";
}

Outputs::~Outputs() {
  if (!kept_) {
    std::error_code ec;
    for (const auto& f : files_) fs::remove(f.published ? f.target : f.tmp, ec);
    for (const auto& [p, e] : adopted_) fs::remove(p, ec);
    for (auto it = created_dirs_.rbegin(); it != created_dirs_.rend(); ++it) fs::remove(it->first, ec);  // only if empty
  }
  for (const auto& f : files_) retire(f.entry);
  for (const auto& [p, e] : adopted_) retire(e);
  for (const auto& [p, e] : created_dirs_) retire(e);
}

void Outputs::make_dir(const std::string& dir) {
  std::error_code ec;
  if (dir.empty()) throw std::runtime_error("empty output directory name");
  if (fs::is_directory(dir, ec)) return;
  if (fs::exists(dir, ec)) throw std::runtime_error(dir + ": cannot create the directory (a file of that name exists)");
  // Record each missing level, outermost first, so that a failure removes exactly those.
  std::vector<fs::path> missing;
  for (fs::path p = fs::path(dir).lexically_normal(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.insert(missing.begin(), p);
    if (p == p.parent_path()) break;
  }
  for (const auto& p : missing) {
    // Enrolled before it exists: a signal in between removes nothing that is not ours (rmdir of
    // a missing directory fails), while enrolling after would leave a window for a leftover.
    created_dirs_.emplace_back(p.string(), enroll(detail::kDir, p.string()));
    if (!fs::create_directory(p, ec) && ec) {
      retire(created_dirs_.back().second);
      created_dirs_.pop_back();
      throw std::runtime_error(fs_message(p.string(), "create the directory", ec));
    }
  }
}

std::string Outputs::stage(const std::string& path) {
  if (path.empty()) throw std::runtime_error("empty output file name");
  std::error_code ec;
  const fs::path target(path);
  if (fs::is_directory(target, ec) || target.filename().empty())
    throw std::runtime_error(path + ": cannot write the file (it is a directory)");
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error(path + ": cannot write the file (directory '" + dir.string() + "' does not exist)");
  if (access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error(path + ": cannot write the file (directory '" + dir.string() + "' is not writable)");
  const std::string tmp = (dir / ("." + target.filename().string() + ".texunit-" + std::to_string(getpid()) + "-" +
                                  std::to_string(g_serial.fetch_add(1)) + ".tmp"))
                              .string();
  files_.push_back({tmp, path, enroll(detail::kFile, tmp), false});
  return tmp;
}

void Outputs::write(const std::string& path, std::string_view bytes) { write_file(stage(path), bytes, path); }

void Outputs::write(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  write_stream(stage(path), fill, path);
}

void Outputs::adopt(const std::string& path) { adopted_.emplace_back(path, enroll(detail::kFile, path)); }

void Outputs::commit() {
  for (auto& f : files_) {
    if (f.published) continue;
    std::error_code ec;
    if (!fs::exists(f.tmp, ec)) throw std::runtime_error(f.target + ": cannot write the file (nothing was written)");
    fs::rename(f.tmp, f.target, ec);
    if (ec) throw std::runtime_error(fs_message(f.target, "write the file", ec));
    retire(f.entry);
    f.entry = nullptr;
  }
  keep();
}

void Outputs::publish() {
  for (auto& f : files_) {
    if (f.published) continue;
    std::error_code ec;
    if (!fs::exists(f.tmp, ec)) throw std::runtime_error(f.target + ": cannot write the file (nothing was written)");
    Entry* const t = enroll(detail::kFile, f.target);
    fs::rename(f.tmp, f.target, ec);
    if (ec) {
      retire(t);
      throw std::runtime_error(fs_message(f.target, "write the file", ec));
    }
    retire(f.entry);
    f.entry = t;
    f.published = true;
  }
}

void Outputs::keep() {
  kept_ = true;
  for (auto& f : files_) retire(std::exchange(f.entry, nullptr));
  for (auto& [p, e] : adopted_) retire(std::exchange(e, nullptr));
  for (auto& [p, e] : created_dirs_) retire(std::exchange(e, nullptr));
}

void Outputs::absorb(Outputs& other) {
  files_.insert(files_.end(), other.files_.begin(), other.files_.end());
  adopted_.insert(adopted_.end(), other.adopted_.begin(), other.adopted_.end());
  created_dirs_.insert(created_dirs_.end(), other.created_dirs_.begin(), other.created_dirs_.end());
  other.files_.clear();
  other.adopted_.clear();
  other.created_dirs_.clear();
}

void check_target(const std::string& path) {
  Outputs probe;  // stage() creates no file: the destructor has nothing to remove
  probe.stage(path);
}

void write_file(const std::string& tmp, std::string_view bytes, const std::string& name) {
  write_checked(tmp, [&](FdBuf& buf, std::ostream&) { buf.put(bytes.data(), bytes.size()); }, name);
}

void write_stream(const std::string& tmp, const std::function<void(std::ostream&)>& fill, const std::string& name) {
  write_checked(tmp, [&](FdBuf&, std::ostream& os) { fill(os); }, name);
}

void write_atomic(const std::string& path, std::string_view bytes) {
  Outputs o;
  o.write(path, bytes);
  o.commit();
}

void write_atomic(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  Outputs o;
  o.write(path, fill);
  o.commit();
}

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string gnuplot(Outputs& outs, const std::string& script, const std::vector<std::string>& pngs) {
  outs.publish();
  for (const auto& p : pngs) outs.adopt(p);
  std::string err;
  const int status = run_capture("gnuplot " + shell_quoted(script) + " 2>&1 >/dev/null", err);
  if (status != 0) {
    if (const auto nl = err.find('\n'); nl != std::string::npos) err.resize(nl);
    return "gnuplot failed on " + script + (err.empty() ? std::string() : " (" + err + ")");
  }
  for (const auto& p : pngs)
    if (!png_complete(p)) return p + ": gnuplot wrote no whole PNG (a full disk?)";
  return "";
}

bool png_complete(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static const char sig[] = "\x89PNG\r\n\x1a\n";
  static const char iend[] = "\0\0\0\0IEND\xae\x42\x60\x82";
  return s.size() >= 8 + 12 && s.compare(0, 8, sig, 8) == 0 && s.compare(s.size() - 12, 12, iend, 12) == 0;
}

void install_signal_cleanup() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);
  sigaddset(&sa.sa_mask, SIGTERM);
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // started with the signal ignored (nohup, `cmd &` in sh): keep it so
    sigaction(sig, &sa, nullptr);
  }
}

void check_stdout_at_exit() {
  std::atexit([] {
    const bool bad = std::fflush(stdout) != 0 || std::ferror(stdout);
    if (!bad) return;
    const int err = errno;
    std::fprintf(stderr, "texunit: error: standard output: cannot write (%s)\n", std::strerror(err ? err : EIO));
    _exit(2);
  });
}

int run(const std::string& cmd) {
  Entry* e = nullptr;
  const pid_t pid = spawn(cmd, e, -1, -1);
  int status = 0;
  reap(pid, status);
  retire(e);
  return status;
}

int run_capture(const std::string& cmd, std::string& out) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("cannot run '" + cmd + "' (" + std::strerror(errno) + ")");
  Entry* e = nullptr;
  pid_t pid = -1;
  try {
    pid = spawn(cmd, e, fds[1], fds[0]);
  } catch (...) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw;
  }
  ::close(fds[1]);
  char buf[4096];
  for (;;) {
    const ssize_t k = ::read(fds[0], buf, sizeof buf);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    out.append(buf, static_cast<size_t>(k));
  }
  ::close(fds[0]);
  int status = 0;
  reap(pid, status);
  retire(e);
  return status;
}

}  // namespace tu::out
