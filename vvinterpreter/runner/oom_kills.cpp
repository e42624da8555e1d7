#include "runner/oom_kills.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace vvi {

namespace {

// The number after `key` in a file of "key value" lines, or -1.
long counter(const std::string& file, const std::string& key) {
  std::ifstream in(file);
  std::string k;
  long v;
  while (in >> k >> v)
    if (k == key) return v;
  return -1;
}

// This process's cgroup as /proc/self/cgroup names it: v2 ("0::/path") or
// the v1 memory controller ("N:memory:/path"); "" when it has none.
std::string cgroup_path(bool v2) {
  std::ifstream in("/proc/self/cgroup");
  for (std::string l; std::getline(in, l);) {
    std::size_t first = l.find(':'), second = l.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    std::string controllers = l.substr(first + 1, second - first - 1);
    if (v2 ? controllers.empty() : controllers == "memory") return l.substr(second + 1);
  }
  return "";
}

// The counter in the cgroup's own file, or in the file at the mount's root
// (a container sees its own cgroup there).
long cgroup_counter(const std::string& mount, const std::string& path, const std::string& file) {
  long v = counter(mount + path + "/" + file, "oom_kill");
  return v >= 0 ? v : counter(mount + "/" + file, "oom_kill");
}

}  // namespace

long oom_kill_count() {
  long total = -1;
  auto add = [&](long v) {
    if (v >= 0) total = (total < 0 ? 0 : total) + v;
  };
  add(counter("/proc/vmstat", "oom_kill"));
  std::string v2 = cgroup_path(true), v1 = cgroup_path(false);
  long unified = cgroup_counter("/sys/fs/cgroup", v2, "memory.events");
  add(unified >= 0 ? unified : cgroup_counter("/sys/fs/cgroup/unified", v2, "memory.events"));
  add(cgroup_counter("/sys/fs/cgroup/memory", v1, "memory.oom_control"));
  return total;
}

}  // namespace vvi
