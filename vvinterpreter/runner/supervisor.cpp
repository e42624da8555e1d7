#include "runner/supervisor.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "runner/fault_guard.hpp"

namespace vvi {

namespace {

using clock_type = std::chrono::steady_clock;

volatile sig_atomic_t stop_signal = 0;
void on_stop_signal(int sig) { stop_signal = sig; }

// While a child runs, SIGTERM, SIGINT and SIGHUP end the child first, so
// it leaves nothing behind and this process can clean up after it.
class stop_signals {
 public:
  stop_signals() {
    stop_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < 3; ++i) sigaction(signals_[i], &sa, &old_[i]);
  }
  ~stop_signals() {
    for (int i = 0; i < 3; ++i) sigaction(signals_[i], &old_[i], nullptr);
  }

 private:
  const int signals_[3] = {SIGTERM, SIGINT, SIGHUP};
  struct sigaction old_[3];
};

// Reads the protocol of runner/fault_guard.cpp, one line at a time.
class report_reader {
 public:
  report_reader(child_end& end, const supervision& s) : end_(end), s_(s) {}

  void feed(const char* data, std::size_t n) {
    pending_.append(data, n);
    std::size_t at;
    while ((at = pending_.find('\n')) != std::string::npos) {
      line(pending_.substr(0, at));
      pending_.erase(0, at + 1);
    }
  }

  bool busy() const { return !end_.activity.what.empty(); }
  double busy_seconds() const { return std::chrono::duration<double>(clock_type::now() - since_).count(); }

 private:
  void line(const std::string& l) {
    std::size_t space = l.find(' ');
    std::string key = l.substr(0, space), rest = space == std::string::npos ? "" : l.substr(space + 1);
    if (key == "begin" || key == "activity") {
      // "WHAT STEP"
      std::size_t last = rest.rfind(' ');
      child_activity a;
      a.what = rest.substr(0, last == std::string::npos ? rest.size() : last);
      if (last != std::string::npos) a.step = static_cast<unsigned>(std::strtoul(rest.c_str() + last + 1, nullptr, 10));
      end_.activity = a;
      if (key == "begin") since_ = clock_type::now();
    } else if (key == "done") {
      end_.activity = child_activity();
    } else if (key == "crash") {
      end_.crash.signal = rest;
    } else if (key == "exception") {
      end_.crash.exception = rest;
    } else if (key == "pc") {
      end_.crash.pc = std::strtoull(rest.c_str(), nullptr, 16);
    } else if (key == "frame") {
      end_.crash.frames.push_back(std::strtoull(rest.c_str(), nullptr, 16));
    } else if (key == "map") {
      end_.crash.maps.push_back(rest);
    } else if (key == "module") {
      std::size_t tab = rest.find('\t');
      if (tab != std::string::npos) end_.modules[rest.substr(0, tab)] = rest.substr(tab + 1);
    } else if (key == "end") {
    } else if (s_.on_line) {
      s_.on_line(l);
    }
  }

  child_end& end_;
  const supervision& s_;
  std::string pending_;
  clock_type::time_point since_ = clock_type::now();
};

}  // namespace

child_end run_supervised(const std::function<int()>& child, const supervision& s) {
  child_end end;
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    end.kind = child_end::exited;
    end.exit_code = child();  // no pipe, no supervision: run unguarded
    return end;
  }
  std::fflush(nullptr);  // nothing buffered is written twice
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
  report_reader reader(end, s);
  stop_signals stops;
  bool killed_for_time = false;
  for (;;) {
    if (stop_signal) {
      kill(pid, SIGKILL);
      break;
    }
    int wait_ms = -1;
    if (s.activity_timeout > 0 && reader.busy()) {
      double left = s.activity_timeout - reader.busy_seconds();
      if (left <= 0) {
        kill(pid, SIGKILL);
        killed_for_time = true;
        end.activity_seconds = reader.busy_seconds();
        break;
      }
      wait_ms = static_cast<int>(left * 1000) + 1;
    }
    pollfd p{fds[0], POLLIN, 0};
    int r = poll(&p, 1, wait_ms);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) continue;
    char buf[8192];
    ssize_t n = read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the child is gone (or closed the pipe on exit)
    reader.feed(buf, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (stop_signal) {
    end.kind = child_end::interrupted;
    end.signal = stop_signal;
  } else if (killed_for_time) {
    end.kind = child_end::timed_out;
  } else if (WIFSIGNALED(status)) {
    end.kind = child_end::crashed;
    end.signal = WTERMSIG(status);
  } else {
    end.kind = child_end::exited;
    end.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  }
  return end;
}

void remove_module_copies(const child_end& end) {
  for (const auto& [copy, original] : end.modules) unlink(copy.c_str());
}

}  // namespace vvi
