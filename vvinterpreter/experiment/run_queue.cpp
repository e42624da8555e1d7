#include "experiment/run_queue.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <ctime>
#include <poll.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include "experiment/child_process.hpp"

namespace vvi {

namespace {

using clock_type = std::chrono::steady_clock;

volatile std::sig_atomic_t interrupting_signal = 0;
void on_interrupt(int sig) { interrupting_signal = sig; }
void on_child(int) {}  // only wakes ppoll

// SIGINT, SIGTERM, SIGHUP and SIGCHLD are blocked but while waiting in
// ppoll, so none is lost between a check and the wait.
class queue_signals {
 public:
  queue_signals() {
    interrupting_signal = 0;
    sigset_t mine;
    sigemptyset(&mine);
    for (int s : signals_) sigaddset(&mine, s);
    sigprocmask(SIG_BLOCK, &mine, &before_);
    for (std::size_t i = 0; i < count; ++i) {
      struct sigaction sa {};
      sa.sa_handler = signals_[i] == SIGCHLD ? on_child : on_interrupt;
      sigemptyset(&sa.sa_mask);
      sigaction(signals_[i], &sa, &old_[i]);
    }
    waiting_ = before_;
    for (int s : signals_) sigdelset(&waiting_, s);
  }
  ~queue_signals() {
    for (std::size_t i = 0; i < count; ++i) sigaction(signals_[i], &old_[i], nullptr);
    sigprocmask(SIG_SETMASK, &before_, nullptr);
  }
  void wait(double seconds) const {
    timespec t{static_cast<time_t>(seconds), static_cast<long>((seconds - static_cast<time_t>(seconds)) * 1e9)};
    ppoll(nullptr, 0, &t, &waiting_);
  }

 private:
  static constexpr std::size_t count = 4;
  const int signals_[count] = {SIGINT, SIGTERM, SIGHUP, SIGCHLD};
  struct sigaction old_[count];
  sigset_t before_, waiting_;
};

struct running {
  pid_t pid;
  unsigned number;
  clock_type::time_point since;
};

// Reaps the runs that ended; true when one did.
bool reap(std::vector<running>& active, bool interrupted, const std::function<void(const run_end&)>& ended) {
  bool any = false;
  for (std::size_t i = 0; i < active.size();) {
    int status = 0;
    pid_t got = waitpid(active[i].pid, &status, WNOHANG);
    if (got == 0 || (got < 0 && errno == EINTR)) {
      ++i;
      continue;
    }
    run_end e;
    e.number = active[i].number;
    e.wait_status = status;
    e.interrupted = interrupted;
    e.seconds = std::chrono::duration<double>(clock_type::now() - active[i].since).count();
    active.erase(active.begin() + static_cast<long>(i));
    ended(e);
    any = true;
  }
  return any;
}

}  // namespace

unsigned usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  int n = CPU_COUNT(&set);
  return n > 0 ? static_cast<unsigned>(n) : 1;
}

int run_all(const std::vector<queued_run>& runs, unsigned jobs, const std::function<void(const run_end&)>& ended,
            const std::function<void()>& tick) {
  queue_signals signals;
  std::vector<running> active;
  std::size_t next = 0;
  auto last_tick = clock_type::now();
  while (next < runs.size() || !active.empty()) {
    if (interrupting_signal) break;
    while (next < runs.size() && active.size() < jobs) {
      const queued_run& r = runs[next++];
      std::string why;
      pid_t pid = start_child(r.command, r.folder, run_output_file, run_error_file, why);
      if (pid < 0) {
        run_end e;
        e.number = r.number;
        e.start_error = why;
        ended(e);
        continue;
      }
      active.push_back({pid, r.number, clock_type::now()});
    }
    if (!reap(active, false, ended)) signals.wait(0.5);
    if (clock_type::now() - last_tick >= std::chrono::milliseconds(500)) {
      tick();
      last_tick = clock_type::now();
    }
  }
  int sig = interrupting_signal;
  if (!sig) return 0;
  // Interrupted: the running runs are told to end (the batch mode removes
  // what it was writing), and killed if they do not within 10 s.
  for (const running& r : active) kill(-r.pid, SIGTERM);
  auto deadline = clock_type::now() + std::chrono::seconds(10);
  while (!active.empty()) {
    if (clock_type::now() > deadline)
      for (const running& r : active) kill(-r.pid, SIGKILL);
    if (!reap(active, true, ended)) signals.wait(0.2);
  }
  return sig;
}

}  // namespace vvi
