// The one checked output path of texunit: every file the CLI and the library writers produce is
// written all or none.
//
// An Outputs object is a set of output files (and directories) written together: each file is
// written to a hidden temporary beside its target (stage() / write()) and renamed into place by
// commit() once every output and every check has succeeded. Every byte is checked: write(2)'s
// result (a full disk is ENOSPC there), the stream state of a streamed writer, close(2); fsync is
// not done (a crash of the machine is out of scope, a failed write is not). A command that throws
// before commit() leaves nothing behind: the destructor removes the temporaries and the
// directories make_dir() created. Targets are checked when staged (their directory exists and is
// writable, they are not a directory), so an impossible output fails the command before the work.
//
// install_signal_cleanup() makes SIGINT / SIGTERM do the same: every temporary alive (of every
// Outputs object, on every thread) is unlinked, every directory created is removed, every child
// started by run() is killed and reaped, and the process exits 128 + signal (130, 143).
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <sys/types.h>

namespace tu::out {

namespace detail {
struct Entry;  // a path or child known to the signal handler (output.cpp)
}

class Outputs {
 public:
  Outputs() = default;
  Outputs(const Outputs&) = delete;
  Outputs& operator=(const Outputs&) = delete;
  ~Outputs();
  // Creates `dir` (and missing parents) unless it exists; removed again on failure.
  void make_dir(const std::string& dir);
  // Returns the temporary path to write `path` to (throws a worded std::runtime_error when the
  // target cannot be written: missing directory, unwritable directory, the target is a directory).
  // The caller writes it with write_file() / write_stream() (or hands it to a library writer).
  std::string stage(const std::string& path);
  // stage() and write `bytes` to the temporary, checked.
  void write(const std::string& path, std::string_view bytes);
  // stage() and stream into the temporary (large files are not held in memory), checked.
  void write(const std::string& path, const std::function<void(std::ostream&)>& fill);
  // A file that a child process writes in place (gnuplot's PNG): removed on failure or a signal.
  void adopt(const std::string& path);
  // Renames every staged file into place, in stage() order, and keeps them.
  void commit();
  // Renames every staged file into place but still owns them: a later failure (a child that reads
  // them and fails) or a signal removes them; keep() ends that.
  void publish();
  void keep();
  // Takes over every file and directory of `other` (which then owns nothing): a part written on
  // its own (a plot that may fail alone) joins the command's outputs.
  void absorb(Outputs& other);

 private:
  struct File {
    std::string tmp, target;
    detail::Entry* entry;  // the temporary's registration (the target's once published)
    bool published;
  };
  std::vector<File> files_;
  std::vector<std::pair<std::string, detail::Entry*>> adopted_;
  std::vector<std::pair<std::string, detail::Entry*>> created_dirs_;  // outermost first
  bool kept_ = false;
};

// Throws the message stage() would (missing or unwritable directory, a directory), creating
// nothing: a command checks its targets before its work with it.
void check_target(const std::string& path);

// Checked writes to a path that is already a staged temporary (a library writer given the
// temporary by its caller); `name` is the target named in a message.
void write_file(const std::string& tmp, std::string_view bytes, const std::string& name);
void write_stream(const std::string& tmp, const std::function<void(std::ostream&)>& fill, const std::string& name);
// One file, all or none: an Outputs of that file alone.
void write_atomic(const std::string& path, std::string_view bytes);
void write_atomic(const std::string& path, const std::function<void(std::ostream&)>& fill);

// True when `path` is a whole PNG (signature and a final IEND chunk): a check of a file another
// program wrote (gnuplot), which a full disk can cut short without an error exit.
bool png_complete(const std::string& path);

// A plot: publishes what `outs` staged (the data and `script`, which gnuplot reads by their
// names), adopts `pngs` and runs gnuplot on `script` (a child: killed on a signal). Returns "" on
// success, else why (gnuplot's exit status and first line of its messages, or a PNG missing or
// cut short); every file stays owned by `outs`, so a failure removes them all.
std::string gnuplot(Outputs& outs, const std::string& script, const std::vector<std::string>& pngs);
// `s` as one word for /bin/sh.
std::string shell_quoted(const std::string& s);

// Installs the SIGINT / SIGTERM handler described above (once, from main()).
void install_signal_cleanup();

// Registers an exit check of standard output (std::cout and stdio share its buffer): when a
// write to it failed or its final flush fails (`texunit cosim --json > F` on a full disk), the
// process exits 2 with a message instead of 0.
void check_stdout_at_exit();

// Runs `/bin/sh -c cmd` in its own process group, known to the signal handler (killed with the
// group and reaped on SIGINT / SIGTERM); returns its wait status as std::system does.
int run(const std::string& cmd);
// The same, with the command's standard output captured in `out`.
int run_capture(const std::string& cmd, std::string& out);

// A file-system error as a sentence: "PATH: cannot WHAT (reason)", without the library's
// "filesystem error: ..." text.
std::string fs_message(const std::string& path, const std::string& what, const std::error_code& ec);

}  // namespace tu::out
