#pragma once
// Times a region in wall-clock and in this thread's CPU time. On a machine
// shared with other work the CPU time is the steadier of the two: it leaves
// out the time the thread waited for a core.
#include <chrono>
#include <ctime>

#include "bench_result.hpp"

class stopwatch {
 public:
  stopwatch() : wall_(std::chrono::steady_clock::now()), cpu_(cpu_ms()) {}
  // Writes the time since construction into r.ms and r.cpu_ms.
  void stop(bench_result& r) const
  {
    r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_).count();
    r.cpu_ms = cpu_ms() - cpu_;
  }

 private:
  static double cpu_ms()
  {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
  }
  std::chrono::steady_clock::time_point wall_;
  double cpu_;
};
