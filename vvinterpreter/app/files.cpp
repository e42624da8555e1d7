#include "app/files.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

namespace vvi {

namespace fs = std::filesystem;

bool write_file(const std::string& path, const std::string& text) {
  try {
    vv::io::write_text_file(path, text);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

std::string executable_dir() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : self.parent_path().string();
}

std::string default_cache_dir() {
  if (const char* d = std::getenv("VV_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/vv";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/vv";
  return "/tmp/vv-cache";
}

std::string absolute_path(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

}  // namespace vvi
