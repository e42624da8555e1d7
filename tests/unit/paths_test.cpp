// The one file reader and "folder of a path" that vvlib, the translator and
// the host share (vv/io/files.hpp): what each returns, against paths and
// bytes written here; what the reader refuses (no regular file, over the
// size limit), and that it refuses a FIFO without blocking.
#include <vv/io/files.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "special_files.hpp"
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

// What no reader may read: each refused with what it is, and a FIFO
// without waiting for a writer.
TEST(ReadFile, RefusesAFifoWithoutBlocking) {
  const std::string path = special_files::fifo("pipe");
  std::string why = "(read)";
  std::string message = special_files::error_reading_fifo(path, [&] {
    if (vv::io::read_file(path, &why)) throw std::runtime_error("read the FIFO: " + why);
    throw std::runtime_error(why);
  });
  EXPECT_EQ(message, "it is a FIFO (named pipe), not a regular file");
}

TEST(ReadFile, RefusesALinkToDevZeroNamingWhereItLeads) {
  const std::string path = special_files::link_to_dev_zero("zero");
  std::string why;
  EXPECT_FALSE(vv::io::read_file(path, &why).has_value());
  EXPECT_EQ(why, "it is a symbolic link to /dev/zero, a character device, not a regular file");
  EXPECT_FALSE(vv::io::read_file("/dev/zero", &why).has_value());
  EXPECT_EQ(why, "it is a character device, not a regular file");
}

TEST(ReadFile, RefusesAFolder) {
  std::string why;
  EXPECT_FALSE(vv::io::read_file(special_files::folder("a_folder"), &why).has_value());
  EXPECT_EQ(why, "it is a folder, not a file");
}

TEST(ReadFile, TakesAFileUpToTheLimitAndRefusesOneByteMore) {
  const vv::io::size_limit ten{10, "test files"};
  const std::string path = test_files::write_scratch("ten.txt", "0123456789");
  std::string why;
  std::optional<std::string> read = vv::io::read_file(path, &why, ten);
  ASSERT_TRUE(read.has_value()) << why;
  EXPECT_EQ(*read, "0123456789");
  test_files::write_scratch("eleven.txt", "0123456789!");
  EXPECT_FALSE(vv::io::read_file(test_files::scratch_dir() + "eleven.txt", &why, ten).has_value());
  EXPECT_EQ(why, "it is 11 bytes, over the 10 bytes limit of test files");
}

TEST(ReadFile, AFileOverTheDefaultLimitIsRefusedUnread) {
  const std::string path = special_files::sparse_file("huge.bin", std::uint64_t(5583457484));
  std::string why;
  EXPECT_FALSE(vv::io::read_file(path, &why).has_value());
  EXPECT_EQ(why, "it is 5.2 GiB, over the 1 GiB limit of files read whole");
}

// A regular file whose size the system does not give (st_size 0) is read
// to its end all the same.
TEST(ReadFile, ReadsAFileThatReportsNoSize) {
  std::string why;
  std::optional<std::string> read = vv::io::read_file("/proc/self/status", &why);
  ASSERT_TRUE(read.has_value()) << why;
  EXPECT_EQ(read->rfind("Name:", 0), 0u);
  EXPECT_NE(read->find("\nPid:"), std::string::npos);
}

TEST(UnreadableFile, SaysWhyWithoutOpening) {
  EXPECT_FALSE(vv::io::unreadable_file(test_files::write_scratch("fine.txt", "fine")).has_value());
  EXPECT_EQ(vv::io::unreadable_file(special_files::fifo("pipe2")), "it is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(vv::io::unreadable_file(test_files::scratch_dir() + "absent"), "No such file or directory");
}

TEST(SizeText, ReadsAsPeopleWriteSizes) {
  EXPECT_EQ(vv::io::size_text(1), "1 byte");
  EXPECT_EQ(vv::io::size_text(1023), "1023 bytes");
  EXPECT_EQ(vv::io::size_text(1024), "1 KiB");
  EXPECT_EQ(vv::io::size_text(std::uint64_t(64) << 20), "64 MiB");
  EXPECT_EQ(vv::io::size_text(std::uint64_t(1) << 30), "1 GiB");
  EXPECT_EQ(vv::io::size_text(std::uint64_t(5583457484)), "5.2 GiB");
  // Just over a limit: the bytes show that it is over.
  EXPECT_EQ(vv::io::size_over_text((std::uint64_t(1) << 30) + 1, std::uint64_t(1) << 30),
            "1 GiB (1073741825 bytes)");
  EXPECT_EQ(vv::io::size_over_text(std::uint64_t(5583457484), std::uint64_t(1) << 30), "5.2 GiB");
}

}  // namespace
