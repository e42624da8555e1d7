// Runs vvinterpreter (or any command) as a user would, with a time limit,
// capturing its exit status, standard output and standard error.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

namespace test_run {

struct result {
  int status = -1;  // exit status; -1 when killed (e.g. after the time limit)
  bool timed_out = false;
  std::string out, err;
};

inline result run(const std::vector<std::string>& argv, int timeout_seconds = 120) {
  result r;
  int out_pipe[2], err_pipe[2];
  if (pipe(out_pipe) != 0 || pipe(err_pipe) != 0) return r;
  pid_t pid = fork();
  if (pid == 0) {
    dup2(out_pipe[1], STDOUT_FILENO);
    dup2(err_pipe[1], STDERR_FILENO);
    close(out_pipe[0]), close(err_pipe[0]), close(out_pipe[1]), close(err_pipe[1]);
    setpgid(0, 0);  // its own group, so a time-out can stop its children too
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  close(out_pipe[1]), close(err_pipe[1]);
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_seconds);
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  int open_fds = 2;
  while (open_fds > 0) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
      break;
    }
    if (poll(fds, 2, static_cast<int>(left.count())) <= 0) continue;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP))) continue;
      char buf[4096];
      ssize_t n = read(fds[i].fd, buf, sizeof buf);
      if (n > 0) (i == 0 ? r.out : r.err).append(buf, static_cast<std::size_t>(n));
      else close(fds[i].fd), fds[i].fd = -1, --open_fds;
    }
  }
  for (pollfd& f : fds)
    if (f.fd >= 0) close(f.fd);
  int status = 0;
  waitpid(pid, &status, 0);
  r.status = (!r.timed_out && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  return r;
}

//! vvinterpreter with the test suite's shared model cache (one precompiled
//! header for all tests) and the given arguments.
inline std::vector<std::string> interpreter(std::vector<std::string> args) {
  std::vector<std::string> argv = {VV_INTERPRETER, "--cache", VV_TEST_CACHE};
  argv.insert(argv.end(), args.begin(), args.end());
  return argv;
}

//! The same inside a virtual X display (Xvfb), for the viewer. Test
//! executables run side by side, so each starts its search for a free
//! display at a number of its own (xvfb-run -a checks, then starts: two
//! searches from the same number can race for one display).
inline std::vector<std::string> in_virtual_display(std::vector<std::string> argv) {
  const std::string first_display = std::to_string(100 + getpid() % 20000);
  std::vector<std::string> out = {"xvfb-run", "-a", "-n", first_display, "-s", "-screen 0 1280x1024x24"};
  out.insert(out.end(), argv.begin(), argv.end());
  return out;
}

}  // namespace test_run
