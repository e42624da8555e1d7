#include "render/image.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

#include <stb/stb_image_write.h>

#include <vv/io/files.hpp>

namespace vvi {

std::string write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
  // Named as vvlib names its temporaries, so batch mode can remove it when
  // the run is killed.
  std::string tmp = vv::io::temporary_beside(path);
  if (!stbi_write_png(tmp.c_str(), width, height, 4, rgba.data(), width * 4)) {
    std::remove(tmp.c_str());
    return path + ": cannot write the PNG file";
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return path + ": cannot write the PNG file: " + why;
  }
  return "";
}

}  // namespace vvi
