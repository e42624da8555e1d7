#include "render/image.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

#include <stb/stb_image_write.h>

#include <vv/io/files.hpp>

namespace vvi {

std::string write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
  // Encoded in memory, then written as vvlib writes every file: checked,
  // atomic, through a symbolic link to its target.
  std::string png;
  auto append = [](void* to, void* data, int size) {
    static_cast<std::string*>(to)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4))
    return path + ": cannot encode the PNG image";
  try {
    vv::io::write_file_atomically(path, png);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace vvi
