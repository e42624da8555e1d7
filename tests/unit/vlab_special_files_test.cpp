// The VLAB file objects (util::Function, Contour, Palette, Materials)
// refuse what is no regular file and what is over the size limit of VLAB
// data files, unread, naming the file and what it is; a FIFO is refused
// without blocking. (Linked with palette_materials_test.cpp, which stands
// in for the OpenGL calls of Palette and Materials.)
#include <util/contour.hpp>
#include <util/function.hpp>
#include <util/materials.hpp>
#include <util/palette.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "special_files.hpp"

namespace {

struct vlab_kind {
  const char* extension;
  std::function<void(const std::string&)> read;
};

std::vector<vlab_kind> kinds() {
  return {{".func", [](const std::string& p) { util::Function f(p); }},
          {".con", [](const std::string& p) { util::Contour c(p); }},
          {".map", [](const std::string& p) { util::Palette m(p); }},
          {".mat", [](const std::string& p) { util::Materials m(p); }}};
}

TEST(VlabFiles, RefuseAFifoWithoutBlocking) {
  for (const vlab_kind& k : kinds()) {
    const std::string path = special_files::fifo(std::string("pipe") + k.extension);
    EXPECT_EQ(special_files::error_reading_fifo(path, [&] { k.read(path); }),
              path + ": cannot open: it is a FIFO (named pipe), not a regular file");
  }
}

TEST(VlabFiles, RefuseALinkToDevZero) {
  for (const vlab_kind& k : kinds()) {
    const std::string path = special_files::link_to_dev_zero(std::string("zero") + k.extension);
    EXPECT_EQ(special_files::error_of([&] { k.read(path); }),
              path + ": cannot open: it is a symbolic link to /dev/zero, a character device, not a regular file");
  }
}

TEST(VlabFiles, RefuseAFolder) {
  for (const vlab_kind& k : kinds()) {
    const std::string path = special_files::folder(std::string("folder") + k.extension);
    EXPECT_EQ(special_files::error_of([&] { k.read(path); }), path + ": cannot open: it is a folder, not a file");
  }
}

TEST(VlabFiles, RefuseAFileOverTheLimitUnread) {
  EXPECT_EQ(vv::io::data_file_limit.bytes, std::uint64_t(64) << 20);
  for (const vlab_kind& k : kinds()) {
    const std::string path = special_files::sparse_file(std::string("huge") + k.extension, std::uint64_t(70) << 20);
    EXPECT_EQ(special_files::error_of([&] { k.read(path); }),
              path + ": cannot open: it is 70 MiB, over the 64 MiB limit of VLAB data files");
  }
}

}  // namespace
