// A command started in the background, in a process group of its own,
// whose output the test reads while it runs: to stop or kill it (or a
// process of its group) at a chosen moment.
#pragma once

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

#include "run_interpreter.hpp"

namespace test_run {

class spawned {
 public:
  explicit spawned(const std::vector<std::string>& argv, int timeout_seconds = 120) {
    int out_pipe[2], err_pipe[2];
    if (pipe(out_pipe) != 0 || pipe(err_pipe) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out_pipe[1], STDOUT_FILENO);
      dup2(err_pipe[1], STDERR_FILENO);
      close(out_pipe[0]), close(err_pipe[0]), close(out_pipe[1]), close(err_pipe[1]);
      setpgid(0, 0);
      std::vector<char*> a;
      for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
      a.push_back(nullptr);
      execvp(a[0], a.data());
      _exit(127);
    }
    setpgid(pid_, pid_);  // also here: the group exists before the test signals it
    close(out_pipe[1]), close(err_pipe[1]);
    fds_[0] = {out_pipe[0], POLLIN, 0};
    fds_[1] = {err_pipe[0], POLLIN, 0};
    deadline_ = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_seconds);
  }
  spawned(const spawned&) = delete;
  spawned& operator=(const spawned&) = delete;

  ~spawned() {
    if (pid_ > 0 && !reaped_) {
      kill(-pid_, SIGKILL);
      int status = 0;
      waitpid(pid_, &status, 0);
    }
    for (pollfd& f : fds_)
      if (f.fd >= 0) close(f.fd);
  }

  bool started() const { return pid_ > 0; }
  //! Still running (it has not ended; it is not reaped here).
  bool running() const {
    siginfo_t info{};
    return waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == 0;
  }
  pid_t pid() const { return pid_; }
  //! Sends sig to the whole group, as a terminal does (Ctrl+Z is SIGTSTP).
  void signal_group(int sig) const { kill(-pid_, sig); }

  //! Reads output until stdout holds `part` (true), or the output ends or
  //! `seconds` pass (false).
  bool wait_for_out(const std::string& part, double seconds) {
    auto until = std::chrono::steady_clock::now() +
                 std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
    while (out.find(part) == std::string::npos)
      if (!pump(until)) return out.find(part) != std::string::npos;
    return true;
  }

  //! Waits for the end (killing the group after the time limit).
  result finish() {
    while (pump(deadline_)) {
    }
    result r;
    if (fds_[0].fd >= 0 || fds_[1].fd >= 0) {
      r.timed_out = true;
      kill(-pid_, SIGKILL);
    }
    int status = 0;
    waitpid(pid_, &status, 0);
    reaped_ = true;
    r.status = (!r.timed_out && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    r.out = out, r.err = err;
    return r;
  }

  std::string out, err;

 private:
  // Reads what there is, waiting at most until `until`; false when both
  // pipes are closed or the time is up.
  bool pump(std::chrono::steady_clock::time_point until) {
    if (fds_[0].fd < 0 && fds_[1].fd < 0) return false;
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    if (poll(fds_, 2, static_cast<int>(std::min<long>(left.count(), 200))) <= 0) return true;
    for (int i = 0; i < 2; ++i) {
      if (fds_[i].fd < 0 || !(fds_[i].revents & (POLLIN | POLLHUP))) continue;
      char buf[4096];
      ssize_t n = read(fds_[i].fd, buf, sizeof buf);
      if (n > 0) (i == 0 ? out : err).append(buf, static_cast<std::size_t>(n));
      else close(fds_[i].fd), fds_[i].fd = -1;
    }
    return true;
  }

  pid_t pid_ = -1;
  bool reaped_ = false;
  pollfd fds_[2] = {{-1, 0, 0}, {-1, 0, 0}};
  std::chrono::steady_clock::time_point deadline_;
};

}  // namespace test_run
