#include "file_watch.hpp"

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

void file_watch::watch(const std::vector<std::string>& paths) {
  files_.clear();
  for (const std::string& p : paths) files_.push_back(read(p));
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
