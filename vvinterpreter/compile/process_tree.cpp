#include "compile/process_tree.hpp"

#include <dirent.h>
#include <signal.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vvi {

namespace {

// The parent of a process, from /proc/PID/stat ("PID (NAME) STATE PPID
// ..."; the name may hold spaces and parentheses, so it is read from the
// last ')'), or 0 when it is gone.
pid_t parent_of(const std::string& pid) {
  std::ifstream in("/proc/" + pid + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t name_end = stat.rfind(')');
  if (name_end == std::string::npos) return 0;
  std::istringstream rest(stat.substr(name_end + 1));
  std::string state;
  long parent = 0;
  rest >> state >> parent;
  return static_cast<pid_t>(parent);
}

std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> children;
  DIR* proc = opendir("/proc");
  if (!proc) return children;
  while (dirent* e = readdir(proc)) {
    char* end = nullptr;
    long pid = std::strtol(e->d_name, &end, 10);
    if (pid > 0 && *end == '\0' && parent_of(e->d_name) == parent) children.push_back(static_cast<pid_t>(pid));
  }
  closedir(proc);
  return children;
}

void kill_descendants(pid_t pid) {
  for (pid_t child : children_of(pid)) {
    kill(child, SIGSTOP);
    kill_descendants(child);
    kill(child, SIGKILL);
  }
}

}  // namespace

void end_process_tree(pid_t pid) {
  kill(pid, SIGSTOP);
  kill_descendants(pid);
  kill(pid, SIGTERM);
  kill(pid, SIGCONT);
}

}  // namespace vvi
