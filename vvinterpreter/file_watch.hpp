// Notices when any of a model's source files changes on disk (by polling
// their modification time and size: simple, and works on every file system).
#pragma once

#include <string>
#include <vector>

namespace vvi {

class file_watch {
 public:
  void watch(const std::vector<std::string>& paths);
  //! True once after any watched file changed (or appeared or vanished).
  bool changed();

 private:
  struct stamp {
    std::string path;
    long long mtime_ns = -1;
    long long size = -1;
  };
  static stamp read(const std::string& path);
  std::vector<stamp> files_;
};

}  // namespace vvi
