// A sweep's folder (--out DIR): made when it is missing, taken when it is
// empty or holds the same sweep (resuming it), refused when it holds
// another sweep or other files, so nothing there is ever lost. One process
// at a time works in it (a lock, DIR/.lock).
#pragma once

#include <string>

namespace vvi {

class sweep_folder {
 public:
  //! Opens `dir` for the sweep whose identity text this is (written to
  //! DIR/sweep.txt when it is new); error() says why not.
  sweep_folder(const std::string& dir, const std::string& identity_text);
  ~sweep_folder();
  sweep_folder(const sweep_folder&) = delete;
  sweep_folder& operator=(const sweep_folder&) = delete;

  const std::string& error() const { return error_; }
  const std::string& path() const { return dir_; }

 private:
  std::string dir_, error_;
  int lock_ = -1;
};

//! Writes DIR/NAME atomically (every file of a sweep's folder is written
//! so: a temporary, then a rename): "" or why not.
std::string write_in_folder(const std::string& dir, const std::string& name, const std::string& text);

}  // namespace vvi
