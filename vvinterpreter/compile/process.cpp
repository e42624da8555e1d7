#include "compile/process.hpp"
#include "compile/process_tree.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace vvi {

namespace {

// Reads the child's output until every process holding the pipe has ended.
// With `cancel`: looks at it every tenth of a second, and once it is set
// ends the child and its children; a child that does not end within two
// seconds of that is killed, and two seconds later the pipe is left to
// whatever still holds it.
void read_output(int fd, pid_t pid, const std::atomic<bool>* cancel, process_result& r) {
  using clock = std::chrono::steady_clock;
  clock::time_point ended_at;
  bool killed = false;
  char buf[4096];
  for (;;) {
    if (cancel && !r.cancelled && cancel->load()) {
      r.cancelled = true;
      ended_at = clock::now();
      end_process_tree(pid);
    }
    if (r.cancelled && !killed && clock::now() - ended_at > std::chrono::seconds(2)) {
      killed = true;
      kill(pid, SIGKILL);
    }
    if (killed && clock::now() - ended_at > std::chrono::seconds(4)) break;
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, cancel ? 100 : -1);
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n > 0) r.output.append(buf, static_cast<std::size_t>(n));
    else if (n == 0 || errno != EINTR) break;
  }
}

}  // namespace

process_result run_process(const std::vector<std::string>& argv, int niceness, const std::atomic<bool>* cancel) {
  process_result r;
  int pipe_fds[2];
  if (argv.empty() || pipe(pipe_fds) != 0) {
    r.output = "cannot create a pipe: " + std::string(std::strerror(errno));
    return r;
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = fork();
  if (pid < 0) {
    r.output = "cannot start " + argv[0] + ": " + std::strerror(errno);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    return r;
  }
  if (pid == 0) {
    // The compiler goes when the interpreter goes (killed, or closed
    // mid-build): no compiler left running on its own.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (niceness) (void)!nice(niceness);
    dup2(pipe_fds[1], STDOUT_FILENO);
    dup2(pipe_fds[1], STDERR_FILENO);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    execvp(args[0], args.data());
    std::string msg = "cannot run " + argv[0] + ": " + std::strerror(errno) + "\n";
    (void)!write(STDERR_FILENO, msg.data(), msg.size());
    _exit(127);
  }
  close(pipe_fds[1]);
  read_output(pipe_fds[0], pid, cancel, r);
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) s += (s.empty() ? "" : " ") + a;
  return s;
}

}  // namespace vvi
