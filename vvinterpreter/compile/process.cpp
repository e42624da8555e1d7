#include "compile/process.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace vvi {

process_result run_process(const std::vector<std::string>& argv, int niceness) {
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
  char buf[4096];
  ssize_t n;
  while ((n = read(pipe_fds[0], buf, sizeof buf)) > 0 || (n < 0 && errno == EINTR))
    if (n > 0) r.output.append(buf, static_cast<std::size_t>(n));
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
