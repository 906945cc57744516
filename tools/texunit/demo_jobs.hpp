// `texunit demo`'s work as independent jobs (docs/performance.md §6): each job fills its own result
// slot, so the jobs run in any order on any number of threads and the demo prints the same tables
// and writes the same PNGs; the printing happens after every job has run.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace tu::cli {

struct DemoJob {
  std::string section;  // the demo section it belongs to (one line of the timing table)
  std::string name;
  double cost = 1;      // estimated CPU seconds (this machine, one idle core): the order
  std::function<void()> run;
  double start_s = 0, wall_s = 0, cpu_s = 0;  // measured: start after the pool's start, wall, thread CPU
  int worker = 0;                             // the pool thread that ran it (0, 1, ...)
};

// Runs every job on `threads` threads (<= 0: every core), the most expensive first (largest cost,
// then list order): a greedy longest-first schedule, so that no long job starts last. Rethrows
// the exception of the first job in list order that threw, after every thread has stopped.
void run_demo_jobs(std::vector<DemoJob>& jobs, int threads);

// The timing table: per section the jobs' CPU seconds and their wall span, the pool's wall and
// CPU time, the speed-up (CPU / wall), the load average, and the longest jobs.
void print_demo_times(const std::vector<DemoJob>& jobs, int threads, double wall_s, double cpu_s,
                      double print_wall_s, const std::string& load_before);

// The process's CPU time (user + system, every thread), the calling thread's, and the load
// average (/proc/loadavg).
double process_cpu_s();
double thread_cpu_s();
std::string load_average();

// The default scene's renders, RTL renders and the other scenes' rows of the demo: appends their
// jobs; the returned function prints the tables (after run_demo_jobs) and returns false when an
// RTL pixel differs from the C model.
std::function<bool()> demo_render_jobs(const std::string& out_dir, std::vector<DemoJob>& jobs);

}  // namespace tu::cli
