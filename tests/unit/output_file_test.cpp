// vv/io/output_file.hpp, the one way vv writes a file for the user (vvlib's
// writers, vvc -o, the interpreter's exports and plugin copies): a unique
// temporary renamed into place, special files written through or refused,
// links followed, long names, the input never overwritten, and what a
// killed writer leaves recognised and cleaned up.
#include <vv/io/output_file.hpp>

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;
using test_files::scratch_dir;
using test_files::slurp;

std::string fresh_dir(const std::string& name) {
  std::string d = scratch_dir() + "output_file_" + name + "/";
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

void put(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string error_writing(const std::string& path, const std::string& bytes) {
  try {
    vv::io::write_file_atomically(path, bytes);
  } catch (const vv::error& e) {
    return e.what();
  }
  return "";
}

// The id in this process's temporaries: ".vvtmp-PID-NS-".
std::string own_id(pid_t pid = getpid()) {
  return ".vvtmp-" + std::to_string(pid) + "-" + vv::io::detail::pid_namespace() + "-";
}

// ---- a unique temporary, written then renamed ----

TEST(OutputFile, TheTemporaryIsNamedForThisProcessItsNamespaceAndNoOtherWriter) {
  std::string d = fresh_dir("unique");
  vv::io::unique_file a = vv::io::create_temporary(d.substr(0, d.size() - 1), "mesh", ".obj");
  vv::io::unique_file b = vv::io::create_temporary(d.substr(0, d.size() - 1), "mesh", ".obj");
  ASSERT_GE(a.fd, 0) << a.error;
  ASSERT_GE(b.fd, 0) << b.error;
  close(a.fd), close(b.fd);
  EXPECT_NE(a.path, b.path);
  for (const std::string& p : {a.path, b.path}) {
    std::string name = fs::path(p).filename().string();
    EXPECT_EQ(name.rfind(".mesh" + own_id(), 0), 0u) << name;
    EXPECT_EQ(name.size(), (".mesh" + own_id() + "XXXXXX.obj").size()) << name;
    EXPECT_EQ(name.substr(name.size() - 4), ".obj");
  }
}

// Every writer once used "NAME.vvtmp.EXT": two writers of one path wrote
// into one temporary and renamed each other's half-written bytes. Eight
// threads writing one path many times each: every write succeeds, the file
// is one of them whole, and no temporary is left.
TEST(OutputFile, WritersOfOnePathAtOnceNeverShareATemporary) {
  std::string d = fresh_dir("threads");
  std::string path = d + "shared.txt";
  std::vector<std::string> texts;
  for (char c = 'a'; c < 'a' + 8; ++c) texts.push_back(std::string(100000, c));
  std::vector<std::string> errors(texts.size());
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < texts.size(); ++i)
    threads.emplace_back([&, i] {
      for (int n = 0; n < 20 && errors[i].empty(); ++n) errors[i] = error_writing(path, texts[i]);
    });
  for (std::thread& t : threads) t.join();
  for (const std::string& e : errors) EXPECT_EQ(e, "");
  std::string got = slurp(path);
  EXPECT_NE(std::find(texts.begin(), texts.end(), got), texts.end()) << "the file is no one write whole";
  EXPECT_EQ(names_in(d), std::vector<std::string>{"shared.txt"});
}

// The fixed name an older writer used, and another writer's temporary, are
// someone else's: left alone.
TEST(OutputFile, OtherWritersTemporariesAreLeftAlone) {
  std::string d = fresh_dir("others");
  put(d + "out.obj.vvtmp.obj", "an older writer's");
  std::string other = ".out" + own_id() + "AbCdEf.obj";  // this process's, being written by another thread
  put(d + other, "another thread's");
  vv::io::write_file_atomically(d + "out.obj", "new\n");
  EXPECT_EQ(slurp(d + "out.obj"), "new\n");
  EXPECT_EQ(slurp(d + "out.obj.vvtmp.obj"), "an older writer's");
  EXPECT_EQ(slurp(d + other), "another thread's");
}

// Renamed, not rewritten: a hard link to the previous file keeps the
// previous bytes (a reader that has the old file open never sees a
// half-written one).
TEST(OutputFile, TheNewFileIsRenamedIntoPlace) {
  std::string d = fresh_dir("renamed");
  put(d + "out.txt", "previous");
  fs::create_hard_link(d + "out.txt", d + "old.txt");
  vv::io::write_file_atomically(d + "out.txt", "next");
  EXPECT_EQ(slurp(d + "out.txt"), "next");
  EXPECT_EQ(slurp(d + "old.txt"), "previous");
}

// A new file gets the mode any new file gets (not the temporary's 0600);
// a file that exists keeps its own.
TEST(OutputFile, ModesAreThoseOfANewFileOrThePreviousOne) {
  std::string d = fresh_dir("modes");
  mode_t mask = umask(027);
  vv::io::write_file_atomically(d + "new.txt", "x");
  put(d + "kept.txt", "x");
  chmod((d + "kept.txt").c_str(), 0604);
  vv::io::write_file_atomically(d + "kept.txt", "y");
  umask(mask);
  EXPECT_EQ(fs::status(d + "new.txt").permissions(), static_cast<fs::perms>(0640));
  EXPECT_EQ(fs::status(d + "kept.txt").permissions(), static_cast<fs::perms>(0604));
}

// ---- special files: written through or refused, never renamed over ----

TEST(OutputFile, AFifoIsWrittenThroughAndStays) {
  std::string d = fresh_dir("fifo");
  std::string pipe = d + "pipe.obj";
  ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
  std::string got;
  std::thread reader([&] { got = slurp(pipe); });
  std::string e = error_writing(pipe, "through the pipe\n");
  reader.join();
  EXPECT_EQ(e, "");
  EXPECT_EQ(got, "through the pipe\n");
  EXPECT_TRUE(fs::is_fifo(pipe));
  EXPECT_EQ(names_in(d), std::vector<std::string>{"pipe.obj"});
}

// For writers that take a path: the temporary (in $TMPDIR: a FIFO's folder
// is no place for it) is copied into the FIFO.
TEST(OutputFile, AFifosTemporaryIsCopiedThrough) {
  std::string d = fresh_dir("fifo_two_stage");
  std::string pipe = d + "pipe.csv";
  ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
  std::string got;
  std::thread reader([&] { got = slurp(pipe); });
  std::string temporary;
  {
    vv::io::output_file out(pipe);
    ASSERT_TRUE(out.is_stream());
    ASSERT_EQ(out.make_temporary(), "");
    temporary = out.temporary();
    EXPECT_TRUE(fs::equivalent(fs::path(temporary).parent_path(), vv::io::temporary_folder()));
    EXPECT_EQ(fs::path(temporary).extension().string(), ".csv");
    vv::io::write_text_file(temporary, "step\n1\n");
    EXPECT_EQ(out.commit(), "");
  }
  reader.join();
  EXPECT_EQ(got, "step\n1\n");
  EXPECT_TRUE(fs::is_fifo(pipe));
  EXPECT_FALSE(fs::exists(temporary));
}

// Devices made here (as root): /dev/null takes the bytes, /dev/full says it
// is full, and both stay devices.
TEST(OutputFile, ADeviceIsWrittenThroughAndAFullOneSaysSo) {
  std::string d = fresh_dir("devices");
  if (mknod((d + "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
      mknod((d + "full").c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0)
    GTEST_SKIP() << "cannot make device nodes here (not root, or no CAP_MKNOD)";
  EXPECT_EQ(error_writing(d + "null", "gone"), "");
  EXPECT_EQ(error_writing(d + "full", "too much"), d + "full: cannot write file: No space left on device");
  EXPECT_TRUE(fs::is_character_file(d + "null"));
  EXPECT_TRUE(fs::is_character_file(d + "full"));
  EXPECT_EQ(names_in(d), (std::vector<std::string>{"full", "null"}));
}

TEST(OutputFile, AFolderASocketAndABlockDeviceAreRefused) {
  std::string d = fresh_dir("refused");
  fs::create_directory(d + "folder");
  EXPECT_EQ(error_writing(d + "folder", "x"), d + "folder: cannot write file: it is a folder");
  int s = socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::string socket_path = d + "socket";
  ASSERT_LT(socket_path.size(), sizeof address.sun_path);
  std::copy(socket_path.begin(), socket_path.end(), address.sun_path);
  ASSERT_EQ(bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  EXPECT_EQ(error_writing(socket_path, "x"), socket_path +
                                                 ": cannot write file: it is a socket (only regular files, "
                                                 "character devices and FIFOs are written)");
  close(s);
  EXPECT_TRUE(fs::is_socket(socket_path));
  if (mknod((d + "block").c_str(), S_IFBLK | 0600, makedev(7, 200)) == 0) {
    EXPECT_EQ(error_writing(d + "block", "x"), d + "block: cannot write file: it is a block device (only regular "
                                                   "files, character devices and FIFOs are written)");
    EXPECT_TRUE(fs::is_block_file(d + "block"));
  }
  EXPECT_TRUE(fs::is_directory(d + "folder"));
}

// ---- symbolic links ----

TEST(OutputFile, ALinksTargetIsWrittenAndTheLinkStays) {
  std::string d = fresh_dir("links");
  fs::create_directory(d + "real");
  put(d + "real/mesh.obj", "old");
  fs::create_symlink("real/mesh.obj", d + "mesh.obj");
  fs::create_symlink("mesh.obj", d + "second.obj");  // a chain, relative at each step
  vv::io::write_file_atomically(d + "second.obj", "new");
  EXPECT_EQ(slurp(d + "real/mesh.obj"), "new");
  EXPECT_TRUE(fs::is_symlink(d + "mesh.obj"));
  EXPECT_TRUE(fs::is_symlink(d + "second.obj"));
  EXPECT_EQ(names_in(d), (std::vector<std::string>{"mesh.obj", "real", "second.obj"}));
  EXPECT_EQ(names_in(d + "real"), std::vector<std::string>{"mesh.obj"});
}

// A dangling link creates the file it names; a loop, or more than 40 links
// in a row, is refused with the reason, and the links stay.
TEST(OutputFile, ADanglingLinkCreatesItsTargetAndALoopIsRefused) {
  std::string d = fresh_dir("dangling");
  fs::create_directory(d + "real");
  fs::create_symlink("real/made.obj", d + "dangling.obj");
  vv::io::write_file_atomically(d + "dangling.obj", "made");
  EXPECT_TRUE(fs::is_symlink(d + "dangling.obj"));
  EXPECT_EQ(slurp(d + "real/made.obj"), "made");

  fs::create_symlink("b", d + "a");
  fs::create_symlink("a", d + "b");
  EXPECT_EQ(error_writing(d + "a", "x"), d + "a: cannot write file: the symbolic link is part of a loop of links");
  EXPECT_TRUE(fs::is_symlink(d + "a") && fs::is_symlink(d + "b"));

  for (int i = 0; i < 41; ++i) fs::create_symlink("l" + std::to_string(i + 1), d + "l" + std::to_string(i));
  EXPECT_EQ(error_writing(d + "l0", "x"), d + "l0: cannot write file: more than 40 symbolic links lead on from it");
  EXPECT_FALSE(fs::exists(fs::symlink_status(d + "l41")));
  vv::io::write_file_atomically(d + "l1", "forty links");  // 40 links: as the system allows
  EXPECT_EQ(slurp(d + "l41"), "forty links");
}

// ---- long names ----

// The temporary's id used to be appended to the name: a name that fits
// failed with "File name too long". The stem is shortened instead, never
// inside a UTF-8 character.
TEST(OutputFile, ANameThatFitsIsWrittenWhateverItsLength) {
  std::string d = fresh_dir("long");
  std::string accented;
  for (int i = 0; i < 125; ++i) accented += "\xC3\xA9";  // é, two bytes
  std::vector<std::string> names = {std::string(251, 'n') + ".obj", std::string(255, 'x'), accented + ".obj",
                                    "." + std::string(254, 'e')};
  for (const std::string& name : names) {
    SCOPED_TRACE(name.size());
    EXPECT_EQ(error_writing(d + name, "fits"), "");
    EXPECT_EQ(slurp(d + name), "fits");
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names_in(d), names);
  // The temporaries themselves (made and checked here) fit and cut no character.
  vv::io::unique_file f = vv::io::create_temporary(d.substr(0, d.size() - 1), accented, ".obj");
  ASSERT_GE(f.fd, 0) << f.error;
  close(f.fd);
  std::string name = fs::path(f.path).filename().string();
  EXPECT_LE(name.size(), 255u);
  std::string stem = name.substr(1, name.find(".vvtmp-") - 1);
  EXPECT_EQ(stem.size() % 2, 0u) << "a character was cut";
  EXPECT_EQ(accented.rfind(stem, 0), 0u);
}

// ---- the input ----

// vvc refuses `-o a.vvp` for the program a.vvp however the path is spelt.
TEST(OutputFile, TheInputIsFoundHoweverItsPathIsSpelt) {
  std::string d = fresh_dir("input");
  put(d + "a.vvp", "program");
  fs::create_directory(d + "sub");
  fs::create_symlink("a.vvp", d + "link.vvp");
  fs::create_hard_link(d + "a.vvp", d + "hard.vvp");
  put(d + "b.vvp", "other");
  std::vector<std::string> inputs = {d + "b.vvp", d + "a.vvp"};
  for (const std::string& spelt : {d + "a.vvp", d + "sub/../a.vvp", d + "./a.vvp", d + "link.vvp", d + "hard.vvp"})
    EXPECT_EQ(vv::io::file_among(spelt, inputs), d + "a.vvp") << spelt;
  EXPECT_EQ(vv::io::file_among(d + "new.cpp", inputs), "");
  EXPECT_FALSE(vv::io::same_file(d + "a.vvp", d + "b.vvp"));
}

// ---- a writer that is killed ----

// A writer killed mid-write (here by the file-size limit's SIGXFSZ, which
// nothing catches, as nothing catches SIGKILL) leaves the previous file
// whole and a temporary that names its process; the next write in the
// folder removes it, but not the temporary of a live process or of another
// PID namespace (its process may be alive).
TEST(OutputFile, AKilledWritersTemporaryGoesWithTheNextWrite) {
  std::string d = fresh_dir("killed");
  put(d + "mesh.obj", "previous\n");
  pid_t child = fork();
  if (child == 0) {
    rlimit limit{4096, 4096};
    setrlimit(RLIMIT_FSIZE, &limit);
    vv::io::write_file_atomically(d + "mesh.obj", std::string(100000, 'v'));
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ) << status;
  EXPECT_EQ(slurp(d + "mesh.obj"), "previous\n");
  std::vector<std::string> left = names_in(d);
  ASSERT_EQ(left.size(), 2u);
  std::string dead = left[0];  // ".mesh.vvtmp-…" sorts first
  EXPECT_EQ(dead.rfind(".mesh" + own_id(child), 0), 0u) << dead;
  EXPECT_EQ(fs::file_size(d + dead), 4096u);

  std::string alive = ".mesh" + own_id() + "AbCdEf.obj";
  std::string elsewhere = ".mesh.vvtmp-" + std::to_string(child) + "-1-AbCdEf.obj";
  put(d + alive, "being written");
  put(d + elsewhere, "another namespace's");
  vv::io::write_file_atomically(d + "other.obj", "next\n");
  std::vector<std::string> expected = {alive, elsewhere, "mesh.obj", "other.obj"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names_in(d), expected);
}

// ---- a writer handed a temporary ----

// The interpreter hands a writer the temporary (so that it knows its
// name); the writer writes it in place, with no temporary of its own, and
// a message about it is about the path.
TEST(OutputFile, AWriterHandedATemporaryWritesItInPlace) {
  std::string d = fresh_dir("handed");
  put(d + "shot.png", "previous");
  vv::io::output_file out(d + "shot.png");
  ASSERT_EQ(out.make_temporary(), "");
  vv::io::write_file_atomically(out.temporary(), "picture");
  EXPECT_EQ(names_in(d).size(), 2u) << "the writer made a second temporary";
  EXPECT_EQ(slurp(d + "shot.png"), "previous");
  EXPECT_EQ(out.in_users_terms(out.temporary() + ": cannot write file: x"), d + "shot.png: cannot write file: x");
  EXPECT_EQ(out.commit(), "");
  EXPECT_EQ(slurp(d + "shot.png"), "picture");
  EXPECT_EQ(names_in(d), std::vector<std::string>{"shot.png"});
}

// After a failed run (vvc's translation errors) the previous output goes
// so that it cannot pass for this run's: behind a link too, but never a
// device or a FIFO.
TEST(OutputFile, RemovingThePreviousOutputKeepsLinksAndSpecialFiles) {
  std::string d = fresh_dir("remove_previous");
  put(d + "real.cpp", "stale");
  fs::create_symlink("real.cpp", d + "out.cpp");
  vv::io::output_file(d + "out.cpp").remove_previous();
  EXPECT_TRUE(fs::is_symlink(d + "out.cpp"));
  EXPECT_FALSE(fs::exists(d + "real.cpp"));
  ASSERT_EQ(mkfifo((d + "pipe").c_str(), 0600), 0);
  vv::io::output_file(d + "pipe").remove_previous();
  EXPECT_TRUE(fs::is_fifo(d + "pipe"));
}

}  // namespace
