// Notices when any of a model's source files changes on disk (by polling
// their modification time and size: simple, and works on every file system).
#pragma once

#include <string>
#include <vector>

namespace vvi {

class file_watch {
 public:
  struct stamp {
    std::string path;
    long long mtime_ns = -1;
    long long size = -1;
  };

  //! Watches these files from now on. A file with a stamp in `as_of`
  //! counts as changed when it differs from that stamp (taken when a build
  //! started: a save during the build is a change after it).
  void watch(const std::vector<std::string>& paths, const std::vector<stamp>& as_of = {});
  //! True once after any watched file changed (or appeared or vanished).
  bool changed();
  std::vector<std::string> paths() const;
  static std::vector<stamp> stamps_of(const std::vector<std::string>& paths);

 private:
  static stamp read(const std::string& path);
  std::vector<stamp> files_;
};

}  // namespace vvi
