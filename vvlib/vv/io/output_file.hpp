// Writing a file for the user safely: the one implementation that vvlib's
// writers, the translator (vvc -o) and the host (exports, screenshots,
// plots, the private copies of model plugins) share.
//
//  * A regular file, or a name not taken yet, is replaced atomically: the
//    bytes go into a temporary of a unique name beside it, which is then
//    renamed over it. The name holds the writer's PID, its PID namespace
//    and random letters (".NAME.vvtmp-PID-NS-XXXXXX.EXT", created with
//    O_EXCL), so no two processes, containers or threads share one, and it
//    fits wherever the target's name fits (the stem is shortened to the
//    folder's NAME_MAX). A new file gets the mode any new file gets; a
//    file that exists keeps its own.
//  * A temporary whose process is gone (a kill -9, a crash) is recognised
//    by its name and removed by the next write in its folder; those of
//    live processes and of other PID namespaces stay.
//  * Through a symbolic link the file it names is written (created, when
//    the link dangles); the link stays. A loop of links, or more than 40
//    in a row, is refused.
//  * A character device (/dev/null, a terminal) or a FIFO is written
//    through, as a shell redirection would, and a failed write (/dev/full)
//    is an error; it is never renamed over. A FIFO without a reader is
//    waited for a while, never for ever. A folder, a block device or a
//    socket is refused.
//  * A file that is this process's own temporary (a writer handed a path
//    by output_file::make_temporary) is written in place: it is nobody
//    else's yet, and a second temporary would be one more to leave behind.
//
// Errors are reasons ("it is a folder", "No space left on device"); the
// caller says which file ("PATH: cannot write file: REASON").
#pragma once

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "../error.hpp"

