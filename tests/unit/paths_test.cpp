// The one file reader and "folder of a path" that vvlib, the translator and
// the host share (vv/io/files.hpp): what each returns, against paths and
// bytes written here.
#include <vv/io/files.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

TEST(FolderOf, IsThePathAsWrittenWithoutItsFile) {
  EXPECT_EQ(vv::io::folder_of("models/leaf/m.vvp"), "models/leaf");
  EXPECT_EQ(vv::io::folder_of("m.vvp"), "");
  EXPECT_EQ(vv::io::folder_of("/m.vvp"), "/");
  EXPECT_EQ(vv::io::folder_of("/work/m.vvp"), "/work");
}

// An #include in a .vvp names a file beside the including one.
TEST(FolderOf, ResolvesBackToTheNeighbouringFile) {
  EXPECT_EQ(vv::io::resolve(vv::io::folder_of("models/leaf/m.vvp"), "inc.vvp"), "models/leaf/inc.vvp");
  EXPECT_EQ(vv::io::resolve(vv::io::folder_of("m.vvp"), "inc.vvp"), "inc.vvp");
  EXPECT_EQ(vv::io::resolve(vv::io::folder_of("/m.vvp"), "inc.vvp"), "/inc.vvp");
  EXPECT_EQ(vv::io::resolve(vv::io::folder_of("a/m.vvp"), "/abs/inc.vvp"), "/abs/inc.vvp");
}

TEST(AbsoluteFolderOf, StartsFromTheWorkingFolder) {
  EXPECT_EQ(vv::io::absolute_folder_of("m.vvp"), fs::current_path().string());
  EXPECT_EQ(vv::io::absolute_folder_of("sub/m.vvp"), (fs::current_path() / "sub").string());
  EXPECT_EQ(vv::io::absolute_folder_of("/work/leaf/m.vvp"), "/work/leaf");
}

TEST(ReadFile, GivesEveryByteBack) {
  const std::string path = test_files::scratch_dir() + "bytes.bin";
  const std::string bytes("line\r\n\0tail\xEF\xBB\xBF", 14);
  std::ofstream(path, std::ios::binary) << bytes;
  std::optional<std::string> read = vv::io::read_file(path);
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->size(), 14u);
  EXPECT_EQ(*read, bytes);
}

TEST(ReadFile, AnEmptyFileIsEmptyText) {
  const std::string path = test_files::scratch_dir() + "empty.txt";
  std::ofstream(path, std::ios::binary).close();
  std::optional<std::string> read = vv::io::read_file(path);
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(*read, "");
}

TEST(ReadFile, AMissingFileSaysWhy) {
  std::string why;
  EXPECT_FALSE(vv::io::read_file(test_files::scratch_dir() + "no_such_file.txt", &why).has_value());
  EXPECT_EQ(why, "No such file or directory");
}

}  // namespace
