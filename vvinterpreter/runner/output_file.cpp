#include "runner/output_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <set>

#include <vv/io/files.hpp>

#include "runner/fault_guard.hpp"

namespace vvi {

namespace {

constexpr const char* marker = ".vvtmp-";

std::string folder_part(const std::string& path) {
  std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string name_part(const std::string& path) {
  std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The extension as written ("" when none), as vv::io::extension_of finds it.
std::string extension_part(const std::string& name) {
  std::size_t dot = name.rfind('.');
  return dot == std::string::npos ? "" : name.substr(dot);
}

// The inode of this process's PID namespace, in hex ("0": unknown): a PID
// means a process only within its namespace.
std::string pid_namespace() {
  char link[64];
  ssize_t n = readlink("/proc/self/ns/pid", link, sizeof link - 1);
  if (n <= 0) return "0";
  link[n] = '\0';
  const char* digits = std::strchr(link, '[');
  unsigned long long inode = digits ? std::strtoull(digits + 1, nullptr, 10) : 0;
  char hex[24];
  std::snprintf(hex, sizeof hex, "%llx", inode);
  return hex;
}

std::string random_hex() {
  static std::random_device device;
  static std::mt19937_64 generator((static_cast<std::uint64_t>(device()) << 32) ^ device() ^
                                   static_cast<std::uint64_t>(time(nullptr)));
  char hex[16];
  std::snprintf(hex, sizeof hex, "%06llx", static_cast<unsigned long long>(generator() & 0xffffff));
  return hex;
}

// Cuts a name to at most `bytes`, not inside a UTF-8 character.
std::string shortened(const std::string& text, std::size_t bytes) {
  if (text.size() <= bytes) return text;
  std::size_t n = bytes;
  while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;
  return text.substr(0, n);
}

long name_max(const std::string& folder) {
  long n = pathconf(folder.c_str(), _PC_NAME_MAX);
  return n > 0 ? n : NAME_MAX;
}

// ".STEM.vvtmp-PID-NS-RANDOM.EXT" in `folder`, short enough that vvlib's
// own temporary beside it (vv::io::temporary_beside adds ".vvtmp.EXT")
// fits in the folder's limit too. The stem is the file's, the extension
// the one the user gave (it chooses the format, also through a link).
std::string temporary_name(const std::string& folder, const std::string& name, const std::string& ext) {
  std::string stem = name.substr(0, name.size() - extension_part(name).size());
  std::string id = marker + std::to_string(getpid()) + "-" + pid_namespace() + "-" + random_hex();
  long room = name_max(folder) - static_cast<long>(1 + id.size() + ext.size() + std::strlen(".vvtmp") + ext.size());
  stem = shortened(stem, room > 0 ? static_cast<std::size_t>(room) : 0);
  return (folder == "/" ? "" : folder) + "/." + stem + id + ext;
}

std::string temporary_folder() {
  const char* tmp = std::getenv("TMPDIR");
  return tmp && *tmp ? tmp : "/tmp";
}

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Writes all of `bytes` to fd; 0 or errno.
int write_all(int fd, const char* bytes, std::size_t n) {
  while (n > 0) {
    ssize_t w = write(fd, bytes, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return w < 0 ? errno : ENOSPC;
    bytes += w, n -= static_cast<std::size_t>(w);
  }
  return 0;
}

// A FIFO is opened for writing only once a reader has it open: wait for one
// a while (the reader may start after us), never for ever.
constexpr double fifo_reader_wait_seconds = 10;

int open_stream(const std::string& target) {
  for (int waited_ms = 0;; waited_ms += 10) {
    int fd = open(target.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd >= 0 || errno != ENXIO || waited_ms >= fifo_reader_wait_seconds * 1000) return fd;
    const timespec pause{0, 10000000};
    nanosleep(&pause, nullptr);
  }
}

}  // namespace

void remove_stale_temporaries(const std::string& folder) {
  static const std::string ours = pid_namespace();
  if (ours == "0") return;
  DIR* d = opendir(folder.c_str());
  if (!d) return;
  while (dirent* e = readdir(d)) {
    std::string name = e->d_name;
    std::size_t at = name.rfind(marker);
    if (name[0] != '.' || at == std::string::npos) continue;
    const char* p = name.c_str() + at + std::strlen(marker);
    char* after = nullptr;
    long pid = std::strtol(p, &after, 10);
    if (pid <= 0 || *after != '-' || name.compare(after + 1 - name.c_str(), ours.size() + 1, ours + "-") != 0)
      continue;
    if (kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // its writer may still run
    std::string path = (folder == "/" ? "" : folder) + "/" + name;
    struct stat st;
    if (lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) unlink(path.c_str());
  }
  closedir(d);
}

output_file::output_file(std::string path) : path_(std::move(path)) {
  // Through symbolic links to the file written; a dangling link's target is
  // created.
  std::string at = path_;
  std::set<std::string> seen;
  for (;;) {
    struct stat st;
    if (lstat(at.c_str(), &st) != 0) break;  // a new file (or an error the writer reports)
    if (S_ISLNK(st.st_mode)) {
      if (!seen.insert(at).second) {
        error_ = path_ + ": cannot write through the symbolic link: it is part of a loop of links";
        return;
      }
      if (seen.size() > 40) {  // as the system counts them (ELOOP)
        error_ = path_ + ": cannot write through the symbolic link: more than 40 links lead on from it";
        return;
      }
      char link[PATH_MAX];
      ssize_t n = readlink(at.c_str(), link, sizeof link - 1);
      if (n < 0) break;
      link[n] = '\0';
      at = link[0] == '/' ? std::string(link) : folder_part(at) + "/" + link;
      continue;
    }
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      stream_ = true;
    } else if (!S_ISREG(st.st_mode)) {
      error_ = path_ + ": cannot write it: it is " + kind_of(st.st_mode) +
               " (files are written to regular files, character devices and FIFOs)";
      return;
    }
    break;
  }
  target_ = at;
  // A device's or a FIFO's folder (/dev) is no place for a temporary.
  std::string folder = stream_ ? temporary_folder() : folder_part(target_);
  remove_stale_temporaries(folder);
  temporary_ = temporary_name(folder, name_part(target_), extension_part(name_part(path_)));
  fault_guard::note_writing(temporary_, path_);
}

output_file::~output_file() {
  if (temporary_.empty() || committed_) return;
  unlink(temporary_.c_str());
  unlink(vv::io::temporary_beside(temporary_).c_str());
  fault_guard::note_written(temporary_);
}

std::string output_file::in_users_terms(std::string message) const {
  if (temporary_.empty()) return message;
  for (std::size_t at; (at = message.find(temporary_)) != std::string::npos;)
    message.replace(at, temporary_.size(), path_);
  return message;
}

std::string output_file::commit() {
  if (!error_.empty()) return error_;
  struct stat st;
  // It may have become a device or a FIFO since: never rename over one.
  if (!stream_ && lstat(target_.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))) stream_ = true;
  if (!stream_) {
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0)
      return path_ + ": cannot write file: " + std::strerror(errno);
    committed_ = true;
    fault_guard::note_written(temporary_);
    return "";
  }
  int from = open(temporary_.c_str(), O_RDONLY | O_CLOEXEC);
  if (from < 0) return path_ + ": cannot write it: cannot read back " + temporary_ + ": " + std::strerror(errno);
  int to = open_stream(target_);
  if (to < 0) {
    int e = errno;
    close(from);
    if (e == ENXIO) return path_ + ": cannot write to the FIFO: no process opened it for reading";
    return path_ + ": cannot write file: " + std::strerror(e);
  }
  fcntl(to, F_SETFL, fcntl(to, F_GETFL) & ~O_NONBLOCK);
  int e = 0;
  char buffer[1 << 16];
  for (ssize_t n; e == 0 && (n = read(from, buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno != EINTR) e = errno;
      continue;
    }
    e = write_all(to, buffer, static_cast<std::size_t>(n));
  }
  close(from);
  if (close(to) != 0 && e == 0) e = errno;
  if (e != 0) return path_ + ": cannot write file: " + std::strerror(e);
  return "";  // the temporary goes with this object
}

std::string write_output(const std::string& path, const std::function<std::string(const std::string&)>& write) {
  output_file out(path);
  if (!out.error().empty()) return out.error();
  std::string e = write(out.temporary());
  if (!e.empty()) return out.in_users_terms(e);
  return out.commit();
}

}  // namespace vvi
