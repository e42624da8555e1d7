// Whole-file reading, atomic writing and path resolution: the one copy
// that vvlib's readers and writers, the translator (vvc) and the host
// (vvinterpreter) share. Needs nothing but the standard library.
#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "../error.hpp"

namespace vv::io {

//! A file's text with a map from byte offsets to line numbers.
class text_file {
 public:
  text_file(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text_.size(); ++i)
      if (text_[i] == '\n') line_starts_.push_back(i + 1);
  }
  const std::string& name() const noexcept { return name_; }
  const std::string& text() const noexcept { return text_; }
  //! 1-based line of a byte offset (offsets past the end give the last line).
  int line_at(std::ptrdiff_t offset) const noexcept {
    if (offset < 0) return 0;
    auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(),
                               static_cast<std::size_t>(offset));
    return static_cast<int>(it - line_starts_.begin());
  }
  [[noreturn]] void fail(std::ptrdiff_t offset, const std::string& problem) const {
    throw error(name_, line_at(offset), problem);
  }

 private:
  std::string name_, text_;
  std::vector<std::size_t> line_starts_;
};

//! A size limit on the files a reader takes whole: each kind of file vv
//! reads has one, so that a wrong path (a huge file, a link to /dev/zero)
//! fails at once with a message instead of filling the memory. The limits
//! are listed in docs/library.md.
struct size_limit {
  std::uint64_t bytes;
  const char* files;  //!< what the limit is for, in messages ("mesh files")
};
//! .vvm, .obj, .off, .ply and .stl files: 1 GiB (a .vvm file of ten million
//! vertices is about 600 MB).
inline constexpr size_limit mesh_file_limit{std::uint64_t(1) << 30, "mesh files"};
//! The VLAB data files (functions, contours, palettes, materials): 64 MiB.
inline constexpr size_limit data_file_limit{std::uint64_t(64) << 20, "VLAB data files"};
//! Program text: .vvp files and the headers they include (vvc): 64 MiB.
inline constexpr size_limit program_file_limit{std::uint64_t(64) << 20, "program files"};
//! Anything else read whole (read_file's default): 1 GiB.
inline constexpr size_limit any_file_limit{std::uint64_t(1) << 30, "files read whole"};

namespace detail {

// bytes in the largest binary unit it reaches, rounded to one decimal:
// the value, the unit's name and its size in bytes.
struct shown_size {
  double value;
  const char* unit;
  double unit_bytes;
};
inline shown_size show_size(std::uint64_t bytes) {
  static const char* const units[] = {"KiB", "MiB", "GiB", "TiB"};
  double unit_bytes = 1024;
  int unit = 0;
  while (unit < 3 && static_cast<double>(bytes) >= unit_bytes * 1024) unit_bytes *= 1024, ++unit;
  return {std::round(static_cast<double>(bytes) / unit_bytes * 10) / 10, units[unit], unit_bytes};
}

}  // namespace detail

//! A size as people read it: "312 bytes", "64 MiB", "5.2 GiB".
inline std::string size_text(std::uint64_t bytes) {
  if (bytes < 1024) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  detail::shown_size s = detail::show_size(bytes);
  char text[48];
  bool whole = s.value == std::floor(s.value);
  std::snprintf(text, sizeof text, whole ? "%.0f %s" : "%.1f %s", s.value, s.unit);
  return text;
}

//! A size over a limit, so that it reads as over it: "5.2 GiB", but
//! "1.0 GiB (1073741825 bytes)" where the rounding hides the difference.
inline std::string size_over_text(std::uint64_t bytes, std::uint64_t limit) {
  std::string text = size_text(bytes);
  if (bytes >= 1024) {
    detail::shown_size s = detail::show_size(bytes);
    if (s.value * s.unit_bytes <= static_cast<double>(limit)) text += " (" + std::to_string(bytes) + " bytes)";
  }
  return text;
}

namespace detail {

// What a file that is not regular is, for messages.
inline std::string kind_of_file(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

// Why a file of this status is no file to read: "" when it is a regular
// file within the limit.
inline std::string unreadable_because(const std::string& path, const struct stat& st, const size_limit& limit) {
  if (S_ISREG(st.st_mode)) {
    if (static_cast<std::uint64_t>(st.st_size) <= limit.bytes) return "";
    return "it is " + size_over_text(static_cast<std::uint64_t>(st.st_size), limit.bytes) + ", over the " +
           size_text(limit.bytes) + " limit of " + limit.files;
  }
  if (S_ISDIR(st.st_mode)) return "it is a folder, not a file";
  // Through a link, name where it leads: "a link to /dev/zero" explains a
  // character device that nobody meant to read.
  struct stat link {};
  std::string through;
  if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
    std::error_code ec;
    std::filesystem::path target = std::filesystem::canonical(path, ec);
    if (!ec) through = "a symbolic link to " + target.string() + ", ";
  }
  return "it is " + through + kind_of_file(st.st_mode) + ", not a regular file";
}

}  // namespace detail

//! Why path is no file to read whole, or std::nullopt when it is a regular
//! file (after following links) within the limit. Never opens the file, so
//! a FIFO does not block. For checks ahead of a reader that is not ours
//! (vvc checks the headers a program includes before g++ reads them).
inline std::optional<std::string> unreadable_file(const std::string& path,
                                                  const size_limit& limit = any_file_limit) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::string(std::strerror(errno));
  std::string why = detail::unreadable_because(path, st, limit);
  if (why.empty()) return std::nullopt;
  return why;
}

