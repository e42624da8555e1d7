#include "runner/supervisor.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include <vv/io/output_file.hpp>

#include "runner/fault_guard.hpp"
#include "runner/oom_kills.hpp"
#include "runner/report_reader.hpp"
#include "runner/report_words.hpp"
#include "runner/thread_state.hpp"

namespace vvi {

namespace {

using clock_type = report_reader::clock_type;

double seconds_between(clock_type::time_point a, clock_type::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

volatile sig_atomic_t stop_signal = 0;
volatile sig_atomic_t continued = 0;
void on_stop_signal(int sig) { stop_signal = sig; }
void on_continue(int) { continued = 1; }
void on_child(int) {}  // only wakes ppoll

// While a child runs, SIGTERM, SIGINT and SIGHUP end the child first, so
// it leaves nothing behind and this process can clean up after it. These
// signals, SIGCHLD (the child stopped or ended) and SIGCONT (this process
// was stopped, with its terminal's job, and goes on) are only taken inside
// ppoll: no wake-up is lost between a check and the wait.
class supervisor_signals {
 public:
  supervisor_signals() {
    stop_signal = 0;
    continued = 0;
    sigset_t mine;
    sigemptyset(&mine);
    for (int i = 0; i < count; ++i) sigaddset(&mine, signals_[i]);
    sigprocmask(SIG_BLOCK, &mine, &blocked_before_);
    for (int i = 0; i < count; ++i) {
      struct sigaction sa {};
      sa.sa_handler = signals_[i] == SIGCHLD ? on_child : signals_[i] == SIGCONT ? on_continue : on_stop_signal;
      sigemptyset(&sa.sa_mask);
      sigaction(signals_[i], &sa, &old_[i]);
    }
    waiting_mask_ = blocked_before_;
    for (int i = 0; i < count; ++i) sigdelset(&waiting_mask_, signals_[i]);
  }
  ~supervisor_signals() {
    for (int i = 0; i < count; ++i) sigaction(signals_[i], &old_[i], nullptr);
    sigprocmask(SIG_SETMASK, &blocked_before_, nullptr);
  }
  //! The signal mask to wait with.
  const sigset_t* waiting_mask() const { return &waiting_mask_; }

  //! Whether this process went on after a stop since last asked. A stop
  //! outside ppoll leaves SIGCONT pending (blocked there): it is taken
  //! here, or the time stopped would count against the model's block.
  static bool took_continue() {
    sigset_t only_continue;
    sigemptyset(&only_continue);
    sigaddset(&only_continue, SIGCONT);
    timespec no_wait{};
    bool pending = sigtimedwait(&only_continue, nullptr, &no_wait) == SIGCONT;
    bool handled = continued != 0;
    continued = 0;
    return pending || handled;
  }

 private:
  static constexpr int count = 5;
  const int signals_[count] = {SIGTERM, SIGINT, SIGHUP, SIGCHLD, SIGCONT};
  struct sigaction old_[count];
  sigset_t blocked_before_, waiting_mask_;
};

// How long the child may take to answer a request for its stack (it takes
// milliseconds; a loaded machine may hold it up).
constexpr double sample_wait_seconds = 2.0;
// How long a stopped child is left stopped before it counts as stuck: a
// terminal's stop (Ctrl+Z) stops this process too, a moment later.
constexpr double stop_grace_seconds = 0.3;

class watch {
 public:
  watch(pid_t pid, int report, child_end& end, const supervision& s)
      : pid_(pid), report_(report), end_(end), s_(s), reader_(end, s) {}

  void run() {
    supervisor_signals signals;
    waiting_mask_ = signals.waiting_mask();
    last_wake_ = clock_type::now();
    while (!ended_) {
      if (stop_signal) {
        finish(child_end::interrupted, stop_signal);
        break;
      }
      clock_type::time_point now = clock_type::now();
      if (supervisor_signals::took_continue()) {
        // This process was stopped (Ctrl+Z, with the model): that time is
        // not the model's. The last wake-up is at most a second before.
        // The clock is read again: the stop may fall after the first read.
        now = clock_type::now();
        double away = seconds_between(last_wake_, now);
        // At most up to now: a block begun while this process was stopped
        // is timed from when it was read.
        reader_.busy_since = std::min(
            now, reader_.busy_since + std::chrono::duration_cast<clock_type::duration>(std::chrono::duration<double>(away)));
        if (stopped_since_) *stopped_since_ = now;
      }
      last_wake_ = now;
      check_child_state(now);
      if (ended_) break;
      double wait = decide(now);
      if (ended_) break;
      if (!wait_and_read(wait)) break;
    }
    drain_and_reap();
  }

 private:
  // The seconds until something is due (-1: nothing); may end the child.
  double decide(clock_type::time_point now) {
    double wait = -1;
    auto due_in = [&](double seconds) { wait = wait < 0 ? seconds : std::min(wait, seconds); };
    if (reader_.activity_number != notices_for_) {  // a new activity: its own notices
      notices_for_ = reader_.activity_number;
      next_notice_ = s_.notice_after;
    }
    if (stopped_since_) {
      double stopped = seconds_between(*stopped_since_, now);
      if (ending_ == ending_for::stop) return settle_ending(now);
      if (stopped < stop_grace_seconds) {
        due_in(stop_grace_seconds - stopped);
        return wait;
      }
      // Stopped alone: ask where it is, and let it go on just long enough
      // to answer (the request is taken before anything else runs).
      begin_ending(ending_for::stop, now);
      kill(pid_, SIGCONT);
      return settle_ending(now);
    }
    if (ending_ != ending_for::nothing) return settle_ending(now);
    if (sampling_for_notice_) {
      if (reader_.sample_arrived || seconds_between(sample_asked_, now) >= sample_wait_seconds) {
        sampling_for_notice_ = false;
        tell_long_activity();
      } else {
        due_in(sample_wait_seconds - seconds_between(sample_asked_, now));
      }
    }
    if (!reader_.busy()) return wait;
    double busy = seconds_between(reader_.busy_since, now);
    double limit = s_.activity_timeout > 0 ? s_.activity_timeout
                   : end_.activity.what == "close" ? s_.close_timeout
                                                   : 0;
    if (limit > 0) {
      if (busy >= limit) {
        end_.activity_seconds = busy;
        end_.time_limit = limit;
        begin_ending(ending_for::time, now);
        return settle_ending(now);
      }
      due_in(limit - busy);
    }
    if (s_.on_long_activity && next_notice_ > 0 && !sampling_for_notice_) {
      if (busy >= next_notice_) {
        notice_seconds_ = next_notice_;
        notice_activity_ = end_.activity;
        next_notice_ *= 2;
        if (safe_to_sample(pid_, reader_.activity_thread)) {
          ask_for_sample(now);
          sampling_for_notice_ = true;
          due_in(sample_wait_seconds);
        } else {
          tell_long_activity(true);
        }
      } else {
        due_in(next_notice_ - busy);
      }
    }
    // Wake at least every second while a block runs: a stop of this
    // process is then never counted as more than a second of the model's.
    due_in(1.0);
    return wait;
  }

  enum class ending_for { nothing, time, stop };

  void begin_ending(ending_for why, clock_type::time_point now) {
    ending_ = why;
    ask_for_sample(now, true);
  }

  // Ends the child once its stack has come, or it did not answer in time.
  double settle_ending(clock_type::time_point now) {
    double waited = seconds_between(sample_asked_, now);
    if (!reader_.sample_arrived && waited < sample_wait_seconds) return sample_wait_seconds - waited;
    if (ending_ == ending_for::stop) finish(child_end::stopped, stop_signal_seen_);
    else finish(child_end::timed_out, 0);
    return 0;
  }

  // last: the child is ended after it answers (it flushes its output).
  void ask_for_sample(clock_type::time_point now, bool last = false) {
    reader_.sample_arrived = false;
    sample_asked_ = now;
    sigval value{};
    value.sival_int = fault_guard::sample_request(++reader_.sample_asked, last);
    sigqueue(pid_, fault_guard::sample_signal(), value);
  }

  // waiting: it was not asked where it is (safe_to_sample). Told also when
  // the block ended since it was asked: it was true then.
  void tell_long_activity(bool waiting = false) {
    long_activity a;
    a.activity = notice_activity_;
    a.seconds = notice_seconds_;
    a.waiting = waiting;
    a.sample = !waiting && reader_.sample_arrived && end_.sample.why == report_words::running ? &end_.sample : nullptr;
    a.modules = &end_.modules;
    reader_.sample_arrived = false;
    s_.on_long_activity(a);
  }

  void finish(child_end::kind_t kind, int sig) {
    kill(pid_, SIGKILL);
    kill(pid_, SIGCONT);  // a stopped child dies only when it runs
    ended_ = true;
    ended_kind_ = kind;
    ended_signal_ = sig;
  }

  // Stopped, continued or gone (WNOHANG: the pipe may outlive the child
  // when it started processes of its own).
  void check_child_state(clock_type::time_point now) {
    for (;;) {
      int status = 0;
      pid_t r = waitpid(pid_, &status, WNOHANG | WUNTRACED | WCONTINUED);
      if (r != pid_) return;
      if (WIFSTOPPED(status)) {
        if (!stopped_since_) stopped_since_ = now;
        stop_signal_seen_ = WSTOPSIG(status);
      } else if (WIFCONTINUED(status)) {
        if (ending_ != ending_for::stop) stopped_since_.reset();
      } else {
        status_ = status;
        reaped_ = true;
        ended_ = true;
        return;
      }
    }
  }

  // Waits up to `seconds` (-1: until something happens) and reads what the
  // child sent; false when its end of the pipe closed.
  bool wait_and_read(double seconds) {
    pollfd p{report_, POLLIN, 0};
    timespec t{};
    if (seconds >= 0) {
      double whole = std::floor(seconds);
      t.tv_sec = static_cast<time_t>(whole);
      t.tv_nsec = static_cast<long>((seconds - whole) * 1e9) + 1000000;  // a millisecond late, not early
      if (t.tv_nsec >= 1000000000) t.tv_sec += 1, t.tv_nsec -= 1000000000;
    }
    int r = ppoll(&p, 1, seconds >= 0 ? &t : nullptr, waiting_mask_);
    if (r <= 0) return true;  // a signal or the time: the loop looks again
    char buf[8192];
    ssize_t n = read(report_, buf, sizeof buf);
    if (n < 0) return errno == EINTR || errno == EAGAIN;
    if (n == 0) return false;  // the child is gone (or closed the pipe on exit)
    reader_.feed(buf, static_cast<std::size_t>(n));
    return true;
  }

  // What the child sent before it went, then its status.
  void drain_and_reap() {
    if (!reaped_) {
      while (waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
      }
      reaped_ = true;
    }
    int flags = fcntl(report_, F_GETFL);
    fcntl(report_, F_SETFL, flags | O_NONBLOCK);
    char buf[8192];
    ssize_t n;
    while ((n = read(report_, buf, sizeof buf)) > 0 || (n < 0 && errno == EINTR))
      if (n > 0) reader_.feed(buf, static_cast<std::size_t>(n));
    if (ended_kind_) {
      end_.kind = *ended_kind_;
      end_.signal = ended_signal_;
    } else if (WIFSIGNALED(status_)) {
      end_.kind = child_end::crashed;
      end_.signal = WTERMSIG(status_);
    } else {
      end_.kind = child_end::exited;
      end_.exit_code = WIFEXITED(status_) ? WEXITSTATUS(status_) : 1;
    }
  }

  pid_t pid_;
  int report_;
  child_end& end_;
  const supervision& s_;
  report_reader reader_;
  const sigset_t* waiting_mask_ = nullptr;
  bool ended_ = false, reaped_ = false;
  int status_ = 0;
  std::optional<child_end::kind_t> ended_kind_;
  int ended_signal_ = 0;
  clock_type::time_point last_wake_, sample_asked_;
  std::optional<clock_type::time_point> stopped_since_;
  int stop_signal_seen_ = 0;
  ending_for ending_ = ending_for::nothing;
  bool sampling_for_notice_ = false;
  unsigned notices_for_ = 0;
  double next_notice_ = 0, notice_seconds_ = 0;
  child_activity notice_activity_;
};

// The temporaries of files the child did not finish: they are its own
// (runner/output_file.hpp), named so no other run uses them; and, in the
// folders it made temporaries in, any its process ID names (it is reaped:
// they are a dead process's).
void remove_unfinished_files(const child_end& end) {
  for (const auto& [target, temporary] : end.writing) unlink(temporary.c_str());
  for (const std::string& folder : end.writing_folders) vv::io::remove_dead_temporaries(folder);
}

}  // namespace

double seconds_from_environment(const char* name, double fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  char* after = nullptr;
  double v = std::strtod(text, &after);
  return after && *after == '\0' && v > 0 && std::isfinite(v) ? v : fallback;
}

child_end run_supervised(const std::function<int()>& child, const supervision& s) {
  child_end end;
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    end.kind = child_end::exited;
    end.exit_code = child();  // no pipe, no supervision: run unguarded
    return end;
  }
  std::fflush(nullptr);  // nothing buffered is written twice
  long oom_before = oom_kill_count();
  pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]), close(fds[1]);
    end.exit_code = child();
    return end;
  }
  if (pid == 0) {
    // The child goes when its supervisor goes (SIGTERM to the interpreter).
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    close(fds[0]);
    fault_guard::install(fds[1]);
    int code = child();
    std::fflush(nullptr);
    _exit(code);
  }
  close(fds[1]);
  watch(pid, fds[0], end, s).run();
  close(fds[0]);
  long oom_after = oom_kill_count();
  if (oom_before >= 0 && oom_after >= 0) end.oom_kills = oom_after - oom_before;
  remove_unfinished_files(end);
  return end;
}

void remove_module_copies(const child_end& end) {
  for (const auto& [copy, original] : end.modules) unlink(copy.c_str());
}

}  // namespace vvi
