#include "output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace vvc {

namespace {

// The folder part of a path as written ("." for a bare name).
std::string folder_of(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string base_of(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// As the kernel does: a link more than 40 deep is a loop.
constexpr int max_link_hops = 40;

// Writes all of text to fd; 0 or errno.
int write_all(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return 0;
}

std::string write_through(const std::string& target, const std::string& text) {
  // No O_CREAT, no O_TRUNC: the device or pipe is there and stays.
  int fd = ::open(target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return std::strerror(errno);
  int e = write_all(fd, text);
  if (::close(fd) != 0 && e == 0) e = errno;
  return e ? std::strerror(e) : "";
}

std::string replace_atomically(const std::string& target, const std::string& text) {
  // A unique temporary beside the target (rename works within one file
  // system). The name is cut so that a long target name still leaves room
  // for the suffix within a file name's 255 bytes.
  constexpr std::size_t max_base = 200;
  std::string name = folder_of(target) + "/" + base_of(target).substr(0, max_base) + ".vvtmp-XXXXXX";
  int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) return std::strerror(errno);
  // mkostemp makes the file private (0600); give it the mode the file had,
  // or the one a new file gets.
  struct stat st {};
  mode_t mode;
  if (::stat(target.c_str(), &st) == 0) {
    mode = st.st_mode & 07777;
  } else {
    mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  int e = ::fchmod(fd, mode) != 0 ? errno : 0;
  if (e == 0) e = write_all(fd, text);
  if (::close(fd) != 0 && e == 0) e = errno;
  if (e == 0 && std::rename(name.c_str(), target.c_str()) != 0) e = errno;
  if (e != 0) {
    ::unlink(name.c_str());
    return std::strerror(e);
  }
  return "";
}

}  // namespace

output_file plan_output(const std::string& path) {
  output_file out;
  out.target = path;
  for (int hops = 0;; ++hops) {
    struct stat st {};
    if (::lstat(out.target.c_str(), &st) != 0) {
      if (errno != ENOENT) {
        out.why = std::strerror(errno);
        return out;
      }
      out.kind = output_file::replace;  // a new file (its folder must exist)
      return out;
    }
    if (S_ISLNK(st.st_mode)) {
      if (hops == max_link_hops) {
        out.why = std::strerror(ELOOP);
        return out;
      }
      std::string link(PATH_MAX + 1, '\0');
      ssize_t n = ::readlink(out.target.c_str(), link.data(), link.size());
      if (n < 0 || static_cast<std::size_t>(n) >= link.size()) {
        out.why = std::strerror(n < 0 ? errno : ENAMETOOLONG);
        return out;
      }
      link.resize(static_cast<std::size_t>(n));
      out.target = link[0] == '/' ? link : folder_of(out.target) + "/" + link;
      continue;
    }
    if (S_ISREG(st.st_mode)) {
      out.kind = output_file::replace;
    } else if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      out.kind = output_file::stream;
    } else {
      out.why = S_ISDIR(st.st_mode)   ? "it is a folder"
                : S_ISBLK(st.st_mode) ? "it is a block device (vvc writes only files, character devices and pipes)"
                                      : "it is a socket (vvc writes only files, character devices and pipes)";
    }
    return out;
  }
}

std::string write_output(const output_file& out, const std::string& text) {
  switch (out.kind) {
    case output_file::replace:
      return replace_atomically(out.target, text);
    case output_file::stream:
      return write_through(out.target, text);
    case output_file::refused:
      break;
  }
  return out.why;
}

void remove_stale_output(const output_file& out) {
  struct stat st {};
  if (out.kind == output_file::replace && ::stat(out.target.c_str(), &st) == 0 && S_ISREG(st.st_mode))
    ::unlink(out.target.c_str());
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

std::string source_at(const std::string& path, const std::vector<std::string>& sources) {
  for (const std::string& s : sources)
    if (same_file(path, s)) return s;
  return "";
}

}  // namespace vvc
