#include "runner/thread_state.hpp"

#include <sys/syscall.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace vvi {

bool safe_to_sample(pid_t pid, pid_t thread) {
  if (thread <= 0) return false;
  std::string task = "/proc/" + std::to_string(pid) + "/task/" + std::to_string(thread);
  std::ifstream calls(task + "/syscall");
  std::string first;
  if (calls >> first) {
    if (first == "running") return true;
    static const long restarted[] = {
        SYS_read,  SYS_write,  SYS_readv,  SYS_writev, SYS_pread64, SYS_pwrite64, SYS_openat,
        SYS_wait4, SYS_waitid, SYS_flock,  SYS_fcntl,  SYS_ioctl,   SYS_futex,
#ifdef SYS_open
        SYS_open,
#endif
    };
    long number = std::strtol(first.c_str(), nullptr, 10);
    return std::find(std::begin(restarted), std::end(restarted), number) != std::end(restarted);
  }
  // Not allowed to look at its system call: only a running thread is safe.
  std::ifstream stat(task + "/stat");
  std::string text;
  std::getline(stat, text);
  std::size_t paren = text.rfind(')');
  return paren != std::string::npos && paren + 2 < text.size() && text[paren + 2] == 'R';
}

}  // namespace vvi