namespace vv::io {

namespace detail {

inline constexpr const char* temporary_marker = ".vvtmp-";

// The folder of a path as written ("." for a bare name).
inline std::string folder_part(const std::string& path) {
  std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

inline std::string name_part(const std::string& path) {
  std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

inline std::string in_folder(const std::string& folder, const std::string& name) {
  return (folder == "/" ? "" : folder) + "/" + name;
}

// A name's extension as written, with its dot ("" when none).
inline std::string extension_part(const std::string& name) {
  std::size_t dot = name.rfind('.');
  return dot == std::string::npos || dot == 0 ? "" : name.substr(dot);
}

// This process's PID namespace as the inode of /proc/self/ns/pid, in hex
// ("0": unknown): a PID names a process only within its namespace.
inline std::string pid_namespace() {
  char link[64];
  ssize_t n = ::readlink("/proc/self/ns/pid", link, sizeof link - 1);
  if (n <= 0) return "0";
  link[n] = '\0';
  const char* digits = std::strchr(link, '[');
  unsigned long long inode = digits ? std::strtoull(digits + 1, nullptr, 10) : 0;
  char hex[24];
  std::snprintf(hex, sizeof hex, "%llx", inode);
  return hex;
}

// The PID that wrote a temporary named `name` in the PID namespace `ns`,
// or 0 when the name is no temporary of that namespace.
inline long temporary_owner(const std::string& name, const std::string& ns) {
  std::size_t at = name.rfind(temporary_marker);
  if (name.empty() || name[0] != '.' || at == std::string::npos) return 0;
  const char* digits = name.c_str() + at + std::strlen(temporary_marker);
  char* after = nullptr;
  long pid = std::strtol(digits, &after, 10);
  if (pid <= 0 || after == digits || *after != '-') return 0;
  std::size_t ns_at = static_cast<std::size_t>(after + 1 - name.c_str());
  if (name.compare(ns_at, ns.size() + 1, ns + "-") != 0) return 0;
  return pid;
}

// Cuts text to at most `bytes`, never inside a UTF-8 character.
inline std::string shortened(const std::string& text, std::size_t bytes) {
  if (text.size() <= bytes) return text;
  std::size_t n = bytes;
  while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;
  return text.substr(0, n);
}

inline std::size_t name_max(const std::string& folder) {
  long n = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  return static_cast<std::size_t>(n > 0 ? n : NAME_MAX);
}

// The mode a new file gets: 0666 less the umask. Read from /proc, since
// umask() can only be read by setting it, which races with other threads.
inline mode_t new_file_mode() {
  if (std::FILE* f = std::fopen("/proc/self/status", "re")) {
    char line[256];
    unsigned mask = 0;
    bool found = false;
    while (!found && std::fgets(line, sizeof line, f)) found = std::sscanf(line, "Umask: %o", &mask) == 1;
    std::fclose(f);
    if (found) return static_cast<mode_t>(0666 & ~mask);
  }
  mode_t mask = ::umask(022);
  ::umask(mask);
  return static_cast<mode_t>(0666 & ~mask);
}

// Writes all of `n` bytes to fd; 0 or errno.
inline int write_all(int fd, const char* bytes, std::size_t n) {
  while (n > 0) {
    ssize_t w = ::write(fd, bytes, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return w < 0 ? errno : ENOSPC;
    bytes += w;
    n -= static_cast<std::size_t>(w);
  }
  return 0;
}

// A FIFO opens for writing only once a reader has it open: the reader may
// start after us, so wait for one a while, never for ever.
inline constexpr int fifo_reader_wait_ms = 10000;

inline int open_stream(const std::string& target) {
  for (int waited_ms = 0;; waited_ms += 10) {
    int fd = ::open(target.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd >= 0) {
      ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      return fd;
    }
    if (errno != ENXIO || waited_ms >= fifo_reader_wait_ms) return -1;
    const timespec pause{0, 10000000};
    ::nanosleep(&pause, nullptr);
  }
}

inline std::string stream_error(int e) {
  return e == ENXIO ? "no process opened the FIFO for reading" : std::strerror(e);
}

// Writes bytes through to a device or FIFO (never created, never
// truncated: it is there and stays); "" or why not.
inline std::string write_through(const std::string& target, const char* bytes, std::size_t n) {
  int fd = open_stream(target);
  if (fd < 0) return stream_error(errno);
  int e = write_all(fd, bytes, n);
  if (::close(fd) != 0 && e == 0) e = errno;
  return e ? std::strerror(e) : "";
}

inline std::string kind_refused(mode_t mode) {
  if (S_ISDIR(mode)) return "it is a folder";
  const char* kind = S_ISBLK(mode) ? "a block device" : S_ISSOCK(mode) ? "a socket" : "a special file";
  return std::string("it is ") + kind + " (only regular files, character devices and FIFOs are written)";
}

}  // namespace detail

//! The folder for temporaries that have no target folder: $TMPDIR or /tmp.
inline std::string temporary_folder() {
  const char* tmp = std::getenv("TMPDIR");
  return tmp && *tmp ? tmp : "/tmp";
}

//! Removes from `folder` the temporaries (see above) whose process is gone,
//! of this PID namespace; those of other namespaces may be alive.
inline void remove_dead_temporaries(const std::string& folder) {
  const std::string ns = detail::pid_namespace();
  if (ns == "0") return;
  DIR* d = ::opendir(folder.c_str());
  if (!d) return;
  while (dirent* e = ::readdir(d)) {
    long pid = detail::temporary_owner(e->d_name, ns);
    if (pid <= 0 || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    std::string path = detail::in_folder(folder, e->d_name);
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::unlink(path.c_str());
  }
  ::closedir(d);
}

//! A new, empty file of a unique temporary name in `folder`, open for
//! writing: ".STEM.vvtmp-PID-NS-XXXXXX.EXT", the stem (and if need be the
//! extension) shortened so the name fits the folder's NAME_MAX. Private
//! (mode 0600) until the caller says otherwise. fd is -1 on failure, and
//! error says why.
struct unique_file {
  std::string path;
  int fd = -1;
  std::string error;
};
inline unique_file create_temporary(const std::string& folder, const std::string& stem, std::string ext) {
  const std::string id =
      detail::temporary_marker + std::to_string(::getpid()) + "-" + detail::pid_namespace() + "-XXXXXX";
  std::size_t limit = detail::name_max(folder);
  std::size_t fixed = 1 + id.size();  // the leading dot and the id
  ext = detail::shortened(ext, limit > fixed ? limit - fixed : 0);
  std::size_t room = limit > fixed + ext.size() ? limit - fixed - ext.size() : 0;
  unique_file f;
  f.path = detail::in_folder(folder, "." + detail::shortened(stem, room) + id + ext);
  f.fd = ::mkostemps(f.path.data(), static_cast<int>(ext.size()), O_CLOEXEC);
  if (f.fd < 0) f.error = std::strerror(errno);
  return f;
}

//! Whether the two paths name one existing file (the same device and
//! inode, however spelt: "./a.vvp", a symbolic or a hard link).
inline bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

//! The first of `files` that `path` names (same_file), or "": a writer
//! refuses to write over its own input with it.
inline std::string file_among(const std::string& path, const std::vector<std::string>& files) {
  for (const std::string& f : files)
    if (same_file(path, f)) return f;
  return "";
}

//! One file to write: where `path` leads and how it is written (see above).
class output_file {
 public:
  explicit output_file(std::string path) : path_(std::move(path)) { plan(); }
  //! An uncommitted temporary is removed.
  ~output_file() { discard(); }
  output_file(const output_file&) = delete;
  output_file& operator=(const output_file&) = delete;

  const std::string& path() const { return path_; }
  //! The file written: the path with its symbolic links followed.
  const std::string& target() const { return target_; }
  //! Why the path cannot be written (nothing else applies then), or "".
  const std::string& problem() const { return problem_; }
  //! A character device or a FIFO: written through.
  bool is_stream() const { return how_ == how::stream; }

  //! Writes the whole file; "" or why not. The target is either the new
  //! file or untouched (a device or FIFO gets what was written until the
  //! error).
  std::string write(const std::string& bytes) {
    switch (how_) {
      case how::refused:
        return problem_;
      case how::stream:
        return detail::write_through(target_, bytes.data(), bytes.size());
      case how::in_place:
        return write_in_place(bytes);
      case how::replace:
        break;
    }
    if (std::string why = make_temporary(); !why.empty()) return why;
    int e = detail::write_all(fd_, bytes.data(), bytes.size());
    if (::close(fd_) != 0 && e == 0) e = errno;
    fd_ = -1;
    if (e != 0) {
      discard();
      return std::strerror(e);
    }
    return commit();
  }

  //! For writers that take a path: creates temporary(), where the writer
  //! writes the whole file (a vvlib writer writes it in place), then
  //! commit() puts it in place. For a device or a FIFO it is in $TMPDIR.
  //! It keeps the path's extension (writers choose the format by it).
  std::string make_temporary() {
    if (how_ == how::refused) return problem_;
    if (!temporary_.empty()) return "";
    std::string name = detail::name_part(how_ == how::in_place ? target_ : path_);
    std::string ext = detail::extension_part(name);
    std::string folder = folder_of_temporary();
    remove_dead_temporaries(folder);
    std::string stem = detail::name_part(target_);
    stem = stem.substr(0, stem.size() - detail::extension_part(stem).size());
    unique_file f = create_temporary(folder, stem, ext);
    if (f.fd < 0) return f.error;
    // mkostemps makes it private: give it the mode the file had, or the
    // one a new file gets.
    struct stat st {};
    mode_t mode = how_ == how::replace && ::stat(target_.c_str(), &st) == 0 ? st.st_mode & 07777
                                                                           : detail::new_file_mode();
    if (::fchmod(f.fd, mode) != 0) {
      std::string why = std::strerror(errno);
      ::close(f.fd);
      ::unlink(f.path.c_str());
      return why;
    }
    temporary_ = f.path;
    fd_ = f.fd;
    return "";
  }
  const std::string& temporary() const { return temporary_; }
  //! Where make_temporary makes it: a supervisor told so before it exists
  //! can remove it if this process dies in between.
  std::string folder_of_temporary() const {
    return how_ == how::stream ? temporary_folder() : detail::folder_part(target_);
  }

  //! Puts the temporary in place: a rename, or for a device or a FIFO a
  //! copy into it. "" or why not; the temporary is gone either way.
  std::string commit() {
    if (how_ == how::refused) return problem_;
    if (temporary_.empty()) return "no temporary was made";
    if (fd_ >= 0) ::close(fd_), fd_ = -1;
    std::string why;
    struct stat st {};
    // It may have become a device or a FIFO since: never rename over one.
    if (how_ != how::stream && ::lstat(target_.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)))
      how_ = how::stream;
    if (how_ == how::stream) {
      why = copy_through();
    } else if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
      why = std::strerror(errno);
    } else {
      temporary_.clear();
    }
    discard();
    return why;
  }

  //! A writer's message that names the temporary, about the path instead.
  std::string in_users_terms(std::string message) const {
    if (temporary_.empty()) return message;
    for (std::size_t at; (at = message.find(temporary_)) != std::string::npos;)
      message.replace(at, temporary_.size(), path_);
    return message;
  }

  //! Removes the regular file at the target (the one a link names; the
  //! link stays), never a device or a FIFO: after a failed run, so that an
  //! earlier run's output cannot pass for this one's.
  void remove_previous() const {
    struct stat st {};
    if (how_ == how::replace && ::stat(target_.c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::unlink(target_.c_str());
  }

 private:
  enum class how { replace, in_place, stream, refused };

  // Follows links to the file written and decides how it is written.
  void plan() {
    target_ = path_;
    std::set<std::string> seen;
    for (;;) {
      struct stat st {};
      if (::lstat(target_.c_str(), &st) != 0) {
        if (errno == ENOENT) break;  // a new file (its folder must exist)
        return refuse(std::strerror(errno));
      }
      if (S_ISLNK(st.st_mode)) {
        if (!seen.insert(target_).second) return refuse("the symbolic link is part of a loop of links");
        if (seen.size() > 40) return refuse("more than 40 symbolic links lead on from it");  // as the system counts
        std::string link(PATH_MAX + 1, '\0');
        ssize_t n = ::readlink(target_.c_str(), link.data(), link.size());
        if (n < 0 || static_cast<std::size_t>(n) >= link.size())
          return refuse(std::strerror(n < 0 ? errno : ENAMETOOLONG));
        link.resize(static_cast<std::size_t>(n));
        target_ = link[0] == '/' ? link : detail::in_folder(detail::folder_part(target_), link);
        continue;
      }
      if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
        how_ = how::stream;
      } else if (!S_ISREG(st.st_mode)) {
        return refuse(detail::kind_refused(st.st_mode));
      } else if (detail::temporary_owner(detail::name_part(target_), detail::pid_namespace()) == ::getpid()) {
        how_ = how::in_place;
      }
      return;
    }
  }
  void refuse(std::string why) {
    how_ = how::refused;
    problem_ = std::move(why);
  }

  std::string write_in_place(const std::string& bytes) {
    int fd = ::open(target_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) return std::strerror(errno);
    int e = detail::write_all(fd, bytes.data(), bytes.size());
    if (::close(fd) != 0 && e == 0) e = errno;
    return e ? std::strerror(e) : "";
  }

  std::string copy_through() {
    int from = ::open(temporary_.c_str(), O_RDONLY | O_CLOEXEC);
    if (from < 0) return std::strerror(errno);
    int to = detail::open_stream(target_);
    if (to < 0) {
      int e = errno;
      ::close(from);
      return detail::stream_error(e);
    }
    int e = 0;
    char buffer[1 << 16];
    for (ssize_t n; e == 0 && (n = ::read(from, buffer, sizeof buffer)) != 0;) {
      if (n < 0) {
        if (errno != EINTR) e = errno;
        continue;
      }
      e = detail::write_all(to, buffer, static_cast<std::size_t>(n));
    }
    ::close(from);
    if (::close(to) != 0 && e == 0) e = errno;
    return e ? std::strerror(e) : "";
  }

  void discard() {
    if (fd_ >= 0) ::close(fd_), fd_ = -1;
    if (!temporary_.empty()) ::unlink(temporary_.c_str());
    temporary_.clear();
  }

  std::string path_, target_, temporary_, problem_;
  how how_ = how::replace;
  int fd_ = -1;
};

//! Writes bytes to path safely (see above); vv::error "path: cannot write
//! file: why" otherwise, with the previous file untouched and no
//! temporary left.
inline void write_file_atomically(const std::string& path, const std::string& bytes) {
  output_file out(path);
  if (std::string why = out.write(bytes); !why.empty()) throw error(path, 0, "cannot write file: " + why);
}

//! Writes text to path safely (see write_file_atomically).
inline void write_text_file(const std::string& path, const std::string& text) { write_file_atomically(path, text); }

}  // namespace vv::io
