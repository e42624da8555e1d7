#include "compile/model_cache.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <random>
#include <sstream>

#include "app/files.hpp"
#include "compile/hashing.hpp"

namespace vvi::cache {

namespace fs = std::filesystem;

std::string unique_id() {
  std::random_device random;  // the kernel's generator
  unsigned long long a = (static_cast<unsigned long long>(random()) << 32) | random();
  unsigned long long b = (static_cast<unsigned long long>(random()) << 32) | random();
  char out[33];
  std::snprintf(out, sizeof out, "%016llx%016llx", a, b);
  return out;
}

namespace {

const char* const manifest_name = "manifest";

// The checksum of a file's bytes, read in one piece (this runs on every
// start of a cached model: no stream copies).
std::string content_of(const std::string& path, bool& readable) {
  readable = false;
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "";
  struct stat st {};
  std::unique_ptr<char[]> bytes;  // not a string: zero-filling a megabyte first would double the cost
  std::size_t size = 0;
  if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
    size = static_cast<std::size_t>(st.st_size);
    bytes.reset(new char[size]);
    std::size_t got = 0;
    while (got < size) {
      ssize_t n = ::read(fd, bytes.get() + got, size - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    readable = got == size;
  }
  ::close(fd);
  return readable ? checksum(std::string_view(bytes.get(), size)) : "";
}

}  // namespace

bool write_manifest(const std::string& dir, const std::vector<listed_file>& files) {
  std::string text;
  for (const listed_file& f : files) {
    std::error_code ec;
    std::uintmax_t size = fs::file_size(dir + "/" + f.name, ec);
    if (ec) return false;
    bool readable = true;
    std::string hash = f.how == check::content ? content_of(dir + "/" + f.name, readable) : "-";
    if (!readable) return false;
    text += std::to_string(size) + " " + hash + " " + f.name + "\n";
  }
  return write_file(dir + "/" + manifest_name, text);
}

verdict verify(const std::string& dir, std::string& why) {
  std::optional<std::string> manifest = read_file(dir + "/" + manifest_name);
  if (!manifest) return verdict::unlisted;
  std::istringstream lines(*manifest);
  std::uintmax_t size = 0;
  std::string hash, name;
  bool any = false;
  while (lines >> size >> hash >> name) {
    any = true;
    std::error_code ec;
    std::uintmax_t found = fs::file_size(dir + "/" + name, ec);
    if (ec) {
      why = name + " is missing";
      return verdict::damaged;
    }
    if (found != size) {
      why = name + " has " + std::to_string(found) + " bytes, " + std::to_string(size) + " expected";
      return verdict::damaged;
    }
    bool readable = true;
    if (hash != "-" && content_of(dir + "/" + name, readable) != hash) {
      why = name + (readable ? " differs from what was built" : " cannot be read");
      return verdict::damaged;
    }
  }
  if (!any || !lines.eof()) {
    why = "its manifest is damaged";
    return verdict::damaged;
  }
  return verdict::good;
}

void publish(const std::string& folder, const std::string& key, const std::string& build) {
  std::error_code ec;
  std::string link = folder + "/" + key;
  std::string tmp_link = folder + "/link-" + unique_id();
  fs::create_directory_symlink(build, tmp_link, ec);
  if (fs::is_directory(fs::symlink_status(link, ec))) fs::remove_all(link, ec);  // an older cache's layout
  fs::rename(tmp_link, link, ec);
  if (ec) fs::remove(tmp_link, ec);
}

namespace {

bool is_link(const fs::path& p) {
  std::error_code ec;
  return fs::is_symlink(fs::symlink_status(p, ec));
}

// Whether an entry of a cache folder is something no reader can want:
// a work folder or a link being made (their makers died, once they are
// old), a build its key no longer names, or a folder of the layout before
// manifests (KEY itself a folder).
bool unwanted(const fs::path& folder, const std::string& name) {
  if (name.rfind("tmp-", 0) == 0 || name.rfind("link-", 0) == 0) return true;
  // A build's lock file, once old: removing one a build still holds costs
  // at most one compile made twice, never a wrong build.
  if (name.rfind("lock-", 0) == 0) return true;
  std::size_t dot = name.find('.');
  if (dot == std::string::npos) return !is_link(folder / name);
  std::error_code ec;
  fs::path named = fs::read_symlink(folder / name.substr(0, dot), ec);
  return ec || named.filename() != name;
}

}  // namespace

void remove_leftovers(const std::string& folder, std::chrono::seconds age) {
  std::time_t now = std::time(nullptr);
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    std::string name = it->path().filename().string();
    struct stat st {};
    if (!unwanted(folder, name) || lstat(it->path().c_str(), &st) != 0 || now - st.st_mtime < age.count()) continue;
    std::error_code rm;
    fs::remove_all(it->path(), rm);
  }
}

std::string new_work_folder(const std::string& folder, const std::string& key) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  remove_leftovers(folder);
  std::string work = folder + "/tmp-" + key + "-" + unique_id();
  fs::create_directories(work, ec);
  return ec ? "" : work;
}

bool store(const std::string& folder, const std::string& work, const std::string& key,
           const std::vector<listed_file>& files) {
  if (!write_manifest(work, files)) return false;
  std::string build = key + "." + unique_id();
  std::error_code ec;
  fs::rename(work, folder + "/" + build, ec);
  if (ec) return false;
  publish(folder, key, build);
  return true;
}

build_lock::build_lock(const std::string& folder, const std::string& key) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  fd_ = ::open((folder + "/lock-" + key).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) return;
  while (::flock(fd_, LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    ::close(fd_);  // a file system without locks: unlocked, as before
    fd_ = -1;
    return;
  }
}

build_lock::~build_lock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace vvi::cache
