#include "viewer/file_watch.hpp"

#include <sys/stat.h>

namespace vvi {

file_watch::stamp file_watch::read(const std::string& path) {
  stamp s;
  s.path = path;
  struct stat st;
  if (stat(path.c_str(), &st) == 0) {
    s.mtime_ns = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
    s.size = static_cast<long long>(st.st_size);
  }
  return s;
}

void file_watch::watch(const std::vector<std::string>& paths, const std::vector<stamp>& as_of) {
  files_.clear();
  for (const std::string& p : paths) {
    stamp s = read(p);
    for (const stamp& before : as_of)
      if (before.path == p) s = before;
    files_.push_back(s);
  }
}

std::vector<std::string> file_watch::paths() const {
  std::vector<std::string> out;
  for (const stamp& s : files_) out.push_back(s.path);
  return out;
}

std::vector<file_watch::stamp> file_watch::stamps_of(const std::vector<std::string>& paths) {
  std::vector<stamp> out;
  for (const std::string& p : paths) out.push_back(read(p));
  return out;
}

bool file_watch::changed() {
  bool any = false;
  for (stamp& s : files_) {
    stamp now = read(s.path);
    if (now.mtime_ns != s.mtime_ns || now.size != s.size) {
      s = now;
      any = true;
    }
  }
  return any;
}

}  // namespace vvi
