// A file the interpreter writes for the user (--export, --screenshot,
// --plots, the viewer's export): written whole into a temporary of its own,
// then put in place, so a failure or a kill leaves the previous file as it
// was and no half-written one.
//
// * The temporary is named for this process and no other
//   (".NAME.vvtmp-PID-NS-RANDOM.EXT", NS the PID namespace): two runs
//   writing one path never share it, and its name fits whenever the
//   target's name does (the stem is shortened to fit NAME_MAX).
// * A symbolic link is written through to its target, also when the
//   target does not exist yet; a loop of links is refused. The link stays.
// * A character device (/dev/null, a terminal) or a FIFO is written
//   through, reporting write errors (a full device); a folder, a block
//   device or a socket is refused. Nothing special is ever renamed over.
// * Temporaries a killed run left in the folder (its process is gone) are
//   removed by the next file written there; the supervisor removes those
//   of a child it saw die (runner/fault_guard.hpp: note_writing).
#pragma once

#include <functional>
#include <string>

namespace vvi {

class output_file {
 public:
  //! Decides where `path` goes; error() says why it cannot be written.
  explicit output_file(std::string path);
  //! An unfinished temporary is removed.
  ~output_file();
  output_file(const output_file&) = delete;
  output_file& operator=(const output_file&) = delete;

  //! Why the path cannot be written (then nothing else applies), or "".
  const std::string& error() const { return error_; }
  //! Where the writer writes the whole file: a new name with the path's
  //! extension (writers choose the format by it).
  const std::string& temporary() const { return temporary_; }
  //! Puts the temporary in place (a rename, or a copy into a device or a
  //! FIFO); "" or the error.
  std::string commit();
  //! A writer's message about the temporary, about the path instead.
  std::string in_users_terms(std::string message) const;

 private:
  std::string path_, target_, temporary_, error_;
  bool stream_ = false;     // a character device or a FIFO: written through
  bool committed_ = false;
};

//! Writes `path` through an output_file: write(temporary) returns "" or its
//! error; returns "" or the error, about `path`.
std::string write_output(const std::string& path, const std::function<std::string(const std::string&)>& write);

//! The temporaries of dead processes of this PID namespace in `folder`
//! (output_file's names) are removed.
void remove_stale_temporaries(const std::string& folder);

}  // namespace vvi