//! A whole file's bytes, or std::nullopt with the reason in *why: the
//! system's ("No such file or directory"), or that it is no regular file
//! ("it is a FIFO (named pipe), not a regular file"; folders, devices,
//! sockets and links to them likewise) or is over the limit ("it is 5.2
//! GiB, over the 1 GiB limit of mesh files"). A FIFO is refused without
//! blocking, and no more than limit.bytes are ever read, even from a file
//! that grows or a regular file whose size the system does not know.
inline std::optional<std::string> read_file(const std::string& path, std::string* why = nullptr,
                                            const size_limit& limit = any_file_limit) {
  auto refuse = [&](std::string reason) -> std::optional<std::string> {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  // Looked at before opening: opening a FIFO for reading waits for a writer.
  if (std::optional<std::string> problem = unreadable_file(path, limit)) return refuse(*problem);
  // Non-blocking all the same, in case the path was replaced since; fstat
  // then says what was opened.
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return refuse(std::strerror(errno));
  struct stat st {};
  std::string problem = ::fstat(fd, &st) != 0 ? std::string(std::strerror(errno))
                                               : detail::unreadable_because(path, st, limit);
  if (!problem.empty()) {
    ::close(fd);
    return refuse(problem);
  }
  std::string bytes;
  // One byte more than the size, to see the end at once; files that report
  // no size (under /proc) grow the buffer as they are read.
  bytes.resize(static_cast<std::size_t>(st.st_size) + 1);
  std::size_t have = 0;
  while (true) {
    if (have == bytes.size()) {
      if (have > limit.bytes) {
        ::close(fd);
        return refuse("it is over the " + size_text(limit.bytes) + " limit of " + limit.files +
                      " (it grew while being read)");
      }
      bytes.resize(std::min<std::uint64_t>(std::max<std::size_t>(2 * have, 4096), limit.bytes + 1));
    }
    ssize_t n = ::read(fd, &bytes[have], bytes.size() - have);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      int e = errno;
      ::close(fd);
      return refuse(std::strerror(e));
    }
    if (n == 0) break;
    have += static_cast<std::size_t>(n);
  }
  ::close(fd);
  if (have > limit.bytes)
    return refuse("it is over the " + size_text(limit.bytes) + " limit of " + limit.files +
                  " (it grew while being read)");
  bytes.resize(have);
  return bytes;
}

//! A file's text for a reader that reports by line (see read_file for
//! what is refused); vv::error "path: cannot open file: why" otherwise.
inline text_file read_text_file(const std::string& path, const size_limit& limit = any_file_limit) {
  std::string why;
  std::optional<std::string> text = read_file(path, &why, limit);
  if (!text) throw error(path, 0, "cannot open file: " + why);
  return text_file(path, std::move(*text));
}

//! The folder of a path as written: "a/b" for "a/b/m.vvp", "/" for
//! "/m.vvp", "" for "m.vvp" (resolve() below puts them back together).
inline std::string folder_of(const std::string& path) { return std::filesystem::path(path).parent_path().string(); }

//! The folder of a path, absolute (relative to the working folder when that
//! cannot be found; "." for a bare name then).
inline std::string absolute_folder_of(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  std::string folder = folder_of(ec ? path : p.string());
  return folder.empty() ? "." : folder;
}

//! The extension of a path, lower-cased, with its dot (".obj"), or "".
inline std::string extension_of(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

//! Where writing path really goes: for a symbolic link, the file it names
//! (the link stays a link); otherwise path itself.
inline std::string write_target(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_symlink(path, ec)) return path;
  std::filesystem::path target = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : target.string();
}

//! A temporary name beside path, with the same extension (writers that
//! choose the format by extension still work on it).
inline std::string temporary_beside(const std::string& path) {
  return path + ".vvtmp" + extension_of(path);
}

//! The temporary that writing path uses (beside a link's target).
inline std::string temporary_for(const std::string& path) { return temporary_beside(write_target(path)); }

//! Writes bytes to path atomically: into a temporary beside the file,
//! checking every write and the close (a full disk shows there), then a
//! rename over it. On failure the previous file is untouched, no temporary
//! is left, and the error says why ("No space left on device").
inline void write_file_atomically(const std::string& path, const std::string& bytes) {
  const std::string target = write_target(path);
  const std::string tmp = temporary_beside(target);
  auto fail = [&](int e, bool remove) {
    if (remove) std::remove(tmp.c_str());
    throw error(path, 0, std::string("cannot write file: ") + std::strerror(e));
  };
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(errno, false);
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      int e = n < 0 ? errno : ENOSPC;
      ::close(fd);
      fail(e, true);
    }
    p += n, left -= static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail(errno, true);
  if (std::rename(tmp.c_str(), target.c_str()) != 0) fail(errno, true);
}

//! Writes text to path atomically (see write_file_atomically).
inline void write_text_file(const std::string& path, const std::string& text) { write_file_atomically(path, text); }

//! A program's relative path, resolved against its model folder.
inline std::string resolve(const std::string& base_dir, const std::string& path) {
  if (base_dir.empty() || path.empty() || path[0] == '/') return path;
  return base_dir.back() == '/' ? base_dir + path : base_dir + "/" + path;
}

}  // namespace vv::io
