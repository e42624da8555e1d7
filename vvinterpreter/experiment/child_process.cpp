#include "experiment/child_process.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace vvi {

namespace {

// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void become(const std::vector<char*>& args, pid_t parent, int report) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);  // the sweep is gone already
  setpgid(0, 0);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);  // the sweep blocks signals it waits for
  execv(args[0], args.data());
  int e = errno;
  if (report >= 0) (void)!write(report, &e, sizeof e);
  _exit(127);
}

std::vector<char*> c_args(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  return args;
}

// The child's exec failure (errno through a close-on-exec pipe), or 0.
int exec_error(int report) {
  int e = 0;
  ssize_t n;
  while ((n = read(report, &e, sizeof e)) < 0 && errno == EINTR) {
  }
  close(report);
  return n == sizeof e ? e : 0;
}

}  // namespace

pid_t start_child(const std::vector<std::string>& argv, const std::string& folder, const std::string& out,
                  const std::string& err, std::string& why) {
  std::vector<char*> args = c_args(argv);
  std::string out_path = folder + "/" + out, err_path = folder + "/" + err;
  int out_fd = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  int err_fd = out_fd < 0 ? -1 : open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  int report[2] = {-1, -1};
  if (out_fd < 0 || err_fd < 0 || pipe2(report, O_CLOEXEC) != 0) {
    why = (out_fd < 0 ? out_path : err_fd < 0 ? err_path : std::string("a pipe")) + ": " + std::strerror(errno);
    if (out_fd >= 0) close(out_fd);
    if (err_fd >= 0) close(err_fd);
    return -1;
  }
  pid_t parent = getpid();
  pid_t pid = fork();
  if (pid == 0) {
    close(report[0]);
    if (dup2(out_fd, STDOUT_FILENO) < 0 || dup2(err_fd, STDERR_FILENO) < 0 || chdir(folder.c_str()) != 0) {
      int e = errno;
      (void)!write(report[1], &e, sizeof e);
      _exit(127);
    }
    become(args, parent, report[1]);
  }
  int fork_errno = errno;
  close(out_fd), close(err_fd), close(report[1]);
  if (pid < 0) {
    close(report[0]);
    why = std::string("cannot start a run: ") + std::strerror(fork_errno);
    return -1;
  }
  setpgid(pid, pid);  // also here: the group exists before the sweep signals it
  if (int e = exec_error(report[0])) {
    int status = 0;
    waitpid(pid, &status, 0);
    why = "cannot run " + argv[0] + " in " + folder + ": " + std::strerror(e);
    return -1;
  }
  return pid;
}

captured run_captured(const std::vector<std::string>& argv) {
  captured c;
  std::vector<char*> args = c_args(argv);
  int out_pipe[2], err_pipe[2];
  if (pipe2(out_pipe, O_CLOEXEC) != 0) return c;
  if (pipe2(err_pipe, O_CLOEXEC) != 0) {
    close(out_pipe[0]), close(out_pipe[1]);
    return c;
  }
  pid_t parent = getpid();
  pid_t pid = fork();
  if (pid == 0) {
    dup2(out_pipe[1], STDOUT_FILENO);
    dup2(err_pipe[1], STDERR_FILENO);
    become(args, parent, -1);
  }
  close(out_pipe[1]), close(err_pipe[1]);
  if (pid < 0) {
    close(out_pipe[0]), close(err_pipe[0]);
    return c;
  }
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  for (int open_fds = 2; open_fds > 0;) {
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buf[4096];
      ssize_t n = read(fds[i].fd, buf, sizeof buf);
      if (n > 0) (i == 0 ? c.out : c.err).append(buf, static_cast<std::size_t>(n));
      else if (n == 0 || errno != EINTR) close(fds[i].fd), fds[i].fd = -1, --open_fds;
    }
  }
  for (pollfd& f : fds)
    if (f.fd >= 0) close(f.fd);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  c.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return c;
}

std::string how_it_ended(int wait_status) {
  if (WIFEXITED(wait_status)) return "exited with status " + std::to_string(WEXITSTATUS(wait_status));
  if (WIFSIGNALED(wait_status)) {
    const char* name = sigabbrev_np(WTERMSIG(wait_status));
    return std::string("killed by SIG") + (name ? name : "?");
  }
  return "ended";
}

}  // namespace vvi
