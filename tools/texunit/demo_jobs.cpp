#include "demo_jobs.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <numeric>

#include "texunit/parallel.hpp"

namespace tu::cli {

double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  if (!(in >> a >> b >> c)) return "n/a";
  char s[64];
  std::snprintf(s, sizeof s, "%.2f %.2f %.2f", a, b, c);
  return s;
}

void run_demo_jobs(std::vector<DemoJob>& jobs, int threads) {
  std::vector<int> order(jobs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return jobs[size_t(a)].cost > jobs[size_t(b)].cost; });
  const auto t0 = std::chrono::steady_clock::now();
  // par::for_each_index hands the indices out in increasing order: the order is the schedule.
  // Its rethrow is the lowest index in `order`; rethrow the first job in list order instead.
  std::vector<std::exception_ptr> errors(jobs.size());
  static std::atomic<int> generation{0};  // one per call: a thread's index is per pool
  const int gen = ++generation;
  std::atomic<int> workers{0};
  par::for_each_index(static_cast<int>(order.size()), threads, [&](int k) {
    thread_local int worker = -1, pool = 0;  // this thread's index in pool `pool`
    if (pool != gen) pool = gen, worker = workers++;
    DemoJob& j = jobs[static_cast<size_t>(order[static_cast<size_t>(k)])];
    j.worker = worker;
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_s();
    try {
      j.run();
    } catch (...) {
      errors[static_cast<size_t>(order[static_cast<size_t>(k)])] = std::current_exception();
    }
    j.cpu_s = thread_cpu_s() - c0;
    j.start_s = std::chrono::duration<double>(w0 - t0).count();
    j.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  });
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

namespace {
double job_cpu_total(const std::vector<DemoJob>& jobs) {
  double c = 0;
  for (const auto& j : jobs) c += j.cpu_s;
  return c;
}
}  // namespace

void print_demo_times(const std::vector<DemoJob>& jobs, int threads, double wall_s, double cpu_s,
                      double print_wall_s, const std::string& load_before) {
  struct Sec {
    int n = 0;
    double cpu = 0, first = 1e300, last = 0, longest = 0;
    std::string longest_name;
  };
  std::vector<std::string> names;  // sections in list order
  std::map<std::string, Sec> sec;
  for (const auto& j : jobs) {
    if (!sec.count(j.section)) names.push_back(j.section);
    Sec& s = sec[j.section];
    ++s.n;
    s.cpu += j.cpu_s;
    s.first = std::min(s.first, j.start_s);
    s.last = std::max(s.last, j.start_s + j.wall_s);
    if (j.cpu_s > s.longest) s.longest = j.cpu_s, s.longest_name = j.name;
  }
  double job_cpu = 0;
  for (const auto& j : jobs) job_cpu += j.cpu_s;
  std::printf("\ndemo timing: %d threads, load average before %s, after %s\n", par::resolve_threads(threads),
              load_before.c_str(), load_average().c_str());
  std::printf("%-16s %5s %9s %21s %9s  %s\n", "section", "jobs", "CPU s", "wall span s", "longest", "(CPU s)");
  for (const auto& n : names) {
    const Sec& s = sec[n];
    std::printf("%-16s %5d %9.2f %9.2f .. %8.2f %9.2f  %s\n", n.c_str(), s.n, s.cpu, s.first, s.last, s.longest,
                s.longest_name.c_str());
  }
  std::vector<double> per_worker;
  for (const auto& j : jobs) {
    if (static_cast<size_t>(j.worker) >= per_worker.size()) per_worker.resize(static_cast<size_t>(j.worker) + 1);
    per_worker[static_cast<size_t>(j.worker)] += j.cpu_s;
  }
  double busiest = 0;
  std::printf("CPU s per pool thread:");
  for (double c : per_worker) std::printf(" %.2f", c), busiest = std::max(busiest, c);
  std::printf(" (on idle cores the jobs would take the busiest thread's %.2f s: speed-up %.2fx)\n", busiest,
              job_cpu_total(jobs) / std::max(busiest, 1e-9));
  std::vector<const DemoJob*> by_cpu;
  for (const auto& j : jobs) by_cpu.push_back(&j);
  std::sort(by_cpu.begin(), by_cpu.end(), [](const DemoJob* a, const DemoJob* b) { return a->cpu_s > b->cpu_s; });
  std::printf("longest jobs (CPU s, estimate):");
  for (size_t i = 0; i < std::min<size_t>(10, by_cpu.size()); ++i)
    std::printf("%s %s %.2f (%.1f)", i ? "," : "", by_cpu[i]->name.c_str(), by_cpu[i]->cpu_s, by_cpu[i]->cost);
  std::printf("\n");
  std::printf("jobs: %.2f CPU s in %.2f s wall (%.2fx on %d threads); tables and PNGs after the jobs: %.2f s wall; "
              "whole demo: %.2f s wall, %.2f s CPU\n",
              job_cpu, wall_s, job_cpu / std::max(wall_s, 1e-9), par::resolve_threads(threads), print_wall_s,
              wall_s + print_wall_s, cpu_s);
}

}  // namespace tu::cli
